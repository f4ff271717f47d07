"""``camlab88 kas edit FILE``: the keyframe editor on the emulated Sigma T5684."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from camlab88.base.plainstate import Opt, Str
from camlab88.commands.kas import add_front_options
from camlab88.replay_policy import KEEP
from camlab88.runopts import fail

COMMAND = "camlab88 kas edit"
KEYS = "F2 saves; Esc/close quits (asks if unsaved: y saves, n discards, Esc stays)"

DESCRIPTION = """\
Edit keyframe FILE (created, empty, if missing) on an emulated Sigma T5684 over a 9600-baud \
line: the stylus is the tablet (--tablet SOURCE) or the mouse, keys are typed on the \
terminal. F2 saves. --script runs an event script (docs/kas.md); --headless needs one. A \
--screenshot run saves nothing but the PNG."""


HELP = "the keyframe editor on the emulated Sigma T5684"


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("file")
    add_front_options(p)
    p.add_argument("--over", help="previous keyframe to draw over (§2.3 guide)").replay = KEEP
    p.add_argument("--seed", default=0, type=int, help="de-regularise random seed").replay = KEEP


def run(args: argparse.Namespace) -> int:
    from camlab88.apps.kas import files, library
    from camlab88.apps.kas.editor import Editor
    from camlab88.apps.kas.program import EditorFront
    from camlab88.commands.kas import prepare_front

    target = Path(args.file)
    preview = args.screenshot is not None  # a screenshot run never touches the user's files
    saved: list[int] = []
    failed: list[OSError] = []
    try:
        prepared = prepare_front(args, COMMAND)  # a refused run creates no FILE
        if not target.exists() and not preview:
            _create(target, Editor(None, None, args.seed).drawing)
        start = files.load_keyframe(target) if target.exists() else None
        over = files.load_drawing_or_frame(library.resolve(args.over)) if args.over else None

        def save(drawing) -> None:
            # (a --load-state runs the session again: its F2s write nothing then)
            if not preview and not getattr(front, "rebuilding", False):
                try:
                    files.save_keyframe(target, drawing)
                except OSError as exc:  # the editor shows it; the exit status says it too
                    failed.append(exc)
                    raise
                saved.append(len(drawing.chains))
            front.editor.message = f"saved {target.name}" if not preview else "(preview)"

        front = EditorFront(Editor(start, over, args.seed), args.background, save)
        ran = _run(front, args, prepared, _start_state(front, start, over, args, save))
    except KeyboardInterrupt:
        return _interrupted(locals().get("front"), target, preview)
    except (OSError, ValueError) as exc:
        return fail(COMMAND, exc)
    _report(front.editor, ran.machine, target, saved, preview, front.discarded)
    if failed and front.editor.dirty:  # the last edits are lost: say why, exit non-zero
        return fail(COMMAND, f"{target}: NOT saved: {failed[-1].strerror or failed[-1]}", 1)
    return 0


def recovery_file(target: Path) -> Path:
    """Where Ctrl-C keeps unsaved edits: beside FILE, never over it."""
    return target.with_name(f"{target.stem}.recovered{target.suffix or '.kas'}")


def _interrupted(front, target: Path, preview: bool) -> int:
    """Ctrl-C: unsaved edits go to a recovery file, named; FILE keeps its last save."""
    from camlab88.apps.kas import files

    if front is None or preview or not front.editor.dirty:
        print(f"{COMMAND}: interrupted; nothing unsaved was lost", file=sys.stderr)
        return 130
    rescue = recovery_file(target)
    try:
        files.save_keyframe(rescue, front.editor.drawing)
    except OSError as exc:
        print(f"{COMMAND}: interrupted; the unsaved edits are LOST (could not write {rescue}: "
              f"{exc.strerror or exc})", file=sys.stderr)
        return 130
    print(f"{COMMAND}: interrupted; the unsaved edits were saved to {rescue} ({target} has "
          "the last F2 save)", file=sys.stderr)
    return 130


def _create(target: Path, empty) -> None:
    """``kas edit FILE`` makes FILE (an empty keyframe) if it is missing."""
    from camlab88.apps.kas import files

    try:
        files.save_keyframe(target, empty)
    except OSError as exc:
        print(f"{COMMAND}: cannot create {target} yet ({exc.strerror or exc}); F2 tries again")
        return
    print(f"{COMMAND}: created {target} (an empty keyframe)")


def _run(front, args: argparse.Namespace, prepared, start):
    from camlab88.commands.kas import run_front

    keys = KEYS + ("; the tablet is the stylus" if args.tablet else "; the mouse is the stylus")
    return run_front(front, args, COMMAND, keys, prepared, start)


# the keyframe the session started from, in its save state: F2 rewrites FILE, so a load
# starts from the state's keyframe (read by the keyframe reader), and FILE is only where
# F2 saves (the command line's; FILE's content is left out of the state's identity)
START = Opt(Str(1 << 24))


def _start_state(front, start, over, args: argparse.Namespace, save):
    from camlab88.apps.kas import files
    from camlab88.apps.kas.editor import Editor
    from camlab88.emulator.harness.input_log import StartState

    text = files.keyframe_text(start) if start is not None else None

    def load(kept: str | None) -> None:
        drawing = files.parse_keyframe(kept, "the state's keyframe") if kept else None
        front.editor = Editor(drawing, over, args.seed)
        front.editor.on_save = save

    return StartState(START, lambda: text, load, (args.file,))


def _report(ed, machine, target: Path, saved: list[int], preview: bool,
            discarded: bool = False) -> None:
    if preview:
        state = "screenshot run: nothing saved"
    elif discarded and ed.dirty:
        state = "NOT saved: quit without saving the last edits"
    elif not saved:
        state = "NOT saved (F2 saves)" if ed.dirty else "nothing to save"
    elif ed.dirty:
        state = f"saved {target} earlier, but the last edits are NOT saved"
    else:
        state = f"saved {target}"
    print(f"kas edit: {len(ed.drawing.chains)} chains, {ed.drawing.n_points} points; {state}; "
          f"{machine.line_stats['host_to_device_bytes']} characters to the Sigma")
