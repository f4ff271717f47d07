"""numba kernels for one generation of the message-passing automaton (thesis section 7.5).

Two interchangeable kernels give identical results:

* ``step_window`` uses a dense message workspace covering only the live cells' bounding box
  plus the message reach (the thesis's row workspace, widened to the whole box because a
  few megabytes are cheap today);
* ``step_hash`` uses an open-addressing hash table keyed by the packed cell position, so work
  and memory follow the live cells and their reach even when they are scattered over the
  whole 65536 x 65536 plane.

Messages are applied in the thesis's order: senders row by row, left to right, each sender's
grid row by row; so mixed operations (+ then |, ...) give the same result in both kernels.
"""

from __future__ import annotations

import types

import numpy as np
from numba import njit

from camlab88.base.kernel_notice import announce_compiles

# one line on stderr when a cold cache compiles (measured ~7 s)
announce_compiles("cellular automaton", 7.0, __name__)

SIDE = 65536
MASK = 0xFFFF
LOOKUP_SIZE = 1 << 16
M32 = 0xFFFFFFFF


@njit(cache=True, inline="always")
def _apply(cur: int, op: int, val: int) -> int:
    if op == 1:
        return (cur + val) & M32
    if op == 2:
        return cur | val
    if op == 3:
        return cur & val
    return cur ^ val


@njit(cache=True, inline="always")
def _mix64(z: np.uint64) -> np.uint64:
    z = (z ^ (z >> np.uint64(30))) * np.uint64(0xBF58476D1CE4E5B9)
    z = (z ^ (z >> np.uint64(27))) * np.uint64(0x94D049BB133111EB)
    return z ^ (z >> np.uint64(31))


@njit(cache=True)
def rand32(seed: int, x: int, y: int, gen: int) -> int:
    """Reproducible 32-bit random number from seed, cell position and generation."""
    z = _mix64(np.uint64(seed) + np.uint64(0x9E3779B97F4A7C15))
    z = _mix64(z ^ (np.uint64(y) << np.uint64(16) | np.uint64(x)))
    z = _mix64(z ^ np.uint64(gen))
    return int(z >> np.uint64(32))


@njit(cache=True)
def _slow_match(v, kind, a, b) -> int:
    """First matching interpretation line for a value beyond the lookup table."""
    for j in range(kind.shape[0]):
        if kind[j] == 0:
            hit = v == a[j]
        elif kind[j] == 1:
            hit = (v & a[j]) == b[j]
        else:
            hit = a[j] <= v <= b[j]
        if hit:
            return j
    return -1


@njit(cache=True)
def _choose(i, x, y, gen, seed, out_start, thresh, forms) -> int:
    """Life-form of outcome ``i`` (random choice if it has several)."""
    s = out_start[i]
    e = out_start[i + 1]
    r = rand32(seed, x, y, gen)
    for j in range(s, e):
        if r < thresh[j]:
            return forms[j]
    return forms[e - 1]


@njit(cache=True)
def broadcasts(ts, bcast_op, bcast_val):
    """The broadcast operations of this generation, in sender order, runs of one op merged."""
    ops = np.empty(ts.shape[0], np.int64)
    vals = np.empty(ts.shape[0], np.int64)
    n = 0
    for i in range(ts.shape[0]):
        t = ts[i]
        if t >= bcast_op.shape[0]:
            continue
        op = bcast_op[t]
        if op == 0:
            continue
        v = bcast_val[t]
        if n > 0 and ops[n - 1] == op:
            vals[n - 1] = _apply(vals[n - 1], op, v)  # same op composes into one
        else:
            ops[n] = op
            vals[n] = v
            n += 1
    return ops[:n], vals[:n]


@njit(cache=True)
def step_window(ys, xs, ts, wy0, wx0, h, w, start, sdy, sdx, sop, sval, bops, bvals,
                lookup, kind, a, b, out_start, thresh, forms, gen, seed, cap):
    """One generation with a dense workspace over rows wy0..wy0+h-1, columns wx0..wx0+w-1.

    Messages landing outside the window are dropped: the caller makes the window the
    intersection of the reach box, the plane and the advance area.
    """
    msg = np.zeros((h, w), np.uint32)
    recv = np.zeros((h, w), np.uint8)
    ntypes = start.shape[0] - 1
    for i in range(ys.shape[0]):
        t = ts[i]
        if t >= ntypes:
            continue
        y = ys[i] - wy0
        x = xs[i] - wx0
        for k in range(start[t], start[t + 1]):
            ty = y + sdy[k]
            tx = x + sdx[k]
            if 0 <= ty < h and 0 <= tx < w:
                msg[ty, tx] = _apply(np.int64(msg[ty, tx]), sop[k], sval[k])
                recv[ty, tx] = 1
    oy = np.empty(cap, np.int64)
    ox = np.empty(cap, np.int64)
    ot = np.empty(cap, np.int64)
    n = 0
    nb = bops.shape[0]
    for r in range(h):
        for c in range(w):
            if recv[r, c] == 0:
                continue
            v = np.int64(msg[r, c])
            for j in range(nb):
                v = _apply(v, bops[j], bvals[j])
            i = lookup[v] if v < LOOKUP_SIZE else _slow_match(v, kind, a, b)
            if i < 0:
                continue
            s = out_start[i]
            if out_start[i + 1] - s == 1:
                t = forms[s]
            else:
                t = _choose(i, c + wx0, r + wy0, gen, seed, out_start, thresh, forms)
            if t > 0:
                oy[n] = r + wy0
                ox[n] = c + wx0
                ot[n] = t
                n += 1
    return oy[:n], ox[:n], ot[:n]


