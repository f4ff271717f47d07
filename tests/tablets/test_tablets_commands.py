"""`camlab88 tablet ...` end to end (headless: the emulated tablet draws a scripted stroke)."""

from __future__ import annotations

import json
import re
import sys

import pytest

from camlab88.cli import main

LINE = re.compile(r"^\s*[\d.]+ x=(\d+) y=(\d+) pressure=(\S+) buttons=0b([01]{4}) prox=(in|out)")


def test_monitor_emulated_summa(capsys) -> None:
    assert main(["tablet", "monitor", "emulated:summa-mm?drive=demo", "--count", "12"]) == 0
    out = capsys.readouterr().out.splitlines()
    assert out[0].startswith("# emulated:summa-mm?drive=demo: Summagraphics MM")
    events = [LINE.match(line) for line in out[1:]]
    assert len(events) == 12 and all(events)
    xs = [int(m.group(1)) for m in events]
    assert xs == sorted(xs) and xs[0] < xs[-1]  # the demo stroke hovers in from the left


def test_monitor_raw_and_other_protocols(capsys) -> None:
    assert main(["tablet", "monitor", "emulated:calcomp?drive=demo", "--count", "3",
                 "--raw"]) == 0
    out = capsys.readouterr().out.splitlines()
    raw = [line for line in out if line.startswith("raw ")]
    assert raw and all(re.fullmatch(r"raw( [0-9a-f]{2})+", line) for line in raw)
    assert sum(bool(LINE.match(line)) for line in out) == 3


def test_monitor_wacom_emulated_with_pressure(capsys) -> None:
    assert main(["tablet", "monitor", "emulated:wacom4?drive=demo", "--count", "40"]) == 0
    out = capsys.readouterr().out.splitlines()
    pressures = {m.group(3) for m in map(LINE.match, out) if m}
    assert "153" in pressures  # the mouse "presses" at 60 % of 255 once the loop starts


def test_monitor_url_source_stops_after_seconds(capsys) -> None:
    assert main(["tablet", "monitor", "loop://?protocol=bitpad1", "--seconds", "0.1"]) == 0
    assert "Bit Pad One" in capsys.readouterr().out


def test_monitor_bad_source_is_a_clear_error() -> None:
    with pytest.raises(SystemExit, match="unknown tablet protocol"):
        main(["tablet", "monitor", "serial:/dev/ttyS0?protocol=mouse"])


def test_calibrate_emulated_saves_per_device(tmp_path, monkeypatch, capsys) -> None:
    monkeypatch.setenv("CAMLAB88_CONFIG_DIR", str(tmp_path))
    assert main(["tablet", "calibrate", "emulated:bitpad2?drive=demo", "--seconds", "20"]) == 0
    out = capsys.readouterr().out
    assert "TOP-LEFT" in out and "BOTTOM-RIGHT" in out and "saved" in out
    data = json.loads((tmp_path / "calibration.json").read_text())
    (entry,) = data.values()
    (ax, ay), (bx, by) = entry["top_left"], entry["bottom_right"]
    assert ax < bx and ay > by  # Bit Pad origin is lower-left: top of the area has larger Y


def test_list_runs_without_devices(capsys) -> None:
    assert main(["tablet", "list"]) == 0
    out = capsys.readouterr().out
    assert "HID digitizers (backend: " in out and "Serial ports:" in out
    assert "backend: hidraw" in out or sys.platform != "linux"  # hidraw first on Linux


def test_tablet_input_emulated_goes_through_the_protocol(tmp_path, monkeypatch) -> None:
    import time

    monkeypatch.setenv("CAMLAB88_CONFIG_DIR", str(tmp_path))  # no stray user calibration
    from camlab88.emulator.tablet_input.pointer import TabletInput
    from camlab88.protocols.tablets.input_layer import MouseSample

    notes: list[str] = []
    tin = TabletInput("emulated:summa-mm", notify=notes.append)
    try:
        samples = [MouseSample(0, 0, 0, (1201, 876)), MouseSample(600, 437.5, 1, (1201, 876))]
        out = tin.poll(samples)
        deadline = time.monotonic() + 5
        while len(out) < 2 and time.monotonic() < deadline:
            out += tin.poll(())
        # the tablet streams: a still pen repeats its last report, so more may follow
        assert {e.source for e in out} == {"tablet"}
        assert [e.kind for e in out[:2]] == ["move", "press"]
        assert (out[0].x, out[0].y) == pytest.approx((0.0, 0.0), abs=0.01)  # top-left
        assert (out[1].x, out[1].y) == pytest.approx((6.0, 4.375), abs=0.01)
        assert all(e.kind == "move" and e.down for e in out[2:])  # held: no phantom release
    finally:
        tin.close()
    assert not notes


def test_tablet_input_without_device_uses_mouse(tmp_path, monkeypatch) -> None:
    monkeypatch.setenv("CAMLAB88_CONFIG_DIR", str(tmp_path))
    from camlab88.emulator.tablet_input.pointer import TabletInput
    from camlab88.protocols.tablets.input_layer import MouseSample

    notes: list[str] = []
    tin = TabletInput("serial:/dev/nonexistent?protocol=wacom4", notify=notes.append)
    out = tin.poll([MouseSample(10, 10, 1, (120, 87.5))])
    assert out[0].source == "mouse" and out[0].kind == "press" and len(notes) == 1
    tin.close()


@pytest.mark.parametrize("source", ["emulated:wacom4?tilt=1", "emulated:summa-mm?flair=1"])
def test_tablet_input_passes_protocol_options_through(source, tmp_path, monkeypatch) -> None:
    import time

    monkeypatch.setenv("CAMLAB88_CONFIG_DIR", str(tmp_path))
    from camlab88.emulator.tablet_input.pointer import TabletInput
    from camlab88.protocols.tablets.input_layer import MouseSample

    tin = TabletInput(source)
    try:
        out = tin.poll([MouseSample(600, 437.5, 1, (1201, 876))])
        deadline = time.monotonic() + 5
        while not out and time.monotonic() < deadline:
            out += tin.poll(())
        assert out and out[0].kind == "press" and out[0].source == "tablet"
        assert (out[0].x, out[0].y) == pytest.approx((6.0, 4.375), abs=0.01)
        if "tilt" in source:
            # (a live tablet is read on its tape: the serial source inside reads the
            # 9-byte packets it is sent)
            assert tin.layer.source.inner.parser.tilt
        else:
            assert out[0].pressure == pytest.approx(0.6, abs=0.01)  # the Flair's Z axis
    finally:
        tin.close()


def test_monitor_count_must_be_positive(capsys) -> None:
    with pytest.raises(SystemExit) as exc:
        main(["tablet", "monitor", "loop://?protocol=calcomp", "--count", "0"])
    assert exc.value.code == 2
    assert "--count" in capsys.readouterr().err


def test_the_source_help_lists_every_protocol_a_tablet_can_speak() -> None:
    """`tablet emulate` accepts summa-flair (an alias): `tablet monitor --help` says so."""
    from camlab88.commands.tablet import SOURCE_HELP
    from camlab88.protocols.tablets.registry import ALIASES, PROTOCOL_NAMES

    listed = SOURCE_HELP.split("P = ")[1].split(", ")
    assert sorted(listed) == sorted([*PROTOCOL_NAMES, *ALIASES])
