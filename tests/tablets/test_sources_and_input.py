"""SOURCE strings, serial sources on ptys and URLs, the input layer's unplug/replug handling,
and calibration files."""

from __future__ import annotations

import json
import time
from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any

import pytest

from camlab88.emulator.tablet import EmulatedTablet
from camlab88.protocols.tablets import summa
from camlab88.protocols.tablets.calibration import (
    Calibration,
    CalibrationError,
    CalibrationSession,
    load_calibration,
    save_calibration,
)
from camlab88.protocols.tablets.events import TabletEvent
from camlab88.protocols.tablets.input_layer import TWELVE_FIELD, InputLayer, MouseSample
from camlab88.protocols.tablets.serial_source import SerialSource
from camlab88.protocols.tablets.sources import (
    SourceError,
    SourceLost,
    TabletSource,
    open_source,
    parse_source,
)
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


def _handled(tablet: EmulatedTablet, command: bytes) -> bool:
    """Wait (guarded) until the tablet's background thread has handled ``command``."""
    deadline = time.monotonic() + HANG_GUARD
    while command not in tablet.commands and time.monotonic() < deadline:
        time.sleep(0.005)
    return command in tablet.commands


def _collect(source, n: int) -> list[TabletEvent]:
    out: list[TabletEvent] = []
    deadline = time.monotonic() + HANG_GUARD
    while len(out) < n and time.monotonic() < deadline:
        out += source.read(timeout=0.01)
    return out


@contextmanager
def _hosted(protocol: str, options: dict[str, str] | None = None, encoder: Any = None,
            early: TabletEvent | None = None) -> Iterator[tuple[EmulatedTablet, SerialSource]]:
    """An emulated tablet (its encoder replaced by ``encoder``; ``early`` sent before the host
    starts) answering from its thread, and our serial source opened on its pty."""
    tablet = EmulatedTablet(protocol, options)
    if encoder is not None:
        tablet.encoder = encoder
    if early is not None:
        tablet.send(early)  # streaming before the host starts
    tablet.serve_in_background()
    try:
        source = SerialSource(parse_source(f"serial:{tablet.slave_path}?protocol={protocol}"),
                              sleep=lambda s: None)
        try:
            yield tablet, source
        finally:
            source.close()
    finally:
        tablet.close()


def test_wacom_source_identifies_the_emulated_tablet() -> None:
    with _hosted("wacom4") as (tablet, source):
        texts = [r.text for r in source.replies]
        assert texts[0].startswith("~#UD") and texts[1].startswith("~R")
        assert source.model.max_x == 15240 and source.model.name == "Wacom UD"
        deadline = time.monotonic() + HANG_GUARD
        while b"ST" not in tablet.commands and time.monotonic() < deadline:
            time.sleep(0.01)  # the emulator's thread answers asynchronously
        assert b"~#" in tablet.commands and b"ST" in tablet.commands  # setup string sent
        tablet.send(TabletEvent(100, 200, True, 1, 99))
        assert _collect(source, 1) == [TabletEvent(100, 200, True, 1, 99)]


def test_wacom_tilt_tablet_switches_the_source_to_9_byte_packets() -> None:
    with _hosted("wacom4", {"tilt": "1"}) as (tablet, source):
        assert source.parser.tilt  # the ~R settings word has the tilt bit set
        event = TabletEvent(300, 400, True, 1, 10, -12, 34)
        tablet.send(event)
        assert _collect(source, 1) == [event]


def test_summa_source_reads_the_size_from_the_config_report() -> None:
    with _hosted("summa-mm") as (tablet, source):
        assert (source.model.max_x, source.model.max_y) == (6000, 6000)
        assert _handled(tablet, b"F")
        assert tablet.commands[:3] == [b"\x00", b"B", b"0"] and b"zb" in tablet.commands
        assert tablet.commands.index(b"a") < tablet.commands.index(b"@")


class _Streaming(summa.SummaEncoder):
    """After the reset the tablet streams (reports in flight when the host starts asking)."""

    def answer(self, command: bytes) -> bytes:
        reply = super().answer(command)
        if command == b"\x00":
            return self.encode(TabletEvent(1000, 2000, True, 0)) * 3
        return reply


def test_summa_size_is_not_taken_from_reports_already_streaming() -> None:
    with _hosted("summa-mm", encoder=_Streaming()) as (tablet, source):
        assert (source.model.max_x, source.model.max_y) == (6000, 6000)
        assert not source.size_notes
        assert _handled(tablet, b"F") and tablet.streaming  # "@" after the size query


class _StreamsRegardless(summa.SummaEncoder):
    """A tablet that ignores prompt mode and answers "a" with two ordinary reports."""

    def answer(self, command: bytes) -> bytes:
        if command == b"a":
            return self.encode(TabletEvent(1000, 2000)) + self.encode(TabletEvent(1001, 2000))
        return b"" if command == b"B" else super().answer(command)


def test_implausible_size_reply_keeps_the_default_and_says_why() -> None:
    with _hosted("summa-mm", encoder=_StreamsRegardless()) as (tablet, source):
        assert (source.model.max_x, source.model.max_y) == (6000, 6000)
        assert "2 reports" in source.size_notes[0] and "keeping 0..6000" in source.size_notes[0]


