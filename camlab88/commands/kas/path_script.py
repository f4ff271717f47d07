"""``camlab88 kas path-script``: a sample path and tick marks from a script, headless."""

from __future__ import annotations

import argparse

from camlab88.runopts import fail

DESCRIPTION = """\
Headless in-betweener set-up: keyframes A and B are shown, the SCRIPT's stylus stroke draws \
the path, 't' then touches place tick marks; writes the path and the tick timing."""


HELP = "draw a sample path and tick marks from a script"


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("first")
    p.add_argument("second")
    p.add_argument("script")
    p.add_argument("--path-out", required=True)
    p.add_argument("--timing-out", required=True)


def run(args: argparse.Namespace) -> int:
    from camlab88.apps.kas import files, library
    from camlab88.apps.kas.events import parse_script
    from camlab88.apps.kas.path_editor import PathEditor
    from camlab88.base.textinput import read_text  # a missing file named, not [Errno 2]

    try:
        pe = PathEditor(files.load_drawing_or_frame(library.resolve(args.first)),
                        files.load_drawing_or_frame(library.resolve(args.second)))
        pe.run(parse_script(read_text(args.script), args.script))
        path = pe.sample_path()
        if path is None:
            raise ValueError(f"{args.script}: the script draws no path")
        files.save_path(args.path_out, path)
        files.save_timing(args.timing_out, pe.timing())
    except (OSError, ValueError) as exc:
        return fail("camlab88 kas path-script", exc)
    print(f"{args.path_out}: path of {len(path.points)} points; {args.timing_out}: "
          f"{len(pe.ticks)} ticks ({len(pe.ticks) + 2} frames with the keyframes)")
    return 0
