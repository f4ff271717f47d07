"""Timing: where along the path each frame sits (§3.1.2 tick marks; §3.2 timing curves)."""

from __future__ import annotations

import numpy as np

from camlab88.apps.kas.files import Timing, validate_timing


def curve(name: str, samples: int = 33) -> Timing:
    """A built-in timing curve (fraction of time -> fraction of distance)."""
    t = np.linspace(0.0, 1.0, samples)
    shapes = {
        "linear": t,
        "ease-in": t * t,
        "ease-out": 1 - (1 - t) ** 2,
        "ease-in-out": t * t * (3 - 2 * t),
        "overshoot": 1 - (1 - t) ** 2 * (1 - 2.5 * t),
    }
    if name not in shapes:
        raise ValueError(f"no built-in timing curve {name!r}; have {', '.join(BUILTIN)}")
    return Timing("curve", np.column_stack([t, shapes[name]]), name)


BUILTIN = ("linear", "ease-in", "ease-out", "ease-in-out", "overshoot")


def ticks_from_curve(t: Timing, frames: int) -> Timing:
    """The tick marks a curve gives for ``frames`` frames (in-betweens only).  Ticks lie on
    the path in order, so a curve that overshoots or turns back (e.g. ``overshoot``) has no
    tick form: ValueError."""
    d = fractions(t, frames)
    out = Timing("ticks", d[1:-1], t.name)
    validate_timing(out)
    return out


def fractions(t: Timing | None, frames: int | None) -> np.ndarray:
    """Distance fractions for every frame, keyframes included (first 0, last 1).

    Tick timing fixes the frame count (ticks + 2); a curve needs ``frames``.
    """
    if t is None:
        t = curve("linear")
    if t.kind == "ticks":
        validate_timing(t)
        n = len(t.values) + 2
        if frames is not None and frames != n:
            raise ValueError(f"the tick timing has {len(t.values)} in-betweens, i.e. {n} "
                             f"frames with the keyframes, but {frames} frames were asked for")
        return np.concatenate([[0.0], t.values, [1.0]])
    validate_timing(t)
    if frames is None:  # e.g. `kas inbetween A B --timing ease-in` without --frames
        named = f" {t.name!r}" if t.name else ""
        raise ValueError(f"the timing curve{named} spreads the frames along the path but no "
                         "frame count was given: --frames N is missing (N >= 2, both "
                         "keyframes counted)")
    if frames < 2:
        raise ValueError(f"a timing curve needs a frame count of at least 2 (both keyframes), "
                         f"not {frames}")
    u = np.linspace(0.0, 1.0, frames)
    d = np.interp(u, t.values[:, 0], t.values[:, 1])
    d[0], d[-1] = 0.0, 1.0  # the keyframes themselves are never moved (§3.1.2)
    return d
