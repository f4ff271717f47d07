"""``ca program`` saved while a dialogue waits on its pop-up choice menu (state version 4):
the dialogue is made again from its name and answers through the program's own code, and
its menu is re-attached to the pads the loaded Rainbow already holds, with the menu's plain
state (the lit item, its place, its scroll). The run goes on choosing from the menu with
exactly the frames of the run that never saved, in this process and in a fresh one, and a
recording begun from such a state replays with ``--check``. A dialogue already given its
file name stays refused, open menu or not (a state never names a file)."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

from camlab88.apps.ca.program.demo import choose, edit_choice, leave_editing
from camlab88.apps.ca.program.menus import main_item_point
from camlab88.cli import main
from camlab88.emulator.machine.state_file import pack, unpack
from camlab88.protocols.session.format import read
from fuzz.states import run_cli
from tests.states.support import ROOT, assert_continues, assert_file_dialogue_refused

RECT = ("frames 2\nmove 350 300\nclick right 350 300\nframes 2\nmove 450 380\n"
        "click right 450 380\n")
# dialogue -> (the input opening its menu, where the menu opens, the item picked, its row
# above 'Do nothing' (the item the menu opens with under the cursor), what the run does next)
DIALOGUES = {
    "Alter display": (leave_editing() + choose("Alter display"),
                      main_item_point("Alter display", 300, 300, jumps=True),
                      "Monochrome", 4, ""),
    "Clear area": (leave_editing() + choose("Clear area"),
                   main_item_point("Clear area", 300, 300, jumps=True),
                   "Clear a rectangle", 1, RECT),
    "Set to value": (edit_choice("left"), (300 - 24, 300), "Life-form 1", 1,
                     "frames 2\nclick right 400 300\nframes 2\nclick right 420 300\n"),
}


def _events(name: str) -> str:
    """Open the dialogue's menu (frame 5), move to the item (frames 9 and 12: lit from
    frame 9), wait, pick it with the right button (frame 22), answer what follows."""
    opening, (x, y), _, rows, after = DIALOGUES[name]
    y -= rows * 18
    return (f"frames 3\n{opening}frames 3\nmove {x} {y - 2}\nframes 3\nmove {x} {y}\n"
            f"frames 10\nclick right {x} {y}\n{after}frames 6\n")


def _argv(d: Path, name: str) -> list[str]:
    (d / "e.events").write_text(_events(name))
    return ["ca", "program", "--headless", "--pattern", "glider", "--events",
            str(d / "e.events")]


def _values(state: Path) -> dict:
    head, _ = unpack(state.read_bytes(), "program")
    return head["values"]["program"]


@pytest.mark.parametrize("name", sorted(DIALOGUES))
@pytest.mark.parametrize(("at", "lit"), [(0.1, "Do nothing"), (0.3, "picked")])
def test_a_ca_state_saved_with_a_choice_menu_open_continues(monkeypatch, tmp_path: Path,
                                                            name: str, at: float,
                                                            lit: str) -> None:
    """Saved as the menu opens ('Do nothing' lit) and with the cursor on the item to pick:
    loaded, the script picks it from the re-attached menu and answers what follows."""
    state = tmp_path / "c.c88state"
    assert_continues(monkeypatch, _argv(tmp_path, name), at, state)
    dialogue = _values(state)["dialogue"]
    assert dialogue["name"] == name and dialogue["answers"] == []
    menu = dialogue["menu"]
    assert menu is not None and menu["open"] and menu["scroll"] == 0
    items = {"Alter display": 6, "Clear area": 3, "Set to value": 2}[name]
    picked = items - 1 - DIALOGUES[name][3]
    assert menu["highlighted"] == (items - 1 if lit == "Do nothing" else picked)


def _cli(args: list[str], cwd: Path) -> subprocess.CompletedProcess[str]:
    env = dict(os.environ, PYTHONPATH=str(ROOT), SDL_VIDEODRIVER="dummy")
    return subprocess.run([sys.executable, "-m", "camlab88", *args], cwd=cwd, env=env,
                          capture_output=True, text=True, timeout=600, check=False)


def test_a_state_saved_with_a_choice_menu_open_continues_in_a_fresh_process(
        tmp_path: Path) -> None:
    """``--frames all`` of a run saving with Clear area's menu open (the item lit) against
    ``--frames rest`` of a new process loading it: the same PNG bytes, the rectangle
    cleared after the load."""
    argv = _argv(tmp_path, "Clear area")
    first = _cli([*argv, "--frames", "all", "--save-state", "s.c88state", "--at", "0.3"],
                 tmp_path)
    assert first.returncode == 0, first.stderr
    assert _values(tmp_path / "s.c88state")["dialogue"]["menu"]["highlighted"] == 1
    second = _cli([*argv, "--frames", "rest", "--load-state", "s.c88state"], tmp_path)
    assert second.returncode == 0, second.stderr
    everything = [p.read_bytes() for p in sorted((tmp_path / "all").glob("frame_*.png"))]
    rest = [p.read_bytes() for p in sorted((tmp_path / "rest").glob("frame_*.png"))]
    assert 0 < len(rest) < len(everything)
    assert rest == everything[len(everything) - len(rest):]
    assert len(set(rest)) > 2  # the menu, the rectangle's corners, the cleared grid


def test_a_recording_begun_from_such_a_state_replays_with_check(tmp_path: Path) -> None:
    """Saved with Alter display's menu open (frame 15), loaded with --record: the recording
    carries the state and its first screen hash is the state's frame; --check agrees."""
    old = Path.cwd()
    os.chdir(tmp_path)
    try:
        argv = _argv(tmp_path, "Alter display")
        code, err = run_cli([*argv, "--save-state", "s.c88state", "--at", "0.3"], 60.0)
        assert code == 0, err
        code, err = run_cli([*argv, "--load-state", "s.c88state", "--record", "r.session"],
                            60.0)
        assert code == 0, err
        code, err = run_cli(["replay", "r.session", "--check"], 60.0)
        assert code == 0, err
        assert read(tmp_path / "r.session").hashes[0].frame == 15  # the state's frame
    finally:
        os.chdir(old)