def test_calcomp_start_up_sets_resolution_and_reads_the_size() -> None:
    from camlab88.protocols.tablets.calcomp import CalcompEncoder
    from camlab88.protocols.tablets.events import TabletModel

    encoder = CalcompEncoder(TabletModel("DrawingBoard II 12x18", 18000, 12000, 1000.0))
    with _hosted("calcomp", encoder=encoder, early=TabletEvent(50, 60, True, 1)) as (
            tablet, source):
        assert _handled(tablet, b"IR")
        assert b"JR1000,0" in tablet.commands and b"VS" in tablet.commands
        assert (source.model.max_x, source.model.max_y) == (18000, 12000)
        assert tablet.streaming  # ESC%IR after the query


# --- input layer ------------------------------------------------------------------------------


class Harness:
    """An emulated tablet and the input layer reading it; ``replug`` makes a new one."""

    def __init__(self) -> None:
        self.notices: list[str] = []
        self.now = 0.0  # the sources' clock: silences are judged on it, so tests set it
        self.tablet = EmulatedTablet("summa-mm")
        self.tablet.assume_initialised()  # read with init=0: set up as our start-up would
        self.layer = InputLayer(TWELVE_FIELD, self._open(), reopen=self._reopen, retry_every=3,
                                notify=self.notices.append, spawn=lambda job: job())
        self.plugged = True

    def _open(self) -> SerialSource:
        url = f"serial:{self.tablet.slave_path}?protocol=summa-mm&init=0"
        return SerialSource(parse_source(url), clock=lambda: self.now)

    def _reopen(self) -> SerialSource:
        if not self.plugged:
            raise SourceLost("still unplugged")
        return self._open()

    def pen(self, fx: float, fy: float, tip: bool) -> None:
        m = self.tablet.model
        assert m.origin == "upper-left"
        self.tablet.send(TabletEvent(round(fx * m.max_x), round(fy * m.max_y), True,
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
    harness.tablet.assume_initialised()
    harness.plugged = True
    for _ in range(6):
        harness.layer.poll(())
    assert harness.layer.active == "tablet" and "back" in harness.notices[-1]
    harness.pen(0.5, 0.5, True)
    resumed = harness.poll_until(1)
    assert resumed[-1].source == "tablet" and resumed[-1].kind == "press"


def test_stream_silent_mid_stroke_ends_the_stroke_then_falls_back_then_resumes(harness):
    harness.pen(0.25, 0.25, True)
    drawn = harness.poll_until(1)
    assert [e.kind for e in drawn] == ["press"]
    mouse = [MouseSample(60, 40, 1, (120, 80))]
    harness.now = 0.3  # a short gap is normal
    assert harness.layer.poll(mouse) == [] and not harness.notices
    harness.now = 0.6  # cable pulled: no bytes, no OS error
    out = harness.layer.poll(mouse)
    assert [(e.kind, e.source) for e in out] == [("release", "tablet")]
    assert (out[0].x, out[0].y) == pytest.approx((drawn[0].x, drawn[0].y))
    assert len(harness.notices) == 1 and "no data" in harness.notices[0]
    harness.now = 1.0
    assert harness.layer.poll(mouse) == [] and len(harness.notices) == 1  # said once
    harness.now = 2.7  # a longer gap: the mouse takes over
    out = harness.layer.poll(mouse)
    assert [(e.kind, e.source) for e in out] == [("press", "mouse")]
    assert len(harness.notices) == 2 and "mouse" in harness.notices[1]
    harness.now = 5.0
    assert harness.layer.poll(mouse)[0].source == "mouse" and len(harness.notices) == 2
    harness.pen(0.5, 0.5, True)  # bytes again: the tablet takes over
    back = harness.poll_until(2)
    assert [(e.kind, e.source) for e in back] == [("release", "mouse"), ("press", "tablet")]
    assert len(harness.notices) == 3 and "again" in harness.notices[2]


def test_silence_with_the_pen_up_is_not_a_fault(harness) -> None:
    harness.pen(0.25, 0.25, False)
    assert [e.kind for e in harness.poll_until(1)] == ["move"]
    harness.now = 30.0  # out of proximity a tablet may say nothing at all
    assert harness.layer.poll([MouseSample(1, 1, 1, (120, 80))]) == []
    assert not harness.notices and harness.layer.active == "tablet"


class _Gone(TabletSource):
    name = "gone"

    def read(self, timeout: float = 0.0) -> list[TabletEvent]:
        raise SourceLost("unplugged")


def test_replug_opens_on_a_worker_and_never_blocks_poll() -> None:
    import threading

    started, go, finished = threading.Event(), threading.Event(), threading.Event()
    tablet = EmulatedTablet("summa-mm")

    def slow_reopen() -> SerialSource:  # a tablet's start-up: seconds of waits
        started.set()
        go.wait(HANG_GUARD)
        url = f"serial:{tablet.slave_path}?protocol=summa-mm&init=0"
        source = SerialSource(parse_source(url))
        finished.set()
        return source

    notes: list[str] = []
    layer = InputLayer(TWELVE_FIELD, _Gone(), reopen=slow_reopen, retry_every=1,
                       notify=notes.append)
    try:
        mouse = [MouseSample(60, 40, 0, (120, 80))]
        layer.poll(mouse)  # lost
        out = layer.poll(mouse)  # starts reopening ...
        assert started.wait(HANG_GUARD)
        assert not finished.is_set()  # ... and came back while the reopen is still running
        assert out and out[0].source == "mouse"
        assert layer.poll(mouse)[0].source == "mouse"  # more frames on the mouse meanwhile
        go.set()
        deadline = time.monotonic() + HANG_GUARD
        while layer.active != "tablet" and time.monotonic() < deadline:
            layer.poll(mouse)
        assert layer.active == "tablet" and "back" in notes[-1]
    finally:
        go.set()
        layer.close()
        tablet.close()


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
