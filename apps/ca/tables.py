"""A :class:`RuleSet` compiled into flat numpy tables for the numba kernels."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from camlab88.apps.ca.rules import MATCH_EXACT, MATCH_PATTERN, MATCH_RANGE, RuleSet

LOOKUP_SIZE = 1 << 16  # message values below this are interpreted by one table lookup
ONE = 1 << 32  # probabilities are thresholds on a 32-bit random number


@dataclass(frozen=True)
class RuleTables:
    send_start: np.ndarray  # int64[T+2]: messages of type t are send_*[start[t]:start[t+1]]
    send_dy: np.ndarray  # int64
    send_dx: np.ndarray  # int64
    send_op: np.ndarray  # int64 (rules.OP_*)
    send_val: np.ndarray  # uint32 as int64
    bcast_op: np.ndarray  # int64[T+1], 0 = this type does not broadcast
    bcast_val: np.ndarray  # int64[T+1]
    interp_kind: np.ndarray  # int64[I]
    interp_a: np.ndarray  # int64[I]
    interp_b: np.ndarray  # int64[I]
    interp_out: np.ndarray  # int64[I] index into outcomes
    lookup: np.ndarray  # int64[LOOKUP_SIZE] outcome index of small values, -1 = dies
    out_start: np.ndarray  # int64[O+1]
    out_thresh: np.ndarray  # int64: choose the first choice whose threshold exceeds r32
    out_form: np.ndarray  # int64
    reach_y: int
    reach_x: int
    sends_per_cell: int
    max_form: int
    dense: DensePlan | None = None


@dataclass(frozen=True)
class DensePlan:
    """How to run the rules as dense grid passes, when that gives the same result.

    Eligible when every message operation commutes with every other one a cell can receive:
    only one kind of operation, or additions whose largest possible sum stays below every
    bit set by the ORs (or XORs); deterministic outcomes; no broadcasts; a cell whose message
    area is 0 dies anyway (so "received nothing" needs no separate mark); life-forms and
    message values small enough for uint8/uint16 grids.
    """

    etype: np.ndarray  # int64: sender life-form of each message entry
    edy: np.ndarray
    edx: np.ndarray
    eop: np.ndarray
    evals: np.ndarray  # message dtype
    lut: np.ndarray  # uint8: message value -> next life-form
    msg_dtype: type
    sep: SeparablePlan | None = None


@dataclass(frozen=True)
class SeparablePlan:
    """The same messages arranged for kernels.dense_step_separable: additions of one value
    from one life-form over a rectangle of offsets less a few cells become box sums
    (groups); the other entries stay one pass each, additions first (the plan only exists
    when all operations commute, so the order is free)."""

    gtype: np.ndarray  # int64[G]
    gval: np.ndarray  # msg dtype
    gy0: np.ndarray  # int64[G]: offset rectangle rows gy0..gy1, columns gx0..gx1
    gy1: np.ndarray
    gx0: np.ndarray
    gx1: np.ndarray
    xg: np.ndarray  # int64: group of each offset missing from its rectangle
    xdy: np.ndarray
    xdx: np.ndarray
    etype: np.ndarray  # the remaining entries
    edy: np.ndarray
    edx: np.ndarray
    eop: np.ndarray
    evals: np.ndarray
    interp: int  # 0: lut; 1 / 2: bit sets masks32 / masks64 (every value below 32 / 64)
    masks32: np.ndarray
    masks64: np.ndarray
    mforms: np.ndarray  # uint8: life-form of each bit set
    ring: int  # rows kept per group: the tallest rectangle plus one


def compile_rules(rules: RuleSet) -> RuleTables:
    cached = rules._tables.get("tables")
    if cached is not None:
        return cached
    top = rules.max_form
    start = np.zeros(top + 2, np.int64)
    dy: list[int] = []
    dx: list[int] = []
    op: list[int] = []
    val: list[int] = []
    bop = np.zeros(top + 1, np.int64)
    bval = np.zeros(top + 1, np.int64)
    most = 0
    for t in range(1, top + 1):
        start[t] = len(dy)
        form = rules.forms.get(t)
        if form is not None:
            # Grid order (row by row) is the order the thesis's row workspace applies them.
            for m in form.messages:
                dy.append(m.dy)
                dx.append(m.dx)
                op.append(m.op)
                val.append(m.value)
            most = max(most, len(form.messages))
            if form.broadcast is not None:
                bop[t], bval[t] = form.broadcast
    start[top + 1] = len(dy)
    start[0] = 0

    # Outcomes: one per interpretation line, thresholds exact on a 2**32 scale.
    out_start = [0]
    thresh: list[int] = []
    forms: list[int] = []
    for it in rules.interpretations:
        choices = it.outcome.choices
        if len(choices) == 1:  # deterministic (most lines): no arithmetic on Fractions
            thresh.append(ONE)
            forms.append(choices[0][1])
        else:
            acc = 0
            for p, lf in choices:
                acc += p
                thresh.append(min(ONE, int(acc * ONE)))
                forms.append(lf)
            thresh[-1] = ONE
        out_start.append(len(thresh))
    kind = np.array([it.kind for it in rules.interpretations], np.int64)
    a = np.array([it.a for it in rules.interpretations], np.int64)
    b = np.array([it.b for it in rules.interpretations], np.int64)

    lookup = _lookup(rules)
    ry, rx = rules.reach
    plan = _dense_plan(rules, top, lookup, out_start, forms)
    tables = RuleTables(
        send_start=start,
        send_dy=np.array(dy, np.int64),
        send_dx=np.array(dx, np.int64),
        send_op=np.array(op, np.int64),
        send_val=np.array(val, np.int64),
        bcast_op=bop,
        bcast_val=bval,
        interp_kind=kind,
        interp_a=a,
        interp_b=b,
        interp_out=np.arange(len(kind), dtype=np.int64),
        lookup=lookup,
        out_start=np.array(out_start, np.int64),
        out_thresh=np.array(thresh, np.int64),
        out_form=np.array(forms, np.int64),
        reach_y=ry,
        reach_x=rx,
        sends_per_cell=max(1, most),
        max_form=top,
        dense=plan,
    )
    rules._tables["tables"] = tables
    return tables


def _lookup(rules: RuleSet) -> np.ndarray:
    """The first matching line for every value below LOOKUP_SIZE (-1: none): lines applied
    last to first so earlier ones win; a value or a range is one store or slice (a rule
    table of a thousand exact values, Langton's loops, takes a millisecond, not 40)."""
    lookup = np.full(LOOKUP_SIZE, -1, np.int64)
    values = None
    for i in range(len(rules.interpretations) - 1, -1, -1):
        it = rules.interpretations[i]
        if it.kind == MATCH_EXACT:
            if it.a < LOOKUP_SIZE:
                lookup[it.a] = i
        elif it.kind == MATCH_PATTERN:
            if values is None:
                values = np.arange(LOOKUP_SIZE, dtype=np.int64)
            lookup[(values & it.a) == it.b] = i
        else:
            assert it.kind == MATCH_RANGE
            if it.a < LOOKUP_SIZE:
                lookup[it.a:min(it.b, LOOKUP_SIZE - 1) + 1] = i
    return lookup


def _dense_plan(rules: RuleSet, top: int, lookup: np.ndarray, out_start: list[int],
                forms: list[int]) -> DensePlan | None:
    from camlab88.apps.ca.rules import OP_ADD, OP_OR, OP_XOR

    if top > 255 or any(f.broadcast for f in rules.forms.values()):
        return None
    if any(len(it.outcome.choices) != 1 for it in rules.interpretations):
        return None
    entries = [(t, m) for t, f in sorted(rules.forms.items()) for m in f.messages]
    ops = {m.op for _, m in entries}
    if not ops <= {OP_ADD, OP_OR, OP_XOR} or {OP_OR, OP_XOR} <= ops:
        return None
    per_offset: dict[tuple[int, int], int] = {}
    bits = 0
    for _, m in entries:
        if m.op == OP_ADD:
            per_offset[(m.dy, m.dx)] = max(per_offset.get((m.dy, m.dx), 0), m.value)
        else:
            bits |= m.value
    add_max = sum(per_offset.values())
    low = (1 << add_max.bit_length()) - 1  # every value the additions can make
    if bits & low:
        return None  # an OR/XOR bit could meet a carry: order would matter
    bound = low | bits
    if bound >= 1 << 16:
        return None
    dtype = np.uint8 if bound < 256 else np.uint16
    size = 256 if dtype is np.uint8 else 1 << 16
    lut = np.zeros(size, np.uint8)
    hit = lookup[:size] >= 0
    lut[hit] = np.array(forms, np.int64)[np.array(out_start, np.int64)[lookup[:size][hit]]]
    if lut[0] != 0:
        return None  # a cell that received nothing must die
    return DensePlan(
        **_entry_arrays(entries, dtype),
        lut=lut,
        msg_dtype=dtype,
        sep=_separable_plan(entries, dtype, lut, bound),
    )


def _entry_arrays(entries: list, dtype: type) -> dict[str, np.ndarray]:
    """The (type, message) entries as the kernels' parallel arrays, values in ``dtype``."""
    return {"etype": np.array([t for t, _ in entries], np.int64),
            "edy": np.array([m.dy for _, m in entries], np.int64),
            "edx": np.array([m.dx for _, m in entries], np.int64),
            "eop": np.array([m.op for _, m in entries], np.int64),
            "evals": np.array([m.value for _, m in entries], dtype)}


# Bit-set interpretation is used for at most this many distinct next life-forms.
MASK_FORMS_MAX = 4
# A group of additions becomes a box sum when this many times its passes per row is still
# fewer than its offsets (0: whenever possible, which the tests use).
GROUP_COST_FACTOR = 2


def _separable_plan(entries: list, dtype: type, lut: np.ndarray, bound: int) -> SeparablePlan:
    from camlab88.apps.ca.rules import OP_ADD

    groups: dict[tuple[int, int], set[tuple[int, int]]] = {}
    for t, m in entries:
        if m.op == OP_ADD:
            groups.setdefault((t, m.value), set()).add((m.dy, m.dx))
    g_rows: list[tuple[int, int, int, int, int, int]] = []
    excluded: list[tuple[int, int, int]] = []
    grouped: set[tuple[int, int, int, int]] = set()
    for (t, v), offs in sorted(groups.items()):
        ys = [dy for dy, _ in offs]
        xs = [dx for _, dx in offs]
        y0, y1, x0, x1 = min(ys), max(ys), min(xs), max(xs)
        missing = [(dy, dx) for dy in range(y0, y1 + 1) for dx in range(x0, x1 + 1)
                   if (dy, dx) not in offs]
        # Passes per row: indicator + box width (horizontal sum) + 2 (running vertical sum)
        # + 1 per missing cell, against one pass per offset the ordinary way; the box passes
        # cost more than a plain one (measured: Life's 3 x 3 less its centre is slower as a
        # box sum than as 8 passes), hence the factor.
        if GROUP_COST_FACTOR * ((x1 - x0 + 1) + 3 + len(missing)) >= len(offs):
            continue
        g = len(g_rows)
        g_rows.append((t, v, y0, y1, x0, x1))
        excluded += [(g, dy, dx) for dy, dx in missing]
        grouped |= {(t, v, dy, dx) for dy, dx in offs}
    rest = [(t, m) for t, m in entries
            if m.op != OP_ADD or (t, m.value, m.dy, m.dx) not in grouped]
    rest.sort(key=lambda e: e[1].op != OP_ADD)  # additions first (stable otherwise)
    present = np.flatnonzero(np.bincount(lut[:bound + 1]))  # sorted distinct life-forms
    forms = [int(f) for f in present if f != 0]
    interp = 0
    if len(forms) <= MASK_FORMS_MAX and bound < 64:
        interp = 1 if bound < 32 else 2
    bitsets = [sum(1 << int(v) for v in np.flatnonzero(lut[:bound + 1] == f))
               for f in forms] if interp else []
    col = list(zip(*g_rows)) if g_rows else [()] * 6
    return SeparablePlan(
        gtype=np.array(col[0], np.int64),
        gval=np.array(col[1], dtype),
        gy0=np.array(col[2], np.int64),
        gy1=np.array(col[3], np.int64),
        gx0=np.array(col[4], np.int64),
        gx1=np.array(col[5], np.int64),
        xg=np.array([g for g, _, _ in excluded], np.int64),
        xdy=np.array([dy for _, dy, _ in excluded], np.int64),
        xdx=np.array([dx for _, _, dx in excluded], np.int64),
        **_entry_arrays(rest, dtype),
        interp=interp,
        masks32=np.array(bitsets if interp == 1 else [], np.uint32),
        masks64=np.array(bitsets if interp == 2 else [], np.uint64),
        mforms=np.array(forms if interp else [], np.uint8),
        ring=max([y1 - y0 + 2 for _, _, y0, y1, _, _ in g_rows], default=1),
    )
