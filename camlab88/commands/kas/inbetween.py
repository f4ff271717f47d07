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


def _inbetween(args: argparse.Namespace) -> int:
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
