"""SOURCE strings, serial sources on ptys and URLs, the input layer's unplug/replug handling,
and calibration files."""

from __future__ import annotations

import json
import time

import pytest

from emulator.tablet import EmulatedTablet
from protocols.tablets.calibration import (
    Calibration,
    CalibrationError,
    CalibrationSession,
    load_calibration,
    save_calibration,
)
from protocols.tablets.events import TabletEvent
from protocols.tablets.input_layer import TWELVE_FIELD, InputLayer, MouseSample
from protocols.tablets.serial_source import SerialSource
from protocols.tablets.sources import SourceError, SourceLost, open_source, parse_source
from tests.tablets.helpers import HANG_GUARD

# --- SOURCE strings ---------------------------------------------------------------------------


def test_parse_source_forms() -> None:
    s = parse_source("hid:56A:10")
    assert (s.kind, s.target, s.vid_pid) == ("hid", "056a:0010", (0x56A, 0x10))
    s = parse_source("serial:/dev/ttyUSB0?protocol=wacom4&baud=19200&tilt=1")
    assert (s.kind, s.target, s.protocol, s.baud, s.options) == (
        "serial", "/dev/ttyUSB0", "wacom4", 19200, {"tilt": "1"})
    s = parse_source("socket://127.0.0.1:7000?protocol=summa-mm&logging=debug")
    assert (s.kind, s.target, s.protocol) == ("url", "socket://127.0.0.1:7000?logging=debug",
                                              "summa-mm")
    s = parse_source("emulated:calcomp")
    assert (s.kind, s.protocol) == ("emulated", "calcomp")
    assert parse_source("emulated:").protocol == "summa-mm"


@pytest.mark.parametrize(("text", "match"), [
    ("", "empty"),
    ("hid:xyz", "hid:VID:PID"),
    ("serial:/dev/ttyS0", "protocol="),
    ("serial:/dev/ttyS0?protocol=nope", "unknown tablet protocol"),
    ("serial:/dev/ttyS0?protocol=wacom4&baud=fast", "baud"),
    ("serial:/dev/ttyS0?protocol=wacom4&colour=red", "unknown option"),
    ("tablet", "not a SOURCE"),
])
def test_bad_sources_say_why(text: str, match: str) -> None:
    with pytest.raises(SourceError, match=match):
        parse_source(text)


def test_missing_port_is_source_lost() -> None:
    with pytest.raises(SourceLost, match="cannot open"):
        open_source("serial:/dev/nonexistent-tablet?protocol=calcomp")


def test_loop_url_source() -> None:
    # loop:// echoes what is written: write a real CalComp frame, read it back decoded.
    source = open_source("loop://?protocol=calcomp")
    try:
        source.write(bytes.fromhex("bc 31 2d 00 2e 0f"))
        events = source.read(timeout=0.5)
        assert [(e.x, e.y, e.buttons) for e in events] == [(6317, 5903, 15)]
        assert source.read(timeout=0.01) == []
    finally:
        source.close()


def _collect(source, n: int) -> list[TabletEvent]:
    out: list[TabletEvent] = []
    deadline = time.monotonic() + HANG_GUARD
    while len(out) < n and time.monotonic() < deadline:
        out += source.read(timeout=0.01)
    return out


def test_wacom_source_identifies_the_emulated_tablet() -> None:
    tablet = EmulatedTablet("wacom4")
    tablet.serve_in_background()
    source = SerialSource(parse_source(f"serial:{tablet.slave_path}?protocol=wacom4"),
                          sleep=lambda s: None)
    try:
        texts = [r.text for r in source.replies]
        assert texts[0].startswith("~#UD") and texts[1].startswith("~R")
        assert source.model.max_x == 15240 and source.model.name == "Wacom UD"
        deadline = time.monotonic() + HANG_GUARD
        while b"ST" not in tablet.commands and time.monotonic() < deadline:
            time.sleep(0.01)  # the emulator's thread answers asynchronously
        assert b"~#" in tablet.commands and b"ST" in tablet.commands  # setup string sent
        tablet.send(TabletEvent(100, 200, True, 1, 99))
        assert _collect(source, 1) == [TabletEvent(100, 200, True, 1, 99)]
    finally:
        source.close()
        tablet.close()


def test_wacom_tilt_tablet_switches_the_source_to_9_byte_packets() -> None:
    tablet = EmulatedTablet("wacom4", {"tilt": "1"})
    tablet.serve_in_background()
    source = SerialSource(parse_source(f"serial:{tablet.slave_path}?protocol=wacom4"),
                          sleep=lambda s: None)
    try:
        assert source.parser.tilt  # the ~R settings word has the tilt bit set
        event = TabletEvent(300, 400, True, 1, 10, -12, 34)
        tablet.send(event)
        assert _collect(source, 1) == [event]
    finally:
        source.close()
        tablet.close()


def test_summa_source_reads_the_size_from_the_config_report() -> None:
    tablet = EmulatedTablet("summa-mm")
    tablet.serve_in_background()
    source = SerialSource(parse_source(f"serial:{tablet.slave_path}?protocol=summa-mm"),
                          sleep=lambda s: None)
    try:
        assert (source.model.max_x, source.model.max_y) == (6000, 6000)
        assert tablet.commands[:2] == [b"\x00", b"0"] and b"zb" in tablet.commands
    finally:
        source.close()
        tablet.close()


# --- input layer ------------------------------------------------------------------------------


