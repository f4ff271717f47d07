"""``camlab88 kas ...``: the keyframe animation suite of thesis chapter 3.

Non-interactive programs for now: in-betweener, superimposer, plotter, exporter, the
real-time viewer's schedule, and the editor model run from an event script.  The device
fronts (``kas edit``, ``kas view`` on the emulated Sigma) register here later.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path


def register(subparsers: argparse._SubParsersAction) -> None:
    kas = subparsers.add_parser("kas", help="KAS, the keyframe animation suite (chapter 3)",
                                description="KAS: keyframe editor model, in-betweener, "
                                "superimposer, viewer schedule and hard copy (thesis ch. 3). "
                                "File names may be library names (see 'kas library').")
    sub = kas.add_subparsers(dest="kas_command", metavar="KAS_COMMAND")
    sub.required = True

    ib = sub.add_parser("inbetween", help="in-between keyframes into a sequence",
                        description="Frames from keyframe A to B (both included) along a "
                        "sample path, placed by a timing (tick marks or a curve); with more "
                        "than two keyframes a spline goes through them all.")
    ib.add_argument("keys", nargs="+", metavar="KEY", help="two or more keyframe files")
    ib.add_argument("--path", help="sample path file (two keyframes only)")
    ib.add_argument("--timing", help="timing file (ticks or curve) or a built-in curve name: "
                    "linear, ease-in, ease-out, ease-in-out, overshoot")
    ib.add_argument("--frames", type=int, help="frames per pair of keyframes, both included")
    ib.add_argument("--missing", default="copy-nearest",
                    choices=("copy-nearest", "grow", "stay"),
                    help="what chains missing from a keyframe do (default copy-nearest)")
    ib.add_argument("--fit", default="stretch", choices=("stretch", "similarity"),
                    help="how the path is fitted to each point pair (default stretch)")
    ib.add_argument("--method", default="catmull-rom",
                    choices=("linear", "overhauser", "catmull-rom", "kochanek-bartels"),
                    help="spline through three or more keyframes (default catmull-rom)")
    ib.add_argument("--tension", type=float, default=0.0)
    ib.add_argument("--continuity", type=float, default=0.0)
    ib.add_argument("--bias", type=float, default=0.0)
    ib.add_argument("--keep-redundant", action="store_true",
                    help="keep collinear points instead of dropping them")
    ib.add_argument("--fps", type=float, default=25.0)
    ib.add_argument("--out", required=True, help="sequence file to write")
    ib.set_defaults(handler=_inbetween)

    sp = sub.add_parser("superimpose", help="superimpose sequences with start offsets",
                        description="Combine sequences; SEQ@N starts N frames late (its first "
                        "frame is held until then); a sequence that ends early holds its "
                        "last frame. The same sequence may be given several times.")
    sp.add_argument("seqs", nargs="+", metavar="SEQ[@OFFSET]")
    sp.add_argument("--out", required=True)
    sp.set_defaults(handler=_superimpose)

    pl = sub.add_parser("plot", help="plot every frame (HP-GL, SVG, PDF) with registration "
                        "marks", description="Each frame at the given size (default the "
                        "twelve-field, 12 x 8.75 inches) with registration marks; HP-GL uses "
                        "pen N for colour N; PDF is one multi-page sequence.pdf.")
    pl.add_argument("seq")
    pl.add_argument("--hpgl", metavar="DIR")
    pl.add_argument("--svg", metavar="DIR")
    pl.add_argument("--pdf", metavar="DIR")
    pl.add_argument("--width", type=float, default=12.0, help="inches (default 12)")
    pl.add_argument("--height", type=float, default=8.75, help="inches (default 8.75)")
    pl.add_argument("--margin", type=float, default=1.0, help="inches round the field")
    pl.set_defaults(handler=_plot)

    ex = sub.add_parser("export", help="export a sequence as GIF, MP4 or PNGs",
                        description="Render every frame (interim software rasteriser) and "
                        "write OUT.gif, OUT.mp4 or OUT_NNNN.png, with a progress bar.")
    ex.add_argument("seq")
    ex.add_argument("out")
    ex.add_argument("--width", type=int, default=768)
    ex.add_argument("--background", choices=("black", "white"), default="black")
    ex.set_defaults(handler=_export)

    sc = sub.add_parser("schedule", help="which frames the real-time viewer shows and drops",
                        description="Given each frame's size in characters on the line, "
                        "compute the real-time line test of §3.1.4: the frame due now is "
                        "sent after each swap; frames passed over are dropped.")
    sc.add_argument("sizes", help="comma-separated characters per frame, or @FILE with one "
                    "number a line")
    sc.add_argument("--fps", type=float, default=25.0)
    sc.add_argument("--baud", type=float, default=9600)
    sc.add_argument("--bits-per-char", type=float, default=10.0, help="10 for 8N1")
    sc.set_defaults(handler=_schedule)

    sh = sub.add_parser("edit-script", help="run the keyframe editor model on an event script",
                        description="Headless: feed the editor model the events of SCRIPT "
                        "(move/down/up X Y, key K, menu ITEM, type TEXT) and save the keyframe.")
    sh.add_argument("script")
    sh.add_argument("--start", help="keyframe to start from (default empty)")
    sh.add_argument("--over", help="previous keyframe to draw over (§2.3 guide)")
    sh.add_argument("--seed", type=int, default=0)
    sh.add_argument("--out", required=True)
    sh.set_defaults(handler=_edit_script)

    ps = sub.add_parser("path-script", help="draw a sample path and tick marks from a script",
                        description="Headless in-betweener set-up: keyframes A and B are "
                        "shown, the SCRIPT's stylus stroke draws the path, 't' then touches "
                        "place tick marks; writes the path and the tick timing.")
    ps.add_argument("first")
    ps.add_argument("second")
    ps.add_argument("script")
    ps.add_argument("--path-out", required=True)
    ps.add_argument("--timing-out", required=True)
    ps.set_defaults(handler=_path_script)

    dm = sub.add_parser("demo", help="build 'a line taking a walk' from the library")
    dm.add_argument("--out", required=True, help="sequence file to write")
    dm.set_defaults(handler=_demo)

    lb = sub.add_parser("library", help="list the shipped keyframes, paths and timings")
    lb.set_defaults(handler=_library)


def _fail(cmd: str, exc: Exception) -> int:
    print(f"camlab88 kas {cmd}: {exc}", file=sys.stderr)
    return 2


def _progress(label: str):
    """A text progress bar on a terminal; nothing when stderr is a file or pipe."""
    if not sys.stderr.isatty():
        return None

    def show(i: int, n: int) -> None:
        width = 30
        done = width * i // max(n, 1)
        sys.stderr.write(f"\r{label} [{'#' * done}{'.' * (width - done)}] {i}/{n}")
        if i >= n:
            sys.stderr.write("\n")
        sys.stderr.flush()
    return show


def _timing(name: str | None):
    from apps.kas import files, library, timing

    if name is None:
        return None
    path = library.resolve(name)
    if not path.exists() and name in timing.BUILTIN:
        return timing.curve(name)
    return files.load_timing(path)


def _inbetween(args: argparse.Namespace) -> int:
    from apps.kas import files, library
    from apps.kas.inbetween import inbetween, inbetween_keys

    try:
        keys = [files.load_drawing_or_frame(library.resolve(k)) for k in args.keys]
        if len(keys) < 2:
            raise ValueError("give at least two keyframes")
        tm = _timing(args.timing)
        if len(keys) == 2:
            path = files.load_path(library.resolve(args.path)) if args.path else None
            seq = inbetween(keys[0], keys[1], args.frames, path, tm, args.missing, args.fit,
                            not args.keep_redundant, args.fps)
        else:
            if args.path:
                raise ValueError("--path works between two keyframes; split the sequence")
            if args.frames is None and (tm is None or tm.kind != "ticks"):
                raise ValueError("--frames is needed")
            seq = inbetween_keys(keys, args.frames, args.method, tm, args.missing,
                                 args.tension, args.continuity, args.bias,
                                 not args.keep_redundant, args.fps)
        files.save_sequence(args.out, seq)
    except (OSError, ValueError) as exc:
        return _fail("inbetween", exc)
    print(f"{args.out}: {len(seq)} frames, {sum(f.n_points for f in seq.frames)} points")
    return 0


def _superimpose(args: argparse.Namespace) -> int:
    from apps.kas import files, library
    from apps.kas.superimpose import superimpose

    try:
        parts = []
        cache: dict[str, object] = {}
        for spec in args.seqs:
            name, _, off = spec.rpartition("@") if "@" in spec else (spec, "", "0")
            try:
                offset = int(off)
            except ValueError:
                raise ValueError(f"{spec!r}: the offset after @ must be a whole number") \
                    from None
            if name not in cache:
                cache[name] = files.load_sequence(library.resolve(name))
            parts.append((cache[name], offset))
        seq = superimpose(parts)
        files.save_sequence(args.out, seq)
    except (OSError, ValueError) as exc:
        return _fail("superimpose", exc)
    print(f"{args.out}: {len(seq)} frames")
    return 0


def _plot(args: argparse.Namespace) -> int:
    from apps.kas import files, library, plot

    targets = [(f, d) for f, d in (("hpgl", args.hpgl), ("svg", args.svg), ("pdf", args.pdf))
               if d]
    if not targets:
        return _fail("plot", ValueError("give --hpgl DIR, --svg DIR and/or --pdf DIR"))
    try:
        if min(args.width, args.height) <= 0 or args.margin < 0:
            raise ValueError("sizes must be positive")
        seq = files.load_sequence(library.resolve(args.seq))
        size = plot.PlotSize(args.width, args.height, args.margin)
        for fmt, d in targets:
            written = plot.plot_sequence(seq, d, fmt, size, _progress(f"plot {fmt}"))
            print(f"{fmt}: {len(written)} file(s) in {d}")
    except (OSError, ValueError) as exc:
        return _fail("plot", exc)
    return 0


def _export(args: argparse.Namespace) -> int:
    from apps.kas import files, library
    from apps.kas.export import export

    try:
        seq = files.load_sequence(library.resolve(args.seq))
        out = export(seq, args.out, args.width, args.background, _progress("export"))
    except (OSError, ValueError) as exc:
        return _fail("export", exc)
    print(f"wrote {out}")
    return 0


def _schedule(args: argparse.Namespace) -> int:
    from apps.kas import viewer_schedule as vs

    try:
        text = args.sizes
        if text.startswith("@"):
            text = ",".join(Path(text[1:]).read_text().split())
        sizes = [int(s) for s in text.split(",") if s.strip()]
        if any(s < 0 for s in sizes):
            raise ValueError("sizes must not be negative")
        sched = vs.realtime(sizes, args.fps, args.baud, args.bits_per_char)
    except (OSError, ValueError) as exc:
        return _fail("schedule", exc)
    print(f"{len(sched.shown)} shown, {len(sched.dropped)} dropped, {sched.end:.3f} s")
    print("shown:", " ".join(map(str, sched.shown_frames)))
    print("dropped:", " ".join(map(str, sched.dropped)))
    return 0


def _edit_script(args: argparse.Namespace) -> int:
    from apps.kas import files, library
    from apps.kas.editor import Editor
    from apps.kas.events import parse_script

    try:
        start = files.load_keyframe(library.resolve(args.start)) if args.start else None
        over = files.load_drawing_or_frame(library.resolve(args.over)) if args.over else None
        events = parse_script(Path(args.script).read_text(encoding="utf-8"), args.script)
        ed = Editor(start, over, args.seed)
        ed.run(events)
        files.save_keyframe(args.out, ed.drawing)
    except (OSError, ValueError) as exc:
        return _fail("edit-script", exc)
    print(f"{args.out}: {len(ed.drawing.chains)} chains, {ed.drawing.n_points} points"
          + (f"; {ed.message}" if ed.message else ""))
    return 0


def _path_script(args: argparse.Namespace) -> int:
    from apps.kas import files, library
    from apps.kas.events import parse_script
    from apps.kas.path_editor import PathEditor

    try:
        pe = PathEditor(files.load_drawing_or_frame(library.resolve(args.first)),
                        files.load_drawing_or_frame(library.resolve(args.second)))
        pe.run(parse_script(Path(args.script).read_text(encoding="utf-8"), args.script))
        path = pe.sample_path()
        if path is None:
            raise ValueError(f"{args.script}: the script draws no path")
        files.save_path(args.path_out, path)
        files.save_timing(args.timing_out, pe.timing())
    except (OSError, ValueError) as exc:
        return _fail("path-script", exc)
    print(f"path of {len(path.points)} points, {len(pe.ticks)} ticks "
          f"({len(pe.ticks) + 2} frames with the keyframes)")
    return 0


def _demo(args: argparse.Namespace) -> int:
    from apps.kas import demo, files

    try:
        seq = demo.build()
        files.save_sequence(args.out, seq)
    except (OSError, ValueError) as exc:
        return _fail("demo", exc)
    print(f"{args.out}: {len(seq)} frames")
    return 0


def _library(args: argparse.Namespace) -> int:
    from apps.kas import library

    for name, kind in library.entries():
        print(f"{name:16} {kind}")
    return 0
