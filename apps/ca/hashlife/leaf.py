"""One generation of a rule set on a small grid of life-form values: HashLife's base case.

The same computation as the direct engine's window kernel (thesis section 7.5): every live
cell sends its messages, senders row by row and left to right, each sender's grid row by
row, so mixed operations give the same value; a cell that receives nothing is dead next
generation, whatever the interpretation of 0 says; the ``WALL`` outside a bounded plane
sends nothing and never changes.  The rules travel as one packed int64 array (``pack``).
"""

from __future__ import annotations

import numpy as np
from camlab88.apps.ca.hashlife.store import WALL
from camlab88.apps.ca.rules import OP_ADD, OP_AND, OP_OR, OP_XOR, RuleSet
from camlab88.apps.ca.tables import LOOKUP_SIZE, compile_rules
from camlab88.base.kernel_set import KernelSet

kernels = KernelSet(__name__)

M32 = 0xFFFFFFFF
# Header of the packed rules: counts, then where each table starts in the array.
H_TYPES, H_LINES, H_RY, H_RX, H_START, H_DY, H_DX, H_OP, H_VAL, H_LOOKUP, H_KIND, H_A, H_B, \
    H_FORM = range(14)
HEADER = 16


class NotDeterministic(ValueError):
    """The rule set has section 8.1 probabilistic outcomes or broadcasts: HashLife cannot
    memoise it (the result of a region would depend on where and when it is)."""


def deterministic_reason(rules: RuleSet) -> str | None:
    """Why HashLife cannot run ``rules`` (None: it can).  Kept with the rule set's other
    derived tables: every jump asks twice, and the walk over its rules cost ~3 us."""
    cached = rules._tables.get("hashlife_reason", ())
    if cached != ():
        return cached
    reason = None
    if any(f.broadcast is not None for f in rules.forms.values()):
        reason = "the rules broadcast messages (section 8.1), which reach every cell"
    elif any(len(it.outcome.choices) != 1 for it in rules.interpretations):
        reason = "the rules have probabilistic outcomes (section 8.1)"
    rules._tables["hashlife_reason"] = reason
    return reason


def order_matters(rules: RuleSet) -> bool:
    """Whether the order in which a cell receives its messages can change its value.

    One kind of operation is order-free (each is commutative and associative); additions
    beside ORs or XORs are too while the largest sum the additions can make stays below
    every bit those set (no carry meets them).  Otherwise the direct engine's order —
    senders by absolute row and column — decides, and across the wrapping plane's seam that
    order is not the order relative to the receiver, so HashLife (which knows no absolute
    positions) keeps live cells away from the seam there (algorithm.py)."""
    ops = {m.op for f in rules.forms.values() for m in f.messages}
    if len(ops) <= 1:
        return False
    if OP_AND in ops or {OP_OR, OP_XOR} <= ops:
        return True
    per_offset: dict[tuple[int, int], int] = {}
    bits = 0
    for f in rules.forms.values():
        for m in f.messages:
            if m.op == OP_ADD:
                per_offset[(m.dy, m.dx)] = max(per_offset.get((m.dy, m.dx), 0), m.value)
            else:
                bits |= m.value
    most = sum(per_offset.values())
    return bool(bits & ((1 << most.bit_length()) - 1))


def pack(rules: RuleSet) -> np.ndarray:
    """The rules' tables in one int64 array: a header of counts and offsets, then the
    send tables, the interpretation lookup and lines, and each line's life-form."""
    reason = deterministic_reason(rules)
    if reason is not None:
        raise NotDeterministic(f"HashLife cannot run {rules.source}: {reason}")
    t = compile_rules(rules)
    form = t.out_form[t.out_start[:-1]]
    parts = [t.send_start, t.send_dy, t.send_dx, t.send_op, t.send_val, t.lookup,
             t.interp_kind, t.interp_a, t.interp_b, form]
    head = np.zeros(HEADER, np.int64)
    head[H_TYPES] = t.send_start.shape[0] - 1
    head[H_LINES] = t.interp_kind.shape[0]
    head[H_RY], head[H_RX] = t.reach_y, t.reach_x
    at = HEADER
    for h, part in zip(range(H_START, H_FORM + 1), parts):
        head[h] = at
        at += part.shape[0]
    return np.concatenate([head, *(np.asarray(p, np.int64) for p in parts)])


@kernels.kernel(inline="always")
def _apply(cur, op, val):
    if op == 1:
        return (cur + val) & M32
    if op == 2:
        return cur | val
    if op == 3:
        return cur & val
    return cur ^ val


@kernels.kernel
def _interpret(v, R):
    """The life-form a cell with message value ``v`` becomes (0: dies)."""
    if v < LOOKUP_SIZE:
        i = R[R[H_LOOKUP] + v]
    else:
        i = -1
        kind, a, b = R[H_KIND], R[H_A], R[H_B]
        for j in range(R[H_LINES]):
            k = R[kind + j]
            if k == 0:
                hit = v == R[a + j]
            elif k == 1:
                hit = (v & R[a + j]) == R[b + j]
            else:
                hit = R[a + j] <= v <= R[b + j]
            if hit:
                i = j
                break
    return np.int64(0) if i < 0 else R[R[H_FORM] + i]


@kernels.export("void(int64[:, ::1], int64, int64, int64, int64, int64[::1])")
def generation(G, s, d, lo, hi, R):
    """Plane d = the next values of plane s for lo <= y, x < hi (the caller keeps the reach
    of every such cell inside the grid); plane 3 is the message scratch.  G holds four
    square planes one above the other (plane p, row y: G[p * side + y]; planes of one
    array, not views: numba reference-counts every view)."""
    n = G.shape[1]
    S, D, M = s * n, d * n, 3 * n
    ntypes, ry, rx = R[H_TYPES], R[H_RY], R[H_RX]
    start, sdy, sdx, sop, sval = R[H_START], R[H_DY], R[H_DX], R[H_OP], R[H_VAL]
    for y in range(lo, hi):
        for x in range(lo, hi):
            G[M + y, x] = -1  # -1: received nothing (message values are 32-bit, >= 0)
    for y in range(lo - ry, hi + ry):
        for x in range(lo - rx, hi + rx):
            t = G[S + y, x]
            if t <= 0 or t >= ntypes:
                continue
            for k in range(R[start + t], R[start + t + 1]):
                ty = y + R[sdy + k]
                tx = x + R[sdx + k]
                if lo <= ty < hi and lo <= tx < hi:
                    cur = G[M + ty, tx]
                    G[M + ty, tx] = _apply(cur if cur >= 0 else np.int64(0), R[sop + k],
                                          R[sval + k])
    for y in range(lo, hi):
        for x in range(lo, hi):
            v = G[M + y, x]
            if G[S + y, x] == WALL:
                G[D + y, x] = WALL
            elif v < 0:
                G[D + y, x] = 0
            else:
                G[D + y, x] = _interpret(v, R)
