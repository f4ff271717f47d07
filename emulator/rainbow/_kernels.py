"""Compiled inner loops (numba) of the band-structure compiler and the video processor.

Kept apart from the Python-level logic so the rules they implement can be read in
compiler.py / video.py and the per-pixel reference without wading through loops.

Imported where a kernel is first called (compiler.py, video.py), not at their import: so
importing emulator.rainbow (any command module that names a Rainbow type) does not import
numba, about 0.15-0.2 s, nor load a kernel from the cache (another 0.2 s).
"""

from __future__ import annotations

import numpy as np
from numba import njit

from camlab88.base.kernel_notice import announce_compiles

announce_compiles("Rainbow", 4.0, __name__,  # cold compile time, measured
                  completion="camlab88.emulator.rainbow.kernel_warmup:compile_kernels")


# Columns of the instance table handed to the compiler kernel.
I_Y0, I_Y1, I_X0, I_X1, I_OX, I_OY, I_RANK, I_PAD, I_MX, I_MY, I_PLANE, I_DEPTH, I_PAGE = range(13)
INSTANCE_COLUMNS = 13


# Cold-compile cost matters here (every Rainbow command's first run compiles this module):
# the loops below stand in for numpy calls numba compiles slowly. A slice assignment
# (``b[:n] = a``) drags in its broadcast check's error-message formatting, ~3.5 s of
# compile; np.unique drags in numba's generic quicksort, ~1.5 s (docs/perf/startup.md).
@njit(cache=True)
def _grow(a, need):
    if need <= a.shape[0]:
        return a
    b = np.empty((max(need, 2 * a.shape[0]), a.shape[1]), a.dtype)
    for i in range(a.shape[0]):
        for c in range(a.shape[1]):
            b[i, c] = a[i, c]
    return b


@njit(cache=True)
def _unique(a):
    """np.unique of a 1-D array (sorted distinct values), sorting ``a`` in place (heapsort)."""
    n = a.shape[0]
    end = n
    start = n // 2
    while end > 1:
        if start > 0:
            start -= 1  # building the heap
        else:
            end -= 1  # taking its greatest to the end
            tmp = a[0]
            a[0] = a[end]
            a[end] = tmp
        root = start
        while True:
            child = 2 * root + 1
            if child >= end:
                break
            if child + 1 < end and a[child] < a[child + 1]:
                child += 1
            if a[root] >= a[child]:
                break
            tmp = a[root]
            a[root] = a[child]
            a[child] = tmp
            root = child
    m = 0
    for p in range(n):
        if m == 0 or a[p] != a[m - 1]:
            a[m] = a[p]
            m += 1
    return a[:m]


@njit(cache=True)
def _less(a, i, j):
    for c in range(a.shape[1]):
        if a[i, c] != a[j, c]:
            return a[i, c] < a[j, c]
    return False


# An explicit signature: compile_rows first types ``nc`` as the literal 0, and a second
# (literal) signature in the on-disk cache can be mixed up with this one by two processes
# compiling at once (docs/development.md, "numba's cache").
@njit("int64(int64[:, ::1], int64)", cache=True)
def _sort_unique(cand, nc):
    """Sort the first nc rows lexicographically and drop repeats: a canonical tie order."""
    for p in range(1, nc):
        q = p
        while q > 0 and _less(cand, q, q - 1):
            for c in range(cand.shape[1]):
                tmp = cand[q, c]
                cand[q, c] = cand[q - 1, c]
                cand[q - 1, c] = tmp
            q -= 1
    m = 0
    for p in range(nc):
        if m > 0 and not _less(cand, m - 1, p):
            continue  # equal to the last kept row (sorted, so not less means equal)
        for c in range(cand.shape[1]):
            cand[m, c] = cand[p, c]
        m += 1
    return m