class Harness:
    """An emulated tablet and the input layer reading it; ``replug`` makes a new one."""

    def __init__(self) -> None:
        self.notices: list[str] = []
        self.tablet = EmulatedTablet("summa-mm")
        self.layer = InputLayer(TWELVE_FIELD, self._open(), reopen=self._reopen, retry_every=3,
                                notify=self.notices.append)
        self.plugged = True

    def _open(self) -> SerialSource:
        url = f"serial:{self.tablet.slave_path}?protocol=summa-mm&init=0"
        return SerialSource(parse_source(url))

    def _reopen(self) -> SerialSource:
        if not self.plugged:
            raise SourceLost("still unplugged")
        return self._open()

    def pen(self, fx: float, fy: float, tip: bool) -> None:
        m = self.tablet.model
        self.tablet.send(TabletEvent(round(fx * m.max_x), round((1 - fy) * m.max_y), True,
                                     1 if tip else 0))

    def poll_until(self, n: int, mouse=()):
        out = []
        deadline = time.monotonic() + HANG_GUARD
        while len(out) < n and time.monotonic() < deadline:
            out += self.layer.poll(mouse, timeout=0.01)
        return out

    def close(self) -> None:
        self.layer.close()
        self.tablet.close()


@pytest.fixture
def harness():
    h = Harness()
    yield h
    h.close()


def test_tablet_strokes_arrive_in_twelve_field_inches(harness) -> None:
    harness.pen(0.0, 0.0, False)
    harness.pen(0.5, 0.5, True)
    harness.pen(1.0, 1.0, True)
    harness.pen(1.0, 1.0, False)
    events = harness.poll_until(4)
    assert [e.kind for e in events] == ["move", "press", "move", "release"]
    assert (events[0].x, events[0].y) == (0.0, 0.0)
    assert (events[1].x, events[1].y) == pytest.approx((6.0, 4.375))
    assert (events[2].x, events[2].y) == pytest.approx((12.0, 8.75))
    assert all(e.source == "tablet" for e in events)


def test_unplug_mid_stroke_falls_back_to_the_mouse_and_replug_resumes(harness) -> None:
    harness.pen(0.25, 0.25, True)
    harness.pen(0.30, 0.25, True)
    drawn = harness.poll_until(2)
    assert [e.kind for e in drawn] == ["press", "move"]
    harness.plugged = False
    harness.tablet.close()  # unplugged mid-stroke
    mouse = [MouseSample(60, 40, 1, (120, 80)), MouseSample(120, 80, 0, (120, 80))]
    out = harness.poll_until(1)
    # the stroke in progress ends cleanly at its last point
    assert out[0].kind == "release" and out[0].source == "tablet"
    assert (out[0].x, out[0].y) == pytest.approx((drawn[-1].x, drawn[-1].y))
    assert len(harness.notices) == 1 and "lost" in harness.notices[0]
    assert harness.layer.active == "mouse"
    fallback = []
    for _ in range(10):  # keeps running on the mouse; says so only once
        fallback += harness.layer.poll(mouse)
    assert len(harness.notices) == 1
    assert fallback[0].kind == "press" and fallback[0].source == "mouse"
    assert (fallback[0].x, fallback[0].y) == pytest.approx((6.0, 4.375))
    # replug: a new tablet on a new port; the layer picks it up on its next retry
    harness.tablet = EmulatedTablet("summa-mm")
    harness.plugged = True
    for _ in range(6):
        harness.layer.poll(())
    assert harness.layer.active == "tablet" and "back" in harness.notices[-1]
    harness.pen(0.5, 0.5, True)
    resumed = harness.poll_until(1)
    assert resumed[-1].source == "tablet" and resumed[-1].kind == "press"


def test_layer_without_a_tablet_uses_the_mouse() -> None:
    layer = InputLayer()
    out = layer.poll([MouseSample(0, 0, 0, (100, 100)), MouseSample(50, 50, 1, (100, 100))])
    assert [e.kind for e in out] == ["move", "press"]
    assert (out[1].x, out[1].y) == (6.0, 4.375)


# --- calibration --------------------------------------------------------------------------


def test_calibration_session_and_file(tmp_path, monkeypatch) -> None:
    monkeypatch.setenv("CAMLAB88_CONFIG_DIR", str(tmp_path))
    session = CalibrationSession("serial:/dev/ttyS0?protocol=summa-mm")
    for e in (TabletEvent(100, 5000), TabletEvent(100, 5000, True, 1),
              TabletEvent(100, 5000, True, 1), TabletEvent(5900, 300),
              TabletEvent(5900, 300, True, 4)):
        session.feed(e)
    cal = session.result()
    assert (cal.top_left, cal.bottom_right) == ((100, 5000), (5900, 300))
    path = save_calibration(cal)
    assert path.parent == tmp_path
    assert load_calibration(cal.device) == cal
    assert cal.to_fraction(3000, 2650) == pytest.approx((0.5, 0.5))
    other = Calibration("hid:056a:0010", (0, 0), (10, 10))
    save_calibration(other)
    assert load_calibration(cal.device) == cal and load_calibration(other.device) == other
    assert sorted(json.loads(path.read_text())) == sorted([cal.device, other.device])
    assert not list(tmp_path.glob(".calibration-*"))  # no temp files left behind


def test_bad_calibration_file_names_the_line(tmp_path) -> None:
    (tmp_path / "calibration.json").write_text('{\n  "x": [1,\n}\n')
    with pytest.raises(CalibrationError, match=r"calibration.json: line \d"):
        load_calibration("x", tmp_path)
    with pytest.raises(CalibrationError, match="share an axis"):
        Calibration("d", (5, 5), (5, 9))
