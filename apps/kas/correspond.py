"""Correspondence between keyframes (§3.1.2): chains match by drawing order; chains are
resampled to equal point counts; chains missing from a keyframe are invented by a rule."""

from __future__ import annotations

import numpy as np

from camlab88.apps.kas.model import Chain, Drawing

MISSING_RULES = ("copy-nearest", "grow", "stay")


def resample(chain: Chain, n: int) -> Chain:
    """``chain`` with ``n - len(chain)`` extra points equally spaced along its length.

    The original vertices are kept, so the drawn line is unchanged (figure 3.3); an extra
    point takes the colour of the segment it lies on.
    """
    m = len(chain)
    if m == 0:
        raise ValueError("cannot resample an empty line-chain")
    if n < m:
        raise ValueError("resampling only adds points")
    extra = n - m
    if extra == 0:
        return chain.copy()
    pts = chain.points
    seg = np.hypot(*np.diff(pts, axis=0).T) if m > 1 else np.zeros(0)
    cum = np.concatenate([[0.0], np.cumsum(seg)])
    length = cum[-1]
    pos = length * np.arange(1, extra + 1) / (extra + 1)
    if m > 1 and length > 0:
        ex = np.column_stack([np.interp(pos, cum, pts[:, 0]), np.interp(pos, cum, pts[:, 1])])
        seg_end = np.clip(np.searchsorted(cum, pos, side="right"), 1, m - 1)
    else:
        ex = np.repeat(pts[:1], extra, axis=0)
        seg_end = np.zeros(extra, dtype=int)
    ex_col = chain.colours[seg_end]
    all_pos = np.concatenate([cum, pos])
    is_extra = np.concatenate([np.zeros(m), np.ones(extra)])
    order = np.lexsort((is_extra, all_pos))
    points = np.concatenate([pts, ex])[order]
    colours = np.concatenate([chain.colours, ex_col])[order]
    return Chain(points, colours, chain.section)


def nearest_chain(chains: list[Chain], target: Chain) -> int:
    """Index of the chain whose centre is nearest ``target``'s centre (ties: first drawn)."""
    centres = np.array([c.centre() for c in chains])
    d = np.hypot(*(centres - target.centre()).T)
    return int(np.argmin(d))


def invent(present_in: Drawing, ref: Chain, rule: str) -> Chain:
    """The counterpart, in a keyframe lacking it, of ``ref`` (a chain another key has)."""
    if rule == "copy-nearest":
        if not present_in.chains:
            rule = "grow"  # nothing to copy: growing from the centre is the only choice
        else:
            src = present_in.chains[nearest_chain(present_in.chains, ref)]
            return Chain(src.points.copy(), src.colours.copy(), ref.section)
    if rule == "grow":
        pts = np.repeat(ref.centre()[None], len(ref), axis=0)
        return Chain(pts, ref.colours.copy(), ref.section)
    if rule == "stay":
        return Chain(ref.points.copy(), ref.colours.copy(), ref.section)
    raise ValueError(f"missing-chain rule must be one of {', '.join(MISSING_RULES)}")


def match(keys: list[Drawing], rule: str = "copy-nearest") -> list[list[Chain]]:
    """Chains of every key, made to correspond: ``out[k][j]`` is chain j of key k, and for
    each j all keys have the same point count."""
    if len(keys) < 2:
        raise ValueError("in-betweening needs at least two keyframes")
    if rule not in MISSING_RULES:
        raise ValueError(f"missing-chain rule must be one of {', '.join(MISSING_RULES)}")
    for k in keys:
        if any(len(c) == 0 for c in k.chains):
            raise ValueError("a keyframe contains an empty line-chain")
    n_chains = max(len(k.chains) for k in keys)
    out: list[list[Chain]] = [[] for _ in keys]
    for j in range(n_chains):
        have = [i for i, k in enumerate(keys) if j < len(k.chains)]
        for i, key in enumerate(keys):
            if j < len(key.chains):
                out[i].append(key.chains[j])
            else:
                src = min(have, key=lambda h, i=i: (abs(h - i), h))  # nearest key in time
                out[i].append(invent(key, keys[src].chains[j], rule))
        n = max(len(out[i][j]) for i in range(len(keys)))
        for i in range(len(keys)):
            out[i][j] = resample(out[i][j], n)
    return out
