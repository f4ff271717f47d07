"""A damaged state is refused before it changes anything: loaded in this process (no fork)
into a program that has been running - as the window's F3 loads into a running program -
or into a fresh build by ``--load-state``, a refused state leaves the program (its declared
state) and the objects camlab88's modules share (menus' item lists, tables) exactly as they
were; a state that is loaded changes the program only, never those shared objects. Every
program checks everything a state says before it changes anything (check, then put)."""

from __future__ import annotations

import json
import sys
import types
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from camlab88 import __version__
from camlab88.base.objstate import OURS, StateError, capture
from camlab88.base.plainstate import encode
from camlab88.emulator.harness import plugins
from camlab88.emulator.harness.loop import Plugin
from camlab88.emulator.harness.program_state import identity, load_program, save_program
from camlab88.emulator.machine.state_file import MachineStateError
from fuzz.mutate import mutate
from fuzz.states import ODD_VALUES, PROGRAMS, close_state, edit_tree, open_state, run_cli

AT = ["--at", "0.1"]  # s of virtual time: inside each run below
LONGER = {"ca-program": ["--stop-after", "12"], "snooker-play": ["--stop-after", "12"],
          "sigma-run": [], "rainbow-run": ["--stop-after", "12"]}  # (frames: 0.24 s)
# (their caches fill as states load)
LOADER = ("camlab88.base.objstate", "camlab88.base.shared_objects")
# a value in each program's state that passes the schema and the program refuses: checked
# after the machines' states and the other values (a late refusal)
LATE = {"ca-program": (b'"edit_mode": "step_up"', b'"edit_mode": "/x"'),
        "snooker-play": (b'"mode": "idle"', b'"mode": "/x"'),
        "rainbow-run": (b'"highlighted": null', b'"highlighted": 99'),
        "sigma-run": None}  # (its machine's part, damaged)


class _Keep(Plugin):
    """Keeps the harness; ``at_start`` is the program's declared state when the run began
    (before a --load-state: this plugin starts before the state plugin)."""

    def __init__(self) -> None:
        self.harness: Any = None
        self.at_start: Any = None

    def start(self, harness) -> None:
        self.harness = harness
        self.at_start = snapshot(harness)


def snapshot(harness) -> Any:
    """The program's declared state now (JSON and parts) and the harness's place."""
    parts: dict[str, bytes] = {}
    target = harness.target
    values = encode(target.STATE_SCHEMA, target.state_values(), parts)
    return json.dumps(values, sort_keys=True), parts, (harness.ticks, harness.frames_shown,
                                                       harness._next_show, harness._shown_at)


def module_objects() -> dict[str, Any]:
    """Every list, dict, set, array, function and instance of ours that one of our modules
    holds at module level (or a class of it), captured: what a state must never change."""
    out: dict[str, Any] = {}
    for name, mod in list(sys.modules.items()):
        if not name.startswith(OURS) or not isinstance(mod, types.ModuleType) or \
                name in LOADER:
            continue
        places = [(f"{name}.{k}", v) for k, v in vars(mod).items()]
        places += [(f"{name}.{k}.{a}", w) for k, v in vars(mod).items()
                   if isinstance(v, type) and v.__module__ == name for a, w in vars(v).items()]
        for where, value in places:
            if isinstance(value, list | dict | set | np.ndarray | types.FunctionType) or (
                    type(value).__module__.startswith(OURS) and hasattr(value, "__dict__")
                    and not isinstance(value, type | types.ModuleType)):
                try:
                    tree, blobs = capture(value)
                except StateError:
                    continue
                out[where] = (json.dumps(tree, sort_keys=True, default=repr), blobs)
    return out


def _changed(before: dict[str, Any], after: dict[str, Any]) -> list[str]:
    return [k for k in before if after.get(k) != before[k]]


class Program:
    """A program that ran on past the state it saved (at AT), in its harness."""

    def __init__(self, name: str, harness: Any, data: bytes, scratch: Path) -> None:
        self.name, self.harness, self.data, self.scratch = name, harness, data, scratch
        self.end = save_program(harness, identity(harness, __version__))  # where it ended

    def move_on(self) -> None:
        """Back to where the run ended: never exactly the state it saved at AT."""
        load_program(self.end, self.harness, identity(self.harness, __version__))


@pytest.fixture(scope="module", params=sorted(LONGER))  # (the editors: test_editor_states)
def program(request, tmp_path_factory) -> Program:
    name = request.param
    folder = tmp_path_factory.mktemp(name)
    state = folder / "at.c88state"
    keep = _Keep()
    real = plugins.standard_plugins
    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(plugins, "standard_plugins", lambda o: [keep, *real(o)])
        code, err = run_cli([*PROGRAMS[name], *LONGER[name], "--save-state", str(state), *AT],
                            300.0)
    assert code == 0, err
    return Program(name, keep.harness, state.read_bytes(), folder / "input.c88state")


def _damaged_late(name: str, data: bytes) -> bytes:
    """The state with a value the program refuses after everything else has been checked
    (sigma run: its machine's part cut short)."""
    opened = open_state(data)
    if LATE[name] is None:
        return close_state(opened[:-100])
    old, new = LATE[name]
    assert old in opened, f"{name}: the state no longer holds {old!r}"
    return close_state(opened.replace(old, new, 1))


def _load_into_running(harness, data: bytes) -> str | None:
    """Load ``data`` as ``--load-state`` does (its identity checked) into the running
    program; None if it loaded, else the refusal."""
    try:
        load_program(data, harness, identity(harness, __version__))
    except MachineStateError as exc:
        return str(exc)
    return None


