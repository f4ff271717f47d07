"""``camlab88 kas edit-script``: the keyframe editor model on an event script, headless."""

from __future__ import annotations

import argparse

from camlab88.runopts import fail

DESCRIPTION = """\
Headless: feed the editor model the events of SCRIPT (move/down/up X Y, key K, menu ITEM, \
type TEXT) and save the keyframe."""


HELP = "run the keyframe editor model on an event script"


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("script")
    p.add_argument("--start", help="keyframe to start from (default empty)")
    p.add_argument("--over", help="previous keyframe to draw over (§2.3 guide)")
    p.add_argument("--seed", default=0, type=int)
    p.add_argument("--out", required=True)


def run(args: argparse.Namespace) -> int:
    from camlab88.apps.kas import files, library
    from camlab88.apps.kas.editor import Editor
    from camlab88.apps.kas.events import parse_script
    from camlab88.base.textinput import read_text  # a missing file named, not [Errno 2]

    try:
        start = files.load_keyframe(library.resolve(args.start)) if args.start else None
        over = files.load_drawing_or_frame(library.resolve(args.over)) if args.over else None
        events = parse_script(read_text(args.script), args.script)
        ed = Editor(start, over, args.seed)
        ed.run(events)
        files.save_keyframe(args.out, ed.drawing)
    except (OSError, ValueError) as exc:
        return fail("camlab88 kas edit-script", exc)
    print(f"{args.out}: {len(ed.drawing.chains)} chains, {ed.drawing.n_points} points"
          + (f"; {ed.message}" if ed.message else ""))
    return 0
