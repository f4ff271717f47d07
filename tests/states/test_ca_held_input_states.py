"""``ca program`` saved while it holds input read during a long "Go to generation" jump
(state version 5): the held events are kept in their own binary form and put back for the
next frame, so the loaded run handles them first, as the unbroken run does, and shows
exactly its frames. The program's clock is replaced (it decides only when the jump's bar
reads input) so the input arrives inside the jump in every run. A held-events part that
is not events is refused in one line naming the state."""

from __future__ import annotations

import time
from pathlib import Path

import pytest

from camlab88.apps.ca.program.demo import choose, leave_editing
from camlab88.apps.ca.program.state import HELD_BYTES
from camlab88.cli import main
from camlab88.emulator.harness import plugins
from camlab88.emulator.harness.loop import Plugin
from camlab88.emulator.machine.state_file import pack, unpack
from camlab88.protocols.rainbow.events import (
    MIDDLE,
    KeyEvent,
    MouseEvent,
    TabletEvent,
    decode_events,
)
from tests.states.support import assert_continues, frame_logs, saved_place

# typed in the jump's tick: the jump's bar reads input from the clock's second reading on
JUMP = (f"frames 3\n{leave_editing()}{choose('Go to generation')}type 100000\nkey return\n"
        "frames 12\nrelease middle 320 310\nframes 6\n")
# arrives inside the jump: a key and a tablet report the program ignores, the mouse moved,
# then the middle button pressed (the main menu opens where the mouse is, the frame after)
ARRIVING = (KeyEvent(0, "a", "a"), TabletEvent(0, 100, 200, 512, 1),
            MouseEvent(0, 320, 310, 0), MouseEvent(0, 320, 310, MIDDLE, 2, True))


class _Clock:
    """Two seconds on at each reading; at the second, ``ARRIVING`` is posted to the
    Rainbow (the jump's bar then reads it and holds it)."""

    def __init__(self, machine) -> None:
        self.machine, self.t, self.reads = machine, 0.0, 0

    def __call__(self) -> float:
        self.reads += 1
        if self.reads == 2:
            for e in ARRIVING:
                self.machine.post(e)
        self.t += 2.0
        return self.t


class _ClockPlugin(Plugin):
    def start(self, harness) -> None:
        harness.target.program.clock = _Clock(harness.target.machine)


@pytest.fixture
def jump_clock(monkeypatch: pytest.MonkeyPatch) -> None:
    """Every ca program run in the test has the replaced clock."""
    real = plugins.standard_plugins
    monkeypatch.setattr(plugins, "standard_plugins",
                        lambda options: [*real(options), _ClockPlugin()])


def _argv(d: Path) -> list[str]:
    (d / "e.events").write_text(JUMP)
    return ["ca", "program", "--headless", "--pattern", "glider", "--events",
            str(d / "e.events")]


def _program_values(state: Path) -> tuple[dict, dict[str, bytes], dict]:
    head, parts = unpack(state.read_bytes(), "program")
    return head, parts, head["values"]["program"]


def test_a_state_holding_input_read_during_a_jump_continues(monkeypatch, jump_clock,
                                                            tmp_path: Path) -> None:
    """Saved after the jump's tick, the four events held: loaded into a fresh program, the
    next frame handles them (the main menu opens at 320, 310) and every frame after the
    save is the unbroken run's."""
    state = tmp_path / "c.c88state"
    _, rest = assert_continues(monkeypatch, _argv(tmp_path), 0.2, state)
    head, parts, values = _program_values(state)
    assert head["state_version"] == 5 and values["dialogue"] is None
    held = decode_events(parts[values["held_events"]])
    assert [type(e) for e in held] == [type(e) for e in ARRIVING]
    assert held[-1].button == 2 and held[-1].pressed and (held[-1].x, held[-1].y) == (320, 310)
    assert len(set(rest.values())) > 1  # the menu opened and closed after the load


def test_without_the_held_input_the_run_differs(monkeypatch, jump_clock,
                                                tmp_path: Path) -> None:
    """The same state with its held events taken out: the loaded run shows other frames
    (the held input put back is what makes the frames match)."""
    state = tmp_path / "c.c88state"
    argv = _argv(tmp_path)
    assert_continues(monkeypatch, argv, 0.2, state)
    head, parts, values = _program_values(state)
    values["held_events"] = None
    emptied = tmp_path / "e.c88state"
    emptied.write_bytes(pack("program", head, parts))
    with frame_logs(monkeypatch) as runs:
        assert main(argv) == 0
        assert main([*argv, "--load-state", str(emptied)]) == 0
    full, rest = runs
    full.pop("ticks"), rest.pop("ticks")
    k = saved_place(emptied)[1]
    assert sorted(rest) == [n for n in sorted(full) if n > k]
    assert any(rest[n] != full[n] for n in rest)


