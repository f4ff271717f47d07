"""One generation of a rule set on a small grid of life-form values: HashLife's base case.

The same computation as the direct engine's window kernel (thesis section 7.5): every live
cell sends its messages, senders row by row and left to right, each sender's grid row by
row, so mixed operations give the same value; a cell that receives nothing is dead next
generation, whatever the interpretation of 0 says; the ``WALL`` outside a bounded plane
sends nothing and never changes.  The rules travel as one packed int64 array (``pack``).
"""

from __future__ import annotations

import numpy as np

from camlab88.apps.ca.hashlife.kernels import (
    H_FORM,
    H_LINES,
    H_RX,
    H_RY,
    H_START,
    H_TYPES,
    HEADER,
)
from camlab88.apps.ca.rules import OP_ADD, OP_AND, OP_OR, OP_XOR, RuleSet
from camlab88.apps.ca.tables import compile_rules


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