@njit(cache=True)
def step_hash(ys, xs, ts, wrap, cy0, cy1, cx0, cx1, start, sdy, sdx, sop, sval, bops, bvals,
              lookup, kind, a, b, out_start, thresh, forms, gen, seed, table, order):
    """One generation with a hash-table workspace; messages outside [cy0..cy1]x[cx0..cx1]
    (the advance area, or the plane) are dropped; with ``wrap`` positions wrap at 65536.

    ``table`` (cap x 2, key -1 = empty, cap a power of two >= twice the messages sent) and
    ``order`` (cap) are scratch space kept by the caller; used slots are emptied again on
    return, so no per-generation clearing of the whole table is needed."""
    cap = table.shape[0]
    bits = 0
    while (1 << bits) < cap:
        bits += 1
    shift = np.uint64(64 - bits)
    hmask = cap - 1
    # key and value side by side (one cache line); slots keep a row's cells together
    # (row hashed, column added) because senders arrive row by row.
    used = 0
    ntypes = start.shape[0] - 1
    for i in range(ys.shape[0]):
        t = ts[i]
        if t >= ntypes:
            continue
        for k in range(start[t], start[t + 1]):
            ty = ys[i] + sdy[k]
            tx = xs[i] + sdx[k]
            if wrap:
                ty &= MASK
                tx &= MASK
            if ty < cy0 or ty > cy1 or tx < cx0 or tx > cx1:
                continue
            key = ty * SIDE + tx
            base = np.int64((np.uint64(ty) * np.uint64(0x9E3779B97F4A7C15)) >> shift)
            slot = (base + tx) & hmask
            while table[slot, 0] != -1 and table[slot, 0] != key:
                slot = (slot + 1) & hmask
            if table[slot, 0] == -1:
                table[slot, 0] = key
                table[slot, 1] = 0
                order[used] = slot
                used += 1
            table[slot, 1] = _apply(table[slot, 1], sop[k], sval[k])
    okey = np.empty(used, np.int64)
    ot = np.empty(used, np.int64)
    n = 0
    nb = bops.shape[0]
    for u in range(used):
        slot = order[u]
        key = table[slot, 0]
        v = table[slot, 1]
        for j in range(nb):
            v = _apply(v, bops[j], bvals[j])
        y = key // SIDE
        x = key - y * SIDE
        i = lookup[v] if v < LOOKUP_SIZE else _slow_match(v, kind, a, b)
        if i < 0:
            continue
        s = out_start[i]
        if out_start[i + 1] - s == 1:
            t = forms[s]
        else:
            t = _choose(i, x, y, gen, seed, out_start, thresh, forms)
        if t > 0:
            okey[n] = key
            ot[n] = t
            n += 1
    for u in range(used):
        table[order[u], 0] = -1
    okey = okey[:n]
    ot = ot[:n]
    idx = np.argsort(okey)
    okey = okey[idx]
    oy = okey // SIDE
    ox = okey - oy * SIDE
    return oy, ox, ot[idx]


# -- the dense path: one compiled family per message dtype ---------------------------------
# The dense kernels take the message workspace in the plan's dtype (uint8 or uint16). A numba
# kernel compiled for two dtypes keeps both signatures in one on-disk cache index, which two
# processes compiling at once can mix up (docs/development.md, "numba's cache"). So the plain
# functions below are compiled once per dtype under their own names ("dense_step_u8", ...),
# each family calling its own helpers, and every compiled kernel has one signature.
_DENSE_PY: dict[str, object] = {}  # name -> plain function, callees before callers


def _dense_kernel(fn):  # registers a plain function for the families
    _DENSE_PY[fn.__name__] = fn
    return fn


@_dense_kernel
def _acc_add(acc, src, t, v):
    for i in range(acc.shape[0]):
        acc[i] += v * (src[i] == t)


