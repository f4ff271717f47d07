"""``camlab88 kas path A B --out P``: draw a sample path and tick marks on the Sigma."""

from __future__ import annotations

import argparse
from pathlib import Path

from camlab88.commands.kas import add_front_options
from camlab88.replay_policy import KEEP, SCRATCH
from camlab88.runopts import fail

COMMAND = "camlab88 kas path"
KEYS = """\
draw the path with the stylus (mouse); t then touches place ticks; F2 saves; Esc/close quits \
(asks if unsaved: y saves, n discards, Esc stays)"""

DESCRIPTION = """\
Keyframes A and B shown superimposed; the stylus draws the sample path, 't' then touches \
place tick marks; F2 (or the end of a headless script) saves the path to --out and the ticks \
to --ticks. A --screenshot run saves nothing but the PNG."""


HELP = "draw a sample path and tick marks on the Sigma"


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("first")
    p.add_argument("second")
    p.add_argument("--out", required=True, help="sample path file to write").replay = SCRATCH
    p.add_argument("--ticks",
                   help="tick timing file to write (default: OUT with _ticks)").replay = SCRATCH
    p.add_argument("--previous",
                   help="the previous pair's path, shown for continuity (default: the "
                        "path last saved for a pair ending at FIRST, if any)").replay = KEEP
    p.add_argument("--no-library", action="store_true",
                   help="do not keep the path in the user library (nor look up the "
                        "previous pair's)").replay = KEEP
    add_front_options(p)


def run(args: argparse.Namespace) -> int:
    from camlab88.apps.kas import files, library
    from camlab88.apps.kas.path_editor import PathEditor
    from camlab88.apps.kas.program import PathFront
    from camlab88.commands.kas import run_front

    out = Path(args.out)
    ticks = Path(args.ticks) if args.ticks else out.with_name(f"{out.stem}_ticks{out.suffix}")
    try:
        prev = _previous(args)
        model = PathEditor(files.load_drawing_or_frame(library.resolve(args.first)),
                           files.load_drawing_or_frame(library.resolve(args.second)), prev)
        save = _saver(args, out, ticks)

        def save_in_run(sample, timing) -> None:
            if not getattr(front, "rebuilding", False):  # (a --load-state runs it again)
                save(sample, timing)

        front = PathFront(model, args.background, save_in_run)
        try:
            run_front(front, args, COMMAND, KEYS)
        except KeyboardInterrupt:
            return _interrupted(front, out)
        sample = model.sample_path()
        if args.script is not None:
            if sample is None:
                raise ValueError(f"{args.script}: the script draws no path")
            save(sample, model.timing())
    except (OSError, ValueError) as exc:
        return fail(COMMAND, exc)
    if sample is not None:
        wrote = "" if args.screenshot is not None else f" -> {out}" + (
            f", {ticks}" if model.ticks else "")
        print(f"kas path: {len(sample.points)} path points, {len(model.ticks)} ticks{wrote}")
    return 0


def _interrupted(front, out: Path) -> int:
    """Ctrl-C: an unsaved path goes to a recovery file, named; --out keeps its last save."""
    import sys

    from camlab88.apps.kas import files

    sample = front.model.sample_path()
    if not front.unsaved() or sample is None:
        print(f"{COMMAND}: interrupted; nothing unsaved was lost", file=sys.stderr)
        return 130
    rescue = out.with_name(f"{out.stem}.recovered{out.suffix or '.kas'}")
    try:
        files.save_path(rescue, sample)
    except OSError as exc:
        print(f"{COMMAND}: interrupted; the unsaved path is LOST (could not write {rescue}: "
              f"{exc.strerror or exc})", file=sys.stderr)
        return 130
    print(f"{COMMAND}: interrupted; the unsaved path ({len(front.model.ticks)} ticks not kept) "
          f"was saved to {rescue}", file=sys.stderr)
    return 130


def _previous(args: argparse.Namespace):
    from camlab88.apps.kas import files, library

    prev_file = library.resolve(args.previous) if args.previous else None
    if prev_file is None and not args.no_library:
        prev_file = library.previous_pair_path(args.first)
        if prev_file is not None:
            print(f"kas path: showing the previous pair's path {prev_file}")
    return files.load_path(prev_file) if prev_file is not None else None


def _saver(args: argparse.Namespace, out: Path, ticks: Path):
    from camlab88.apps.kas import files, library

    def save(sample, timing) -> None:
        if args.screenshot is not None:  # a screenshot run never touches the user's files
            return
        files.save_path(out, sample)
        if len(timing.values):
            files.save_timing(ticks, timing)
        if not args.no_library:
            p_name, t_name = library.pair_names(args.first, args.second)
            files.save_path(library.user_file(p_name), sample)
            if len(timing.values):
                files.save_timing(library.user_file(t_name), timing)
    return save
