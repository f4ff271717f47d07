"""Esc (with no command to cancel) and the window's close button quit the KAS editor and
path tool, asking first over unsaved work: y saves and quits, n quits without saving, Esc
stays. Ctrl-C keeps unsaved edits in a recovery file it names."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

from camlab88.apps.kas.editor import Editor
from camlab88.apps.kas.events import Key, Pointer
from camlab88.apps.kas.files import load_keyframe
from camlab88.apps.kas.model import Drawing
from camlab88.apps.kas.path_editor import PathEditor
from camlab88.apps.kas.program import EditorFront, PathFront
from camlab88.apps.kas.program.base import QUIT_QUESTION

ROOT = Path(__file__).resolve().parents[2]
ESC = b"\x1b"


def _dirty_editor(saved: list) -> EditorFront:
    front = EditorFront(Editor(), on_save=lambda d: saved.append(d.copy()))
    for down in (True, False):
        front.editor.feed(Pointer(0.5, 0.5, down))
    assert front.editor.dirty
    return front


def test_esc_quits_at_once_when_nothing_is_unsaved() -> None:
    front = EditorFront(Editor())
    front.keys(ESC)
    assert front.quitting and not front.discarded


def test_esc_over_unsaved_edits_asks_and_esc_stays() -> None:
    front = _dirty_editor([])
    front.keys(ESC)
    assert not front.quitting and front.editor.message == QUIT_QUESTION
    front.keys(b"q")  # not an answer: the question stays
    assert not front.quitting and front.editor.message == QUIT_QUESTION
    front.keys(ESC)
    assert not front.quitting and not front.asking and front.editor.message == ""
    front.keys(b"u")  # the editor works as before: undo point
    assert not front.quitting


def test_y_saves_and_quits_n_quits_without_saving() -> None:
    saved: list = []
    front = _dirty_editor(saved)
    front.keys(ESC + b"y")
    assert front.quitting and len(saved) == 1 and not front.editor.dirty
    saved.clear()
    front = _dirty_editor(saved)
    front.keys(ESC + b"n")
    assert front.quitting and front.discarded and saved == []


def test_a_failed_save_at_the_question_does_not_quit() -> None:
    def full(_drawing: Drawing) -> None:
        raise OSError(28, "No space left on device")

    front = _dirty_editor([])
    front.editor.on_save = full
    front.keys(ESC + b"y")
    assert not front.quitting and "NOT saved" in front.editor.message


def test_esc_cancels_a_command_before_it_quits() -> None:
    front = EditorFront(Editor())
    front.editor.feed(Key("e"))   # edit mode
    front.editor.feed(Key("t"))   # rotate: asks for a number
    assert front.editor.pending is not None
    front.keys(ESC)
    assert front.editor.pending is None and not front.quitting
    front.keys(ESC)
    assert front.quitting


def test_close_asks_once_and_closing_again_discards() -> None:
    front = _dirty_editor([])
    assert not front.may_close() and front.editor.message == QUIT_QUESTION
    assert front.may_close() and front.discarded


def test_the_path_tool_asks_over_an_unsaved_path() -> None:
    model = PathEditor(Drawing(), Drawing())
    saved: list = []
    front = PathFront(model, on_save=lambda p, t: saved.append(p))
    front.keys(ESC)
    assert front.quitting  # nothing drawn: quits at once
    front = PathFront(PathEditor(Drawing(), Drawing()), on_save=lambda p, t: saved.append(p))
    for x, down in ((0.0, True), (1.0, True), (1.0, False)):
        front.model.feed(Pointer(x, 0.0, down))
    front.keys(ESC)
    assert not front.quitting and front.model.message == QUIT_QUESTION
    front.keys(b"y")
    assert front.quitting and len(saved) == 1
    front = PathFront(front.model, on_save=lambda p, t: saved.append(p))
    front.keys(b"\x1b")
    assert not front.quitting  # a new front has saved nothing yet: asks
    front.keys(b"n")
    assert front.quitting and front.discarded


def test_a_scripted_esc_y_ends_the_editor_and_saves(tmp_path: Path) -> None:
    """Through the whole program: the script's Esc then y, on the line, end the run (the
    script's later events never play) and save FILE."""
    script = tmp_path / "quit.script"
    script.write_text("down 0 0\nup 0 0\ndown 1 1\nup 1 1\nkey escape\nkey y\n"
                      "down -1 -1\nup -1 -1\n")
    target = tmp_path / "k.kas"
    done = subprocess.run([sys.executable, "-m", "camlab88", "kas", "edit", str(target),
                           "--headless", "--script", str(script)], cwd=tmp_path,
                          capture_output=True, text=True, timeout=300,
                          env=dict(os.environ, PYTHONPATH=str(ROOT)))
    assert done.returncode == 0, done.stderr
    kept = load_keyframe(target)
    assert kept.n_points == 2  # the point after the quit was never drawn
    assert "saved" in done.stdout


def test_ctrl_c_keeps_unsaved_edits_in_a_recovery_file(tmp_path: Path, capsys) -> None:
    from camlab88.commands.kas.edit import _interrupted, recovery_file

    front = _dirty_editor([])
    target = tmp_path / "k.kas"
    assert _interrupted(front, target, preview=False) == 130
    rescue = recovery_file(target)
    assert load_keyframe(rescue).n_points == 1 and not target.exists()
    assert str(rescue) in capsys.readouterr().err


def _window_keys(monkeypatch, keys: list[tuple[str, str]]) -> list[int]:
    """The window's poll: nothing for 20 polls (the script's drawing arrives), then one key
    each poll from ``keys``; returns the list of polls made."""
    from camlab88.emulator.host_input import KeyDown
    from camlab88.emulator.window import Window

    polls: list[int] = []

    def poll(self) -> list:
        polls.append(1)
        n = len(polls) - 20
        return [KeyDown(*keys[n])] if 0 <= n < len(keys) else []

    monkeypatch.setattr(Window, "poll", poll)
    return polls


def test_the_window_esc_then_n_quits_without_saving(tmp_path: Path, monkeypatch,
                                                     capsys) -> None:
    from camlab88.cli import main

    polls = _window_keys(monkeypatch, [("escape", ""), ("n", "n")])
    script = tmp_path / "s.txt"
    script.write_text("down 0 0\nup 0 0\ndown 1 1\nup 1 1\n")
    target = tmp_path / "k.kas"
    assert main(["kas", "edit", str(target), "--script", str(script)]) == 0
    assert len(polls) < 200  # it ended on the answer, not by some limit
    assert "NOT saved: quit without saving" in capsys.readouterr().out
    assert load_keyframe(target).chains == []


def test_the_path_tools_window_esc_quits(tmp_path: Path, monkeypatch) -> None:
    from camlab88.cli import main

    polls = _window_keys(monkeypatch, [("escape", "")])
    out = tmp_path / "p.kas"
    assert main(["kas", "path", "sun_a", "sun_b", "--out", str(out), "--no-library",
                 "--previous", "walk_path"]) == 0
    assert 20 < len(polls) < 200 and not out.exists()
