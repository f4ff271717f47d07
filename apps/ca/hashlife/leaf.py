"""One generation of a rule set on a small grid of life-form values: HashLife's base case.

The direct engine sends messages from each live cell (thesis section 7.5); here each cell
gathers the messages it would receive, which is the same computation seen from the target:
senders row by row, left to right (the order the engine applies them, so mixed operations
give the same value), each sender contributing its one grid entry for this offset.  A cell
that receives nothing is dead next generation, whatever the interpretation of 0 says; the
``WALL`` outside a bounded plane sends nothing and never changes.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numba import njit

from apps.ca.hashlife.store import WALL
from apps.ca.rules import OP_ADD, OP_AND, OP_OR, OP_XOR, RuleSet
from apps.ca.tables import LOOKUP_SIZE, compile_rules

M32 = 0xFFFFFFFF


class NotDeterministic(ValueError):
    """The rule set has section 8.1 probabilistic outcomes or broadcasts: HashLife cannot
    memoise it (the result of a region would depend on where and when it is)."""


@dataclass(frozen=True)
class LeafRule:
    """The rules as gather tables: ``inc[t, oy + ry, ox + rx]`` is the message a life-form
    ``t`` at offset (oy, ox) from a cell sends to it (-1: none)."""

    inc: np.ndarray  # int64[T, 2ry+1, 2rx+1]
    mop: np.ndarray  # int64[M] operation of each message
    mval: np.ndarray  # int64[M]
    lookup: np.ndarray  # int64[65536]: interpretation line of small values, -1 = dies
    kind: np.ndarray  # int64[I] the lines, for values beyond the lookup table
    a: np.ndarray
    b: np.ndarray
    form: np.ndarray  # int64[I] the life-form each line gives
    ry: int
    rx: int
    shift: int  # s: 2**s >= the reach, so a level-k node steps 2**(k-2-s) generations


def deterministic_reason(rules: RuleSet) -> str | None:
    """Why HashLife cannot run ``rules`` (None: it can)."""
    if any(f.broadcast is not None for f in rules.forms.values()):
        return "the rules broadcast messages (section 8.1), which reach every cell"
    if any(len(it.outcome.choices) != 1 for it in rules.interpretations):
        return "the rules have probabilistic outcomes (section 8.1)"
    return None


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


def leaf_rule(rules: RuleSet) -> LeafRule:
    """The gather tables of ``rules`` (cached on the rule set)."""
    cached = rules._tables.get("hashlife_leaf")
    if cached is not None:
        return cached
    reason = deterministic_reason(rules)
    if reason is not None:
        raise NotDeterministic(f"HashLife cannot run {rules.source}: {reason}")
    t = compile_rules(rules)
    ry, rx = t.reach_y, t.reach_x
    ntypes = t.send_start.shape[0] - 1
    inc = np.full((ntypes, 2 * ry + 1, 2 * rx + 1), -1, np.int64)
    for form in range(1, ntypes):
        for k in range(t.send_start[form], t.send_start[form + 1]):
            inc[form, ry - t.send_dy[k], rx - t.send_dx[k]] = k
    reach = max(ry, rx, 1)
    rule = LeafRule(inc, t.send_op.copy(), t.send_val.copy(), t.lookup, t.interp_kind,
                    t.interp_a, t.interp_b, t.out_form[t.out_start[:-1]].copy(), ry, rx,
                    (reach - 1).bit_length())
    rules._tables["hashlife_leaf"] = rule
    return rule


@njit(cache=True, inline="always")
def _apply(cur, op, val):
    if op == 1:
        return (cur + val) & M32
    if op == 2:
        return cur | val
    if op == 3:
        return cur & val
    return cur ^ val


@njit(cache=True)
def _interpret(v, lookup, kind, a, b, form):
    if v < LOOKUP_SIZE:
        i = lookup[v]
    else:
        i = -1
        for j in range(kind.shape[0]):
            if kind[j] == 0:
                hit = v == a[j]
            elif kind[j] == 1:
                hit = (v & a[j]) == b[j]
            else:
                hit = a[j] <= v <= b[j]
            if hit:
                i = j
                break
    return 0 if i < 0 else form[i]


@njit(cache=True)
def generation(src, dst, lo, hi, inc, mop, mval, lookup, kind, a, b, form):
    """dst[y, x] = next value of src[y, x] for lo <= y, x < hi (the caller keeps the reach
    of every such cell inside src)."""
    ntypes, h, w = inc.shape
    ry, rx = h // 2, w // 2
    for y in range(lo, hi):
        for x in range(lo, hi):
            c = src[y, x]
            if c == WALL:
                dst[y, x] = WALL
                continue
            got = False
            v = np.int64(0)  # int64, not literal 0: one cached signature for _interpret
            for oy in range(h):
                row = src[y + oy - ry]
                for ox in range(w):
                    t = row[x + ox - rx]
                    if t <= 0 or t >= ntypes:
                        continue
                    k = inc[t, oy, ox]
                    if k >= 0:
                        v = _apply(v, mop[k], mval[k])
                        got = True
            dst[y, x] = _interpret(np.int64(v), lookup, kind, a, b, form) if got else 0
