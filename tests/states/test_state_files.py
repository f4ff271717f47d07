"""State files: a state of another program, version or input is refused with one line naming
the file and the difference; damaged files too; the F2/F3/F4 keys through scripted events;
whole runs through a fresh process for each device."""

from __future__ import annotations

import hashlib
import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from camlab88.cli import main
from camlab88.emulator.harness.loop import Harness, RunOptions
from camlab88.emulator.harness.program_state import StateOptions
from camlab88.emulator.harness.rainbow import RainbowTarget
from camlab88.emulator.harness.state_plugin import StatePlugin
from camlab88.emulator.host_input import KeyDown
from camlab88.emulator.machine.state_file import MAGIC, pack, unpack
from tests.states.support import ROOT, inputs_of

RAINBOW = ["rainbow", "run", "--headless", "--stop-after", "12"]


def _refused(argv: list[str]) -> str:
    """The one-line refusal a command exits with (SystemExit's message, printed by the CLI)."""
    with pytest.raises(SystemExit) as exc:
        main(argv)
    text = str(exc.value.code)
    assert "\n" not in text and "not loaded" in text
    return text


@pytest.fixture
def rainbow_state(tmp_path: Path, capsys) -> Path:
    state = tmp_path / "r.c88state"
    assert main([*RAINBOW, "--save-state", str(state)]) == 0
    capsys.readouterr()
    return state


def _rewrite(state: Path, **changes) -> None:
    head, blobs = unpack(state.read_bytes(), "program")
    head.update(changes)
    for key in ("format_version", "device", "blobs"):
        head.pop(key)
    state.write_bytes(pack("program", head, blobs))


def test_a_state_of_another_program_is_refused(rainbow_state: Path, tmp_path: Path,
                                                capsys) -> None:
    line = _refused(["snooker", "play", "--headless", "--stop-after", "3", "--load-state",
                     str(rainbow_state)])
    assert str(rainbow_state) in line and "a state of 'camlab88 rainbow run'" in line


def test_a_state_of_another_version_is_refused(rainbow_state: Path, capsys) -> None:
    _rewrite(rainbow_state, state_version=2)
    line = _refused([*RAINBOW, "--load-state", str(rainbow_state)])
    assert "a state of version 2; this camlab88 rainbow run reads version 1" in line
    assert str(rainbow_state) in line


def test_the_camlab88_version_that_saved_a_state_is_only_noted(rainbow_state: Path) -> None:
    """(The program's state version is what must agree.)"""
    _rewrite(rainbow_state, camlab88="0.0.1")
    assert main([*RAINBOW, "--load-state", str(rainbow_state)]) == 0


def test_a_state_with_other_arguments_is_refused(rainbow_state: Path, capsys) -> None:
    assert "other arguments or input files" in _refused(
        ["rainbow", "run", "--headless", "--stop-after", "12", "--demo", "shelf",
         "--load-state", str(rainbow_state)])


def test_a_state_with_other_input_files_is_refused(tmp_path: Path, capsys) -> None:
    d = inputs_of("tests/data/sessions/sigma_run.session", tmp_path)
    argv = ["sigma", "run", "--headless", "--in", str(d / "picture.sigma"), "--seconds", "1"]
    assert main([*argv, "--save-state", str(d / "s.c88state")]) == 0
    (d / "picture.sigma").write_bytes(b"changed")
    capsys.readouterr()
    line = _refused([*argv, "--load-state", str(d / "s.c88state")])
    assert "other arguments or input files" in line and "sha256" in line