@_dense_kernel
def _acc_or(acc, src, t, v):
    for i in range(acc.shape[0]):
        acc[i] |= v * (src[i] == t)


@_dense_kernel
def _acc_xor(acc, src, t, v):
    for i in range(acc.shape[0]):
        acc[i] ^= v * (src[i] == t)


@_dense_kernel
def _dense_step(T, out, etype, edy, edx, eop, evals, lut, acc):
    """The dense fast path fused row by row (the section 7.5 workspace idea): each target
    row's messages gather in a one-row buffer that stays in cache, then are interpreted at
    once.  Same result as dense_messages + dense_interpret; returns the population."""
    h, w = T.shape
    n = 0
    for r in range(h):
        acc[:] = 0
        for e in range(etype.shape[0]):
            sr = r - edy[e]
            if sr < 0 or sr >= h:
                continue
            dx = edx[e]
            c0 = max(0, dx)
            c1 = min(w, w + dx)
            dst = acc[c0:c1]
            src = T[sr, c0 - dx:c1 - dx]
            t = np.uint8(etype[e])
            op = eop[e]
            if op == 1:
                _acc_add(dst, src, t, evals[e])
            elif op == 2:
                _acc_or(dst, src, t, evals[e])
            else:
                _acc_xor(dst, src, t, evals[e])
        orow = out[r]
        for c in range(w):
            k = lut[acc[c]]
            orow[c] = k
            n += k != 0
    return n


# -- the separable dense path ------------------------------------------------------------
# Additions of one value from one sender life-form to a rectangle of offsets (less a few
# cells) are a box sum of the indicator grid (T == type): per source row a horizontal sum,
# kept in a small ring, and per target row a running vertical sum (add the row entering the
# box, subtract the one leaving); the offsets missing from the rectangle are subtracted.
# Exact in the message dtype's modular arithmetic, because the true sum fits in it.


@_dense_kernel
def _group_row(T, sr, t, v, gx1, width, ind, hrow):
    """Indicator of source row ``sr`` padded so ind[j] = (T[sr, j - gx1] == t) (0 off the
    grid), and its horizontal box sum times v: hrow[c] = v * sum(ind[c:c + width])."""
    w = T.shape[1]
    # ind[j] holds source column j - gx1: those inside the grid are j in lo..hi-1.
    lo = max(0, gx1)
    hi = min(ind.shape[0], gx1 + w)
    ind[:lo] = 0
    ind[hi:] = 0
    src = T[sr, lo - gx1:hi - gx1]
    dst = ind[lo:hi]
    for c in range(hi - lo):  # (a bool store here does not vectorise)
        dst[c] = np.uint8(1) if src[c] == t else np.uint8(0)
    for c in range(w):
        hrow[c] = ind[c]
    for k in range(1, width):
        part = ind[k:k + w]
        for c in range(w):
            hrow[c] += part[c]
    if v != 1:
        for c in range(w):
            hrow[c] *= v


@_dense_kernel
def _add_row(dst, src):
    for c in range(dst.shape[0]):
        dst[c] += src[c]


@_dense_kernel
def _sub_row(dst, src):
    for c in range(dst.shape[0]):
        dst[c] -= src[c]


@_dense_kernel
def _sub_scaled(dst, src, v):
    for c in range(dst.shape[0]):
        dst[c] -= v * src[c]


@_dense_kernel
def _interp_lut(acc, orow, lut):
    for c in range(acc.shape[0]):
        orow[c] = lut[acc[c]]


@_dense_kernel
def _interp_mask32(acc, orow, masks, forms):
    """Next life-form from bit sets (bit v of masks[j] set: value v gives forms[j]); only
    used when every reachable value is below 32, so the shift is defined; vectorises,
    unlike a table lookup."""
    orow[:] = 0
    for j in range(masks.shape[0]):
        m = masks[j]
        f = forms[j]
        for c in range(acc.shape[0]):
            orow[c] += np.uint8((m >> np.uint32(acc[c])) & np.uint32(1)) * f


@_dense_kernel
def _interp_mask64(acc, orow, masks, forms):
    """As _interp_mask32 for values below 64."""
    orow[:] = 0
    for j in range(masks.shape[0]):
        m = masks[j]
        f = forms[j]
        for c in range(acc.shape[0]):
            orow[c] += np.uint8((m >> np.uint64(acc[c])) & np.uint64(1)) * f