def test_the_undamaged_state_differs_from_the_running_program_and_loads(program) -> None:
    """(So a half-applied load below would show.)"""
    name, harness, data = program.name, program.harness, program.data
    program.move_on()
    running = snapshot(harness)
    assert _load_into_running(harness, data) is None
    assert snapshot(harness)[:2] != running[:2], f"{name}: the state is the running program's"
    assert _load_into_running(harness, data) is None  # the same again: all of it loaded


def test_a_state_refused_late_changes_neither_the_running_program_nor_shared_objects(
        program) -> None:
    name, harness, data = program.name, program.harness, program.data
    program.move_on()
    running, shared = snapshot(harness), module_objects()
    refusal = _load_into_running(harness, _damaged_late(name, data))
    assert refusal is not None, name
    assert snapshot(harness) == running, f"{name}: a refused state changed the program"
    assert not _changed(shared, module_objects())


def test_load_state_refuses_naming_the_file_and_where_and_the_fresh_program_is_unchanged(
        program) -> None:
    name, data, scratch = program.name, program.data, program.scratch
    scratch.write_bytes(_damaged_late(name, data))
    shared = module_objects()
    keep = _Keep()
    real = plugins.standard_plugins
    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(plugins, "standard_plugins", lambda o: [keep, *real(o)])
        code, err = run_cli([*PROGRAMS[name], "--load-state", str(scratch)], 60.0)
    assert code == 2 and err.count("\n") == 1, err
    assert f"{scratch}: not loaded: " in err
    assert snapshot(keep.harness) == keep.at_start, f"{name}: the refused state changed it"
    assert not _changed(shared, module_objects())


def test_a_loaded_state_changes_its_program_not_the_objects_programs_share(program) -> None:
    harness, data = program.harness, program.data
    shared = module_objects()
    program.move_on()
    assert _load_into_running(harness, data) is None
    assert not _changed(shared, module_objects())


# ------------------------------------------------------------------ any damage
json_values = st.sampled_from(ODD_VALUES) | st.integers() | st.text(max_size=4)
damage = st.one_of(
    st.tuples(st.just("values"), st.lists(st.tuples(st.integers(0, 1 << 30), json_values),
                                          min_size=1, max_size=3)),
    st.tuples(st.just("bytes"), st.integers(0, 1 << 32)),
    st.tuples(st.just("file"), st.integers(0, 1 << 32)))


def _damage(data: bytes, kind: str, how: Any) -> bytes:
    import random

    if kind == "values":  # the header's declared values (past zlib's checksums)
        return edit_tree(data, how)
    if kind == "bytes":  # bytes of the opened state: the values' text and the parts
        return close_state(mutate(open_state(data), random.Random(how)))
    return mutate(data, random.Random(how))  # the file's own bytes


@settings(max_examples=30, deadline=None,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])
@given(damaged=damage)
def test_any_damaged_state_is_refused_unchanged_or_loaded_never_half(program,
                                                                     damaged) -> None:
    name, harness, data = program.name, program.harness, program.data
    assert _load_into_running(harness, data) is None
    program.move_on()
    running, shared = snapshot(harness), module_objects()
    if _load_into_running(harness, _damage(data, *damaged)) is not None:
        assert snapshot(harness) == running, f"{name}: a refused state changed the program"
    assert not _changed(shared, module_objects()), f"{name}: a state changed shared objects"


# ------------------------------------------------------------------ kas view's line test
def _period_state(data: bytes, k: Any = None, machine: bytes | None = None) -> bytes:
    """``kas view``'s state with its period and/or its machine's state replaced."""
    from camlab88.emulator.machine.state_file import pack, unpack

    head, blobs = unpack(data, "program")
    bare = {n: v for n, v in head.items() if n not in ("blobs", "format_version", "device")}
    values = dict(bare["values"])
    if k is not None:
        values["period"] = k
    if machine is not None:
        blobs[values["machine"]] = machine
    return pack("program", dict(bare, values=values), blobs)


def test_kas_view_refuses_a_damaged_state_and_runs_on_unchanged(tmp_path) -> None:
    """The line test is the target that loads itself (a generator run again to the saved
    period): a period past its end, or a damaged machine, is refused before the running
    line test changes (it was run again on its own build and left there)."""
    assert run_cli(["kas", "demo", "--out", str(tmp_path / "seq.kas")], 300.0)[0] == 0
    state, keep = tmp_path / "v.c88state", _Keep()
    real = plugins.standard_plugins
    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(plugins, "standard_plugins", lambda o: [keep, *real(o)])
        code, err = run_cli(["kas", "view", str(tmp_path / "seq.kas"), "--headless",
                             "--every", "--save-state", str(state), "--at", "0.5"], 300.0)
    assert code == 0, err
    harness, data = keep.harness, state.read_bytes()
    target = harness.target
    assert _load_into_running(harness, data) is None
    for _ in range(5):
        assert target.tick()  # on past the state
    before = (target.k, target.machine, target.machine.save_state(), target.result)
    for damaged, why in ((_period_state(data, k=10**6), "ends before period 1000000"),
                         (_period_state(data, machine=b"damaged"), "machine state")):
        refusal = _load_into_running(harness, damaged)
        assert refusal is not None and why in refusal, refusal
        now = (target.k, target.machine, target.machine.save_state(), target.result)
        assert now[0] == before[0] and now[1] is before[1] and now[2:] == before[2:]
    assert target.tick()  # and it runs on
