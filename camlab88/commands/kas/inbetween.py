"""``camlab88 kas inbetween``: in-between keyframes into a sequence."""

from __future__ import annotations

import argparse

from camlab88.runopts import fail


def _timing(name: str | None):
    from camlab88.apps.kas import files, library, timing

    if name is None:
        return None
    path = library.resolve(name)
    if not path.exists() and name in timing.BUILTIN:
        return timing.curve(name)
    return files.load_timing(path)

DESCRIPTION = """\
Frames from keyframe A to B (both included) along a sample path, placed by a timing (tick \
marks or a curve); with more than two keyframes a spline goes through them all."""


HELP = "in-between keyframes into a sequence"


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("keys", nargs="+", metavar="KEY", help="two or more keyframe files")
    p.add_argument("--path", help="sample path file (two keyframes only)")
    p.add_argument("--timing",
                   help="timing file (ticks or curve) or a built-in curve name: linear, "
                        "ease-in, ease-out, ease-in-out, overshoot")
    p.add_argument("--count", "--frames", dest="frames", type=int, metavar="N",
                   help="frames per pair of keyframes, both included (--frames N is the "
                        "old spelling: elsewhere --frames names a directory of PNGs)")
    p.add_argument("--missing", default="copy-nearest", choices=["copy-nearest", "grow", "stay"],
                   help="what chains missing from a keyframe do (default copy-nearest)")
    p.add_argument("--fit", default="similarity-reflect",
                   choices=["similarity-reflect", "axis-stretch", "similarity", "stretch"],
                   help="how the path is fitted to each point pair: axis-stretch is the "
                        "thesis's literal per-axis stretch, similarity-reflect (default; "
                        "'stretch' is its old name) and similarity are ours (docs/kas.md)")
    p.add_argument("--method", default="catmull-rom",
                   choices=["linear", "overhauser", "catmull-rom", "kochanek-bartels"],
                   help="spline through three or more keyframes (default catmull-rom)")
    p.add_argument("--tension", default=0.0, type=float)
    p.add_argument("--continuity", default=0.0, type=float)
    p.add_argument("--bias", default=0.0, type=float)
    p.add_argument("--keep-redundant", action="store_true",
                   help="keep collinear points instead of dropping them")
    p.add_argument("--fps", default=25.0, type=float)
    p.add_argument("--out", required=True, help="sequence file to write")


def run(args: argparse.Namespace) -> int:
    from camlab88.apps.kas import files, library, pathfit
    from camlab88.apps.kas.inbetween import check_cost, frame_count, inbetween, inbetween_keys

    try:
        keys = [files.load_drawing_or_frame(library.resolve(k)) for k in args.keys]
        if len(keys) < 2:
            raise ValueError("give at least two keyframes")
        tm = _timing(args.timing)
        if len(keys) == 2 or args.frames is not None or (tm is not None and tm.kind == "ticks"):
            check_cost(" + ".join(args.keys), keys, frame_count(tm, args.frames, len(keys)))
        if len(keys) == 2:
            path = pathfit.load_checked(library.resolve(args.path)) if args.path else None
            seq = inbetween(keys[0], keys[1], args.frames, path, tm, args.missing, args.fit,
                            not args.keep_redundant, args.fps)
        else:
            if args.path:
                raise ValueError("--path works between two keyframes; split the sequence")
            if args.frames is None and (tm is None or tm.kind != "ticks"):
                raise ValueError("--count N is needed (frames per pair of keyframes)")
            seq = inbetween_keys(keys, args.frames, args.method, tm, args.missing,
                                 args.tension, args.continuity, args.bias,
                                 not args.keep_redundant, args.fps)
        files.save_sequence(args.out, seq)
    except (OSError, ValueError) as exc:
        return fail("camlab88 kas inbetween", exc)
    print(f"{args.out}: {len(seq)} frames, {sum(f.n_points for f in seq.frames)} points")
    return 0