def _changed(tmp_path: Path, change) -> tuple[list[str], Path]:
    argv = _argv(tmp_path, "Clear area")
    state = tmp_path / "c.c88state"
    assert main([*argv, "--save-state", str(state), "--at", "0.3"]) == 0
    head, parts = unpack(state.read_bytes(), "program")
    change(head["values"]["program"]["dialogue"])
    state.write_bytes(pack("program", head, parts))
    return argv, state


def _answer(dialogue: dict) -> None:
    dialogue["answers"].append({"kind": "text", "text": "Clear a rectangle", "ints": []})


@pytest.mark.parametrize(("change", "refusal"), [
    (lambda d: d["menu"].update(highlighted=3), "menu item 3 of 3"),
    (lambda d: d["menu"].update(x=10**6), "menu x 1000000 is outside 0.."),
    (lambda d: d["menu"].update(y=-1), "menu y -1 is outside 0.."),
    (lambda d: d["menu"].update(scroll=-18), "menu scroll -18 is outside 0..0"),
    (lambda d: d["menu"].update(open=False), "the dialogue 'Clear area''s choice menu is not "
                                             "open"),
    (lambda d: d.update(menu=None),
     "the dialogue 'Clear area' would wait on a menu choice the state does not hold"),
    (_answer, "the dialogue 'Clear area' asks for no menu choice here"),
])
def test_a_menu_the_dialogue_and_the_rainbow_do_not_hold_is_refused(tmp_path: Path,
                                                                   change, refusal: str
                                                                   ) -> None:
    argv, state = _changed(tmp_path, change)
    with pytest.raises(SystemExit) as stop:
        main([*argv, "--load-state", str(state)])
    assert refusal in str(stop.value) and str(state) in str(stop.value)
    assert "\n" not in str(stop.value)


def test_a_file_dialogue_s_menu_after_its_file_name_is_not_saved(tmp_path: Path,
                                                                  capsys) -> None:
    """Load pattern asks for the orientation in a menu once it has its file: a state would
    name the file, so --save-state fails the run in one line naming it (status 1)."""
    (tmp_path / "e.events").write_text(
        "frames 3\n" + leave_editing() + choose("Load pattern") +
        "frames 2\ntype glider\nkey return\nframes 2\nclick right 420 320\nframes 30\n")
    assert_file_dialogue_refused(tmp_path / "e.events", "Load pattern", capsys)