@pytest.mark.parametrize(("damage", "why"), [
    (lambda b: b[:-3], "truncated or bad event"),       # the last event cut short
    (lambda b: b"\x09" + b, "unknown event kind 9"),    # a kind no event has
    (lambda b: b[:1] + b"\xff" * 8 + b[9:], None),      # a time the program never reads
])
def test_a_damaged_held_events_part_is_refused_in_one_line(jump_clock, tmp_path: Path,
                                                           damage, why) -> None:
    state = tmp_path / "c.c88state"
    argv = _argv(tmp_path)
    assert main([*argv, "--save-state", str(state), "--at", "0.2"]) == 0
    head, parts, values = _program_values(state)
    name = values["held_events"]
    parts[name] = damage(parts[name])
    bad = tmp_path / "bad.c88state"
    bad.write_bytes(pack("program", head, parts))
    if why is None:  # still events: the time stamp chooses nothing, the state loads
        assert main([*argv, "--load-state", str(bad)]) == 0
        return
    with pytest.raises(SystemExit) as stop:
        main([*argv, "--load-state", str(bad)])
    text = str(stop.value)
    assert str(bad) in text and "state.program.held_events: byte" in text and why in text
    assert "\n" not in text


def test_more_held_input_than_a_state_holds_is_refused(tmp_path: Path) -> None:
    """A held-events part past its bound (HELD_BYTES) or of more events than a jump holds."""
    from camlab88.apps.ca.program.jump_bar import HOLD_LIMIT
    from camlab88.apps.ca.program.state import held_from
    from camlab88.protocols.rainbow.events import encode_event

    mouse = encode_event(MouseEvent(0, 1, 2, 0))
    assert len(held_from(mouse * HOLD_LIMIT)) == HOLD_LIMIT
    with pytest.raises(ValueError, match=f"a jump holds at most {HOLD_LIMIT}"):
        held_from(mouse * (HOLD_LIMIT + 1))
    assert HELD_BYTES == 64 * HOLD_LIMIT


def test_a_save_holding_more_bytes_than_the_bound_is_refused_in_one_line() -> None:
    """Key events with names longer than any window's (held from a script's ``key``): the
    save is refused, naming the bound, rather than writing a state no load would take."""
    from camlab88.apps.ca.program.jump_bar import HOLD_LIMIT
    from camlab88.apps.ca.program.program import Options
    from camlab88.apps.ca.program.state import state_values
    from tests.ca_program.driver import Driver

    d = Driver(Options(pattern="glider"))
    d.program.held_events = [KeyEvent(0, "k" * 100, "")] * HOLD_LIMIT
    with pytest.raises(ValueError, match=f"more than a state holds .*{HELD_BYTES} bytes"):
        state_values(d.program)
    d.program.held_events = [KeyEvent(0, "k" * 32, "\N{GRINNING FACE}" * 4)] * HOLD_LIMIT
    assert len(state_values(d.program)["held_events"]) <= HELD_BYTES  # a window's fit


def test_a_jump_holds_at_most_hold_limit_events_the_oldest_dropped() -> None:
    from camlab88.apps.ca.program.jump_bar import HOLD_LIMIT, JumpBar
    from camlab88.apps.ca.program.program import Options
    from tests.ca_program.driver import Driver

    d = Driver(Options(pattern="glider"))
    d.program.held_events = [MouseEvent(i, 1, 1, 0) for i in range(HOLD_LIMIT)]
    d.machine.post(KeyEvent(0, "a", "a"))
    JumpBar(d.program, 0, 10, time.monotonic)._read_input()
    held = d.program.held_events
    assert len(held) == HOLD_LIMIT and held[0].t_ms == 1 and isinstance(held[-1], KeyEvent)


@pytest.mark.parametrize("pointing", ["checkpoint", "huge", "missing"])
def test_a_held_events_field_naming_another_part_is_refused(jump_clock, tmp_path: Path,
                                                            pointing: str) -> None:
    """The field names the automaton's checkpoint part (text, not events), a part past
    HELD_BYTES, or no part: each refused in one line naming the state and the field."""
    state = tmp_path / "c.c88state"
    argv = _argv(tmp_path)
    assert main([*argv, "--save-state", str(state), "--at", "0.2"]) == 0
    head, parts, values = _program_values(state)
    if pointing == "checkpoint":
        values["held_events"] = values["engine"]["checkpoint"]
    elif pointing == "huge":
        parts[values["held_events"]] = b"\x01" * (HELD_BYTES + 20)
    else:
        values["held_events"] = "b999"
    bad = tmp_path / "bad.c88state"
    bad.write_bytes(pack("program", head, parts))
    with pytest.raises(SystemExit) as stop:
        main([*argv, "--load-state", str(bad)])
    text = str(stop.value)
    assert str(bad) in text and "state.program.held_events" in text and "\n" not in text


def test_a_recording_begun_from_such_a_state_replays_with_check(jump_clock, tmp_path: Path,
                                                                monkeypatch) -> None:
    """Loaded with --record: the recording carries the state (its held input with it) and
    ``replay --check`` agrees with every screen hash, the held input handled first."""
    from camlab88.protocols.session.format import read
    from fuzz.states import run_cli

    monkeypatch.chdir(tmp_path)
    argv = _argv(tmp_path)
    code, err = run_cli([*argv, "--save-state", "s.c88state", "--at", "0.2"], 60.0)
    assert code == 0, err
    code, err = run_cli([*argv, "--load-state", "s.c88state", "--record", "r.session"], 60.0)
    assert code == 0, err
    code, err = run_cli(["replay", "r.session", "--check"], 60.0)
    assert code == 0, err
    assert read(tmp_path / "r.session").hashes[0].frame == 6  # the state's frame
