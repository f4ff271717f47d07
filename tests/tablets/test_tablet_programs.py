"""The tablet tools are programs on the harness: the command modules only parse and wire (an
AST scan), monitor's ``--count``/``--seconds`` and its reopening of a lost tablet, calibrate's
give-up, and the window's mouse and keys driving the emulated tablet through its protocol."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

from camlab88.emulator.harness import Plugin, RunOptions, run
from camlab88.emulator.host_input import KeyDown, PointerButton, PointerMove
from camlab88.protocols.tablets.events import TabletEvent, TabletModel
from camlab88.protocols.tablets.sources import SourceLost

COMMANDS = Path(__file__).resolve().parents[2] / "camlab88" / "commands" / "tablet"
CLOCKS = {"monotonic", "sleep", "time", "perf_counter", "wait_frame"}
READS = {"read", "poll", "step", "show"}


def loops(source: str, name: str = "<src>") -> list[str]:
    """What in ``source`` runs a loop over time or events: a ``while``, a clock read or a
    sleep, a ``for`` over something read or polled, a ``time`` import."""
    found = []
    for node in ast.walk(ast.parse(source, name)):
        if isinstance(node, ast.While):
            found.append(f"{name}:{node.lineno}: a while loop")
        elif isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) \
                and node.func.attr in CLOCKS:
            found.append(f"{name}:{node.lineno}: reads or waits on a clock ({node.func.attr})")
        elif isinstance(node, ast.For):
            names = {n.id for n in ast.walk(node.iter) if isinstance(n, ast.Name)}
            calls = {n.func.attr for n in ast.walk(node.iter)
                     if isinstance(n, ast.Call) and isinstance(n.func, ast.Attribute)}
            if "events" in names or calls & READS:
                found.append(f"{name}:{node.lineno}: a for loop over events")
        elif isinstance(node, ast.Import | ast.ImportFrom) and any(
                a.name == "time" for a in node.names) or (
                isinstance(node, ast.ImportFrom) and node.module == "time"):
            found.append(f"{name}:{node.lineno}: imports time")
    return found


def test_the_tablet_commands_run_no_loop_of_their_own() -> None:
    found = [f for path in sorted(COMMANDS.glob("*.py"))
             for f in loops(path.read_text(encoding="utf-8"), path.name)]
    assert not found, "a tablet command runs its own loop (give the harness a program in " \
        "emulator/tablet_input):\n" + "\n".join(found)


def test_the_scan_sees_the_loops_the_commands_once_ran() -> None:
    old = ("import time\nstart = time.monotonic()\nwhile not session.done:\n"
           "    events = source.read(timeout=0.02)\n    for e in events:\n        pass\n"
           "for e in held.read(0.02):\n    pass\nemu.window.wait_frame(60)\n"
           "for d in devices:\n    print(d)\n")
    kinds = [f.split(": ", 1)[1] for f in loops(old)]
    assert sorted(kinds) == sorted([
        "imports time", "reads or waits on a clock (monotonic)", "a while loop",
        "a for loop over events", "a for loop over events",
        "reads or waits on a clock (wait_frame)"])


class Clock:
    """A wall clock a test moves: each reading is ``step`` s after the last."""

    def __init__(self, step: float) -> None:
        self.now, self.step = 0.0, step

    def __call__(self) -> float:
        self.now += self.step
        return self.now


class FakeSource:
    """``read`` hands out the queued batches, then raises ``lose`` (or returns nothing)."""

    name = "fake"
    model = TabletModel("Fake", 100, 100, 100.0, None, None)

    def __init__(self, batches: list[list[TabletEvent]], lose: bool = False) -> None:
        self.batches, self.lose, self.closed, self.heard = list(batches), lose, False, 0

    def read(self, timeout: float = 0.0) -> list[TabletEvent]:
        if self.batches:
            return self.batches.pop(0)
        if self.lose:
            raise SourceLost("fake: unplugged")
        return []

    def close(self) -> None:
        self.closed = True


def _events(n: int) -> list[TabletEvent]:
    return [TabletEvent(k, k) for k in range(n)]


def _held(source: FakeSource, clock: Clock):
    from camlab88.emulator.tablet_input.monitor import Held
    from camlab88.protocols.tablets.sources import parse_source

    return Held(source, parse_source("loop://?protocol=bitpad1"), None, clock=clock)


def test_monitor_stops_at_exactly_count_reports(capsys) -> None:
    from camlab88.emulator.tablet_input.monitor import MonitorProgram

    clock = Clock(0.001)
    program = MonitorProgram(_held(FakeSource([_events(3), _events(4)]), clock), None, 5,
                             None, clock=clock)
    harness = run(program, RunOptions(headless=True))
    lines = capsys.readouterr().out.splitlines()
    assert len(lines) == 5 and harness.ticks == 2 and program.exit_status == 0


def test_monitor_stops_after_seconds_on_the_wall_clock(capsys) -> None:
    from camlab88.emulator.tablet_input.monitor import MonitorProgram

    clock = Clock(0.25)  # the program reads it once at the start and once a tick
    program = MonitorProgram(_held(FakeSource([]), Clock(0.0)), None, None, 1.0, clock=clock)
    harness = run(program, RunOptions(headless=True))
    assert harness.ticks == 4  # ticks at 0.25, 0.5, 0.75 s read; the one at 1.0 s stops
    assert capsys.readouterr().out == ""


def test_monitor_reopens_a_lost_tablet_and_goes_on(monkeypatch, capsys) -> None:
    from camlab88.emulator.tablet_input.monitor import MonitorProgram
    from camlab88.protocols.tablets import sources

    first = FakeSource([_events(1)], lose=True)
    again = FakeSource([_events(2)])
    opened = []
    monkeypatch.setattr(sources, "open_source",
                        lambda spec, on_raw=None: opened.append(spec) or again)
    clock = Clock(0.3)  # past Held.RETRY after two readings
    program = MonitorProgram(_held(first, clock), None, 3, None, clock=clock)
    run(program, RunOptions(headless=True))
    out, err = capsys.readouterr()
    assert len(out.splitlines()) == 3 and first.closed and len(opened) == 1
    assert "lost fake: unplugged; waiting for it to come back" in err and ": back" in err


def test_calibrate_gives_up_after_its_seconds_with_a_hint(capsys) -> None:
    from camlab88.emulator.tablet_input.calibrate import CalibrateProgram
    from camlab88.protocols.tablets.calibration import CalibrationSession

    clock = Clock(1.0)
    program = CalibrateProgram(CalibrationSession("fake"), FakeSource([]), None, 2.5,
                               clock=clock)
    harness = run(program, RunOptions(headless=True))
    assert program.exit_status == 1 and harness.ticks == 3
    assert "calibration gave up after 2.5 s: nothing came from the tablet" in \
        capsys.readouterr().err


class Hand(Plugin):
    """Stands in for the window: host events at chosen ticks."""

    def __init__(self, script: dict[int, list[object]]) -> None:
        self.script = script

    def handle_events(self, harness, events):
        return events + self.script.get(harness.ticks, [])


def test_the_window_mouse_and_keys_drive_the_tablet_through_its_protocol() -> None:
    from camlab88.emulator.tablet_input.emulate import EmulateProgram
    from camlab88.emulator.tablet_input.emulated_source import EmulatedSource
    from camlab88.protocols.tablets.sources import parse_source

    emu = EmulatedSource(parse_source("emulated:wacom4"), reader=False)
    try:
        emu.with_view()  # the window's part, headless
        w, h = emu.view.size
        program = EmulateProgram(emu, demo=False, seconds=None)
        seen: list[TabletEvent] = []
        show = emu.show
        emu.show = lambda events: (seen.extend(events), show(events))
        hand = Hand({1: [PointerMove(w // 2, h // 2)],
                     2: [PointerButton(w // 2, h // 2, 1, True)],
                     3: [PointerMove(w - 1, h // 2, frozenset({1}))],
                     4: [KeyDown("e")], 5: [KeyDown("o")]})
        run(program, RunOptions(headless=True, stop_after=7), [hand])
        frame = program.frame()
    finally:
        emu.close()
    m = emu.tablet.model
    assert [(e.tip, e.tool, e.proximity) for e in seen] == [
        (False, "pen", True), (True, "pen", True), (True, "pen", True),
        (True, "eraser", True), (False, "eraser", False)]
    assert (seen[1].x, seen[2].x) == (pytest.approx(m.max_x / 2, abs=m.max_x / w), m.max_x)
    assert frame.shape == (h, w, 3) and emu.view.ink.any()  # the stroke drawn, from the bytes


def test_the_headless_tools_never_import_pygame(tmp_path) -> None:
    import os
    import subprocess
    import sys

    script = ("import sys\nfrom camlab88.cli import main\n"
              "main(['tablet', 'monitor', 'emulated:summa-mm?drive=demo', '--count', '3'])\n"
              "main(['tablet', 'calibrate', 'emulated:bitpad2?drive=demo'])\n"
              "main(['tablet', 'monitor', 'loop://?protocol=calcomp', '--seconds', '0.1'])\n"
              "print('pygame' in sys.modules)\n")
    env = {k: v for k, v in os.environ.items()
           if k not in ("DISPLAY", "WAYLAND_DISPLAY", "SDL_VIDEODRIVER")}
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True,
                          timeout=120, env={**env, "CAMLAB88_CONFIG_DIR": str(tmp_path)})
    assert done.returncode == 0, done.stderr
    assert done.stdout.splitlines()[-1] == "False"