@njit(cache=True)
def compile_rows(ya, yb, width, inst):
    """Band structure for screen rows ya..yb-1 from the instance table (see bands.py)."""
    n = inst.shape[0]
    sel = np.empty(n, np.int64)
    ns = 0
    for i in range(n):
        if inst[i, I_Y0] < yb and inst[i, I_Y1] > ya:
            sel[ns] = i
            ns += 1
    ye = np.empty(2 * ns + 2, np.int64)
    ye[0] = ya
    ye[1] = yb
    k = 2
    for j in range(ns):
        i = sel[j]
        ye[k] = min(max(inst[i, I_Y0], ya), yb)
        ye[k + 1] = min(max(inst[i, I_Y1], ya), yb)
        k += 2
    ye = _unique(ye)

    bands = np.empty((16, 4), np.int64)
    spans = np.empty((64, 5), np.int64)
    srcs = np.empty((64, 5), np.int64)
    nb = 0
    nsp = 0
    nsr = 0
    active = np.empty(ns, np.int64)
    tie = np.empty(ns, np.int64)
    cand = np.empty((ns, 5), np.int64)
    for e in range(ye.shape[0] - 1):
        y0 = ye[e]
        y1 = ye[e + 1]
        na = 0
        for j in range(ns):
            i = sel[j]
            if inst[i, I_Y0] <= y0 and inst[i, I_Y1] >= y1:
                active[na] = i
                na += 1
        xe = np.empty(2 * na + 2, np.int64)
        xe[0] = 0
        xe[1] = width
        for j in range(na):
            xe[2 + 2 * j] = inst[active[j], I_X0]
            xe[3 + 2 * j] = inst[active[j], I_X1]
        xe = _unique(xe)
        band_s0 = nsp
        band_r0 = nsr
        for g in range(xe.shape[0] - 1):
            x0 = xe[g]
            x1 = xe[g + 1]
            best = -1
            nt = 0
            for j in range(na):
                i = active[j]
                if inst[i, I_X0] <= x0 and inst[i, I_X1] >= x1:
                    r = inst[i, I_RANK]
                    if r > best:
                        best = r
                        nt = 0
                    if r == best:
                        tie[nt] = i
                        nt += 1
            page = 0
            nc = 0
            for t in range(nt):
                i = tie[t]
                if inst[i, I_PAGE] > page:
                    page = inst[i, I_PAGE]
                if inst[i, I_DEPTH] == 0:
                    continue
                cand[nc, 0] = inst[i, I_PAD]
                cand[nc, 1] = inst[i, I_MX] + x0 - inst[i, I_OX]
                cand[nc, 2] = inst[i, I_MY] + y0 - inst[i, I_OY]
                cand[nc, 3] = inst[i, I_PLANE]
                cand[nc, 4] = inst[i, I_DEPTH]
                nc += 1
            nc = _sort_unique(cand, nc)
            # merge with the previous span of this band if it continues it
            merged = False
            if nsp > band_s0:
                ps = nsp - 1
                if spans[ps, 2] == page and spans[ps, 4] - spans[ps, 3] == nc:
                    w = spans[ps, 1] - spans[ps, 0]
                    ok = True
                    for c in range(nc):
                        r = spans[ps, 3] + c
                        if (srcs[r, 0] != cand[c, 0] or srcs[r, 1] + w != cand[c, 1]
                                or srcs[r, 2] != cand[c, 2] or srcs[r, 3] != cand[c, 3]
                                or srcs[r, 4] != cand[c, 4]):
                            ok = False
                            break
                    if ok:
                        spans[ps, 1] = x1
                        merged = True
            if not merged:
                spans = _grow(spans, nsp + 1)
                srcs = _grow(srcs, nsr + nc)
                spans[nsp, 0] = x0
                spans[nsp, 1] = x1
                spans[nsp, 2] = page
                spans[nsp, 3] = nsr
                spans[nsp, 4] = nsr + nc
                for c in range(nc):
                    for f in range(5):
                        srcs[nsr + c, f] = cand[c, f]
                nsr += nc
                nsp += 1
        # merge with the previous band if every span continues it one row further down
        merged = False
        if nb > 0:
            pb = nb - 1
            h = bands[pb, 1] - bands[pb, 0]
            if bands[pb, 3] - bands[pb, 2] == nsp - band_s0:
                ok = True
                for q in range(nsp - band_s0):
                    a = bands[pb, 2] + q
                    b = band_s0 + q
                    if (spans[a, 0] != spans[b, 0] or spans[a, 1] != spans[b, 1]
                            or spans[a, 2] != spans[b, 2]
                            or spans[a, 4] - spans[a, 3] != spans[b, 4] - spans[b, 3]):
                        ok = False
                        break
                    for c in range(spans[b, 4] - spans[b, 3]):
                        ra = spans[a, 3] + c
                        rb = spans[b, 3] + c
                        if (srcs[ra, 0] != srcs[rb, 0] or srcs[ra, 1] != srcs[rb, 1]
                                or srcs[ra, 2] + h != srcs[rb, 2]
                                or srcs[ra, 3] != srcs[rb, 3] or srcs[ra, 4] != srcs[rb, 4]):
                            ok = False
                            break
                    if not ok:
                        break
                if ok:
                    bands[pb, 1] = y1
                    nsp = band_s0
                    nsr = band_r0
                    merged = True
        if not merged:
            bands = _grow(bands, nb + 1)
            bands[nb, 0] = y0
            bands[nb, 1] = y1
            bands[nb, 2] = band_s0
            bands[nb, 3] = nsp
            nb += 1
    return bands[:nb].copy(), spans[:nsp].copy(), srcs[:nsr].copy()


@njit(cache=True)
def scanout(bands, spans, srcs, words, lut, out):
    """Fill ``out`` (h, w, 3) from the band structure, memory words and the 4096-entry LUT."""
    for b in range(bands.shape[0]):
        y0 = bands[b, 0]
        for y in range(y0, bands[b, 1]):
            dy = y - y0
            for s in range(bands[b, 2], bands[b, 3]):
                x0 = spans[s, 0]
                x1 = spans[s, 1]
                base = spans[s, 2] * 256
                r0 = spans[s, 3]
                r1 = spans[s, 4]
                if r0 == r1:
                    c0 = lut[base, 0]
                    c1 = lut[base, 1]
                    c2 = lut[base, 2]
                    for x in range(x0, x1):
                        out[y, x, 0] = c0
                        out[y, x, 1] = c1
                        out[y, x, 2] = c2
                    continue
                for x in range(x0, x1):
                    w = 0
                    for r in range(r0, r1):
                        mask = ((1 << srcs[r, 4]) - 1) << srcs[r, 3]
                        w |= words[srcs[r, 2] + dy, srcs[r, 1] + x - x0] & mask
                    out[y, x, 0] = lut[base + w, 0]
                    out[y, x, 1] = lut[base + w, 1]
                    out[y, x, 2] = lut[base + w, 2]