@pytest.mark.parametrize("damage", ["magic", "version", "truncated", "tree"])
def test_a_damaged_state_file_is_one_line_naming_it(rainbow_state: Path, capsys,
                                                    damage: str) -> None:
    data = rainbow_state.read_bytes()
    if damage == "magic":
        data = b"X" + data[1:]
    elif damage == "version":
        n = int.from_bytes(data[len(MAGIC):len(MAGIC) + 4], "big")
        head = json.loads(data[len(MAGIC) + 4:len(MAGIC) + 4 + n])
        head["format_version"] = 99
        text = json.dumps(head, sort_keys=True).encode()
        data = MAGIC + len(text).to_bytes(4, "big") + text + data[len(MAGIC) + 4 + n:]
    elif damage == "truncated":
        data = data[:len(data) // 2]
    rainbow_state.write_bytes(data)
    if damage == "tree":  # the object tree the old format held: a class to build
        _rewrite(rainbow_state, values={"O": "os:_wrap_close", "id": 0, "a": []})
    line = _refused([*RAINBOW, "--load-state", str(rainbow_state)])
    assert str(rainbow_state) in line


def test_a_missing_state_file_is_named(tmp_path: Path, capsys) -> None:
    with pytest.raises(SystemExit) as exc:
        main([*RAINBOW, "--load-state", str(tmp_path / "none.c88state")])
    assert str(tmp_path / "none.c88state") in str(exc.value)


# --------------------------------------------------------------------------- the keys
def _demo_harness(tmp_path: Path) -> Harness:
    from camlab88.emulator.machine import RainbowMachine
    from camlab88.protocols.rainbow.demo import Demo

    session = RainbowMachine()
    demo = Demo(session.client)

    def step() -> bool:
        demo.step()
        return True

    opts = RunOptions(headless=True, command="camlab88 rainbow run", argv=["rainbow", "run"],
                      state=StateOptions(version="test", key_dir=tmp_path, snapshots=[],
                                         snapshot_every=__import__("fractions").Fraction(1, 10)))
    h = Harness(RainbowTarget(session, step, "demo", "", program=demo), opts)
    for p in h.plugins:
        p.start(h)
    return h


def _frame_hash(h: Harness) -> str:
    return hashlib.sha256(h.target.frame().tobytes()).hexdigest()


def test_f2_saves_f3_loads_and_f4_steps_back(tmp_path: Path, capsys) -> None:
    h = _demo_harness(tmp_path)
    plugin = next(p for p in h.plugins if isinstance(p, StatePlugin))
    for _ in range(5):
        h._tick_once()
    assert plugin.handle_events(h, [KeyDown("f2")]) == []  # the key is the plugin's
    written = sorted(tmp_path.glob("*.c88state"))
    assert [p.name for p in written] == ["rainbow-run-001.c88state"]
    assert str(written[0]) in capsys.readouterr().err  # the file is named
    at_save, picture = h.ticks, _frame_hash(h)
    for _ in range(12):
        h._tick_once()
    assert _frame_hash(h) != picture
    plugin.handle_events(h, [KeyDown("f3")])
    assert (h.ticks, _frame_hash(h)) == (at_save, picture)
    for _ in range(12):
        h._tick_once()
    now = h.target.time()
    plugin.handle_events(h, [KeyDown("f4")])
    assert h.target.time() < now and h.ticks < at_save + 12
    assert "F4: back to" in capsys.readouterr().err


def test_a_program_that_uses_f2_keeps_it_and_shift_f2_saves(tmp_path: Path) -> None:
    h = _demo_harness(tmp_path)
    h.target.key_names = frozenset({"f2"})  # as the KAS editor's target says
    h._tick_once()
    plugin = next(p for p in h.plugins if isinstance(p, StatePlugin))
    assert plugin.handle_events(h, [KeyDown("f2")]) == [KeyDown("f2")]
    assert not list(tmp_path.glob("*.c88state"))
    assert plugin.handle_events(h, [KeyDown("f2", mods=frozenset({"shift"}))]) == []
    assert len(list(tmp_path.glob("*.c88state"))) == 1


# --------------------------------------------------------------------------- fresh processes
def _cli(args: list[str], cwd: Path) -> subprocess.CompletedProcess[str]:
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    return subprocess.run([sys.executable, "-m", "camlab88", *args], cwd=cwd, env=env,
                          capture_output=True, text=True, timeout=600, check=False)


def _pngs(d: Path) -> list[bytes]:
    return [p.read_bytes() for p in sorted(d.glob("frame_*.png"))]


@pytest.mark.parametrize("argv, at", [
    (["snooker", "play", "--headless", "--events", "scenario.events"], "4"),
], ids=["rainbow-snooker-play"])
def test_a_state_continues_in_a_fresh_process(tmp_path: Path, argv: list[str], at: str) -> None:
    rec = {"kas": "kas_edit", "snooker": "snooker_play"}[argv[0]]
    d = inputs_of(f"tests/data/sessions/{rec}.session", tmp_path)
    inputs = {p: p.read_bytes() for p in d.iterdir()}
    first = _cli([*argv, "--frames", "all", "--save-state", "s.c88state", "--at", at], d)
    assert first.returncode == 0, first.stderr
    for path, data in inputs.items():  # kas edit's F2 (after the save) rewrote key.kas
        path.write_bytes(data)
    second = _cli([*argv, "--frames", "rest", "--load-state", "s.c88state"], d)
    assert second.returncode == 0, second.stderr
    everything, rest = _pngs(d / "all"), _pngs(d / "rest")
    assert 0 < len(rest) < len(everything)
    assert rest == everything[len(everything) - len(rest):]


def test_a_save_at_a_time_before_the_loaded_state_saves_at_once(rainbow_state: Path,
                                                                tmp_path: Path) -> None:
    again = tmp_path / "again.c88state"
    assert main(["rainbow", "run", "--headless", "--stop-after", "14", "--load-state",
                 str(rainbow_state), "--save-state", str(again), "--at", "0"]) == 0
    head, _ = unpack(again.read_bytes(), "program")
    loaded, _ = unpack(rainbow_state.read_bytes(), "program")
    assert head["harness"][0] == loaded["harness"][0] + 1  # the first tick after loading


def test_at_without_save_state_is_refused() -> None:
    with pytest.raises(SystemExit, match="--at needs --save-state"):
        main([*RAINBOW, "--at", "1"])


@pytest.mark.parametrize("flag", ["save", "load"])
def test_a_target_that_declares_no_state_refuses_state_files_at_its_start(
        tmp_path: Path, flag: str) -> None:
    """(Every command's program declares one now: a harness target that does not.)"""
    from tests.support.targets import Counter

    state = tmp_path / "s.c88state"
    state.write_bytes(b"x")
    opts = RunOptions(headless=True, command="camlab88 counter", argv=["counter"],
                      state=StateOptions(version="test", **{flag: state}))
    h = Harness(Counter(10), opts)
    plugin = next(p for p in h.plugins if isinstance(p, StatePlugin))
    with pytest.raises(SystemExit) as stop:
        plugin.start(h)
    assert f"--{flag}-state: this program does not declare its state" in str(stop.value)
    assert "\n" not in str(stop.value)


def test_the_identity_holds_the_inputs_as_the_run_began(tmp_path: Path,
                                                        monkeypatch) -> None:
    """Input files are hashed once, when a run with --save-state begins (as the program read
    them), not when the state is saved: an input changed on disk during the run does not
    make the state refuse the inputs it was made from."""
    from camlab88.emulator.harness import plugins
    from camlab88.emulator.harness.loop import Plugin

    events = tmp_path / "e.events"
    events.write_text("frames 3\nclick middle 400 300\nframes 6\n")
    argv = ["ca", "program", "--headless", "--pattern", "glider", "--events", str(events)]
    first = events.read_text()

    class Edit(Plugin):  # someone edits the events file once the program has read it
        def post_tick(self, harness) -> None:
            if harness.ticks == 2:
                events.write_text(first + "frames 1\n")

    real = plugins.standard_plugins
    monkeypatch.setattr(plugins, "standard_plugins", lambda o: [*real(o), Edit()])
    state = tmp_path / "s.c88state"
    assert main([*argv, "--save-state", str(state), "--at", "0.1"]) == 0
    monkeypatch.setattr(plugins, "standard_plugins", real)
    events.write_text(first)
    assert main([*argv, "--load-state", str(state)]) == 0
    events.write_text(first + "frames 1\n")
    with pytest.raises(SystemExit, match="saved with other arguments or input files"):
        main([*argv, "--load-state", str(state)])