@_dense_kernel
def _dense_step_separable(T, out, gtype, gval, gy0, gy1, gx0, gx1, xg, xdy, xdx,
                         etype, edy, edx, eop, evals, interp, lut, masks32, masks64, mforms,
                         acc, ind, hring, vsum):
    """One dense generation; the same result as dense_step on the full entry list.

    Groups g (sender type gtype[g], value gval[g], offsets rows gy0..gy1, columns gx0..gx1,
    less the excluded offsets (xdy, xdx) of group xg) are box sums; the remaining entries
    (adds first) use dense_step's one pass per entry.  Scratch: acc[w];
    ind[G, R, w + gx1 - gx0], hring[G, R, w], vsum[G, w] with R >= box height + 1.
    interp: 0 table lookup, 1 / 2 bit sets of 32 / 64 bits.  Returns the population."""
    h, w = T.shape
    ng = gtype.shape[0]
    R = hring.shape[1]
    for g in range(ng):
        vsum[g, :] = 0
        t = np.uint8(gtype[g])
        width = gx1[g] - gx0[g] + 1
        for sr in range(-gy1[g], -gy0[g]):  # rows already in the box above row 0
            if 0 <= sr < h:
                s = sr % R
                _group_row(T, sr, t, gval[g], gx1[g], width, ind[g, s], hring[g, s])
                vsum[g] += hring[g, s]
    n = 0
    for r in range(h):
        for g in range(ng):
            sr = r - gy0[g]
            vs = vsum[g]
            if 0 <= sr < h:
                s = sr % R
                _group_row(T, sr, np.uint8(gtype[g]), gval[g], gx1[g], gx1[g] - gx0[g] + 1,
                           ind[g, s], hring[g, s])
                _add_row(vs, hring[g, s])
            sr = r - gy1[g] - 1
            if 0 <= sr < h:
                _sub_row(vs, hring[g, sr % R])
        if ng > 0:
            acc[:] = vsum[0]
            for g in range(1, ng):
                _add_row(acc, vsum[g])
        else:
            acc[:] = 0
        for x in range(xg.shape[0]):
            g = xg[x]
            sr = r - xdy[x]
            if sr < 0 or sr >= h:
                continue
            j = gx1[g] - xdx[x]
            _sub_scaled(acc, ind[g, sr % R, j:j + w], gval[g])
        # The same per-entry passes as _dense_step, written out again: moved into a shared
        # helper kernel they measured about 25% slower (numba does not inline it), and
        # about 10% slower even as an inline="always" helper of the family (both dense
        # steps, Life on a 1200x1200 soup, 60 generations, best of 7).
        for e in range(etype.shape[0]):  # (additions first: see tables.SeparablePlan)
            sr = r - edy[e]
            if sr < 0 or sr >= h:
                continue
            dx = edx[e]
            c0 = max(0, dx)
            c1 = min(w, w + dx)
            dst = acc[c0:c1]
            src = T[sr, c0 - dx:c1 - dx]
            t = np.uint8(etype[e])
            op = eop[e]
            if op == 1:
                _acc_add(dst, src, t, evals[e])
            elif op == 2:
                _acc_or(dst, src, t, evals[e])
            else:
                _acc_xor(dst, src, t, evals[e])
        orow = out[r]
        if interp == 1:
            _interp_mask32(acc, orow, masks32, mforms)
        elif interp == 2:
            _interp_mask64(acc, orow, masks64, mforms)
        else:
            _interp_lut(acc, orow, lut)
        for c in range(w):
            n += orow[c] != 0
    return n


def _family(suffix: str, message: str) -> dict[str, object]:
    """The dense kernels compiled under names ending in ``suffix``, calling each other, for
    message workspaces of dtype ``message``."""
    namespace = dict(globals())
    family = {}
    for name, fn in _DENSE_PY.items():
        f = types.FunctionType(fn.__code__, namespace, f"{name}_{suffix}", fn.__defaults__,
                               fn.__closure__)
        f.__qualname__ = f"{fn.__qualname__}_{suffix}"  # numba names its cache files by it
        f.__module__ = fn.__module__
        f.__doc__ = fn.__doc__
        family[name] = namespace[name] = njit(cache=True)(f)
    return family


DENSE_FAMILIES = {np.dtype(np.uint8): _family("u8", "uint8"),
                  np.dtype(np.uint16): _family("u16", "uint16")}


def dense_step(T, out, etype, edy, edx, eop, evals, lut, acc):
    """The dense fast path, one pass per message entry (see the plain definition above),
    compiled for the workspace dtype ``acc.dtype``; returns the population."""
    return DENSE_FAMILIES[acc.dtype]["_dense_step"](T, out, etype, edy, edx, eop, evals, lut,
                                                   acc)


def dense_step_separable(*args):
    """The separable dense path (arguments as in the plain definition above), compiled for
    the workspace dtype (``acc``, argument 22); returns the population."""
    return DENSE_FAMILIES[args[21].dtype]["_dense_step_separable"](*args)
