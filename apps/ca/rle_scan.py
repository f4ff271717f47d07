"""The RLE body read in two compiled passes over its bytes (no Python step per token).

Pass one checks the body and measures it (live runs, cells, the box of the live cells);
pass two writes the runs either as cell arrays or straight into a uint8 grid, so a 12 MB
RLE of a random 4000 x 4000 soup decodes in tens of milliseconds and a dense pattern never
exists as 16 million (x, y, state) triples.  Same grammar as the token reader in
rle_body.py, which still words the error messages.
"""

from __future__ import annotations

import numpy as np
from numba import njit

PLANE = 65536
MAX_STATE = 255
OK, SYNTAX, HIGH_STATE, TOO_WIDE = 0, 1, 2, 3
# scan() results: status, error offset, end ('!' offset), live runs, live cells, first and
# last live row, first and last live column, largest state
_FIELDS = 10


def _tables() -> tuple[np.ndarray, np.ndarray]:
    """Byte classes (0 not allowed, 1 whitespace, 2 digit, 3 symbol, 4 first of two) and
    the state of each one-byte symbol."""
    kind = np.zeros(256, np.int64)
    state = np.zeros(256, np.int64)
    kind[[9, 10, 11, 12, 13, 32]] = 1
    kind[48:58] = 2
    for ch in "bo.$!ABCDEFGHIJKLMNOPQRSTUVWX":
        kind[ord(ch)] = 3
    state[ord("o")] = 1
    state[65:89] = np.arange(1, 25)
    kind[112:122] = 4  # p..y
    return kind, state


_KIND, _STATE = _tables()


@njit(cache=True, inline="always")
def _symbol(b, i, kind, state):
    """(state, length) of the symbol at byte i; length 0 if there is none."""
    k = kind[b[i]]
    if k == 3:
        return state[b[i]], np.int64(1)
    if k == 4 and i + 1 < b.shape[0] and 65 <= b[i + 1] <= 88:  # pA..yX
        return np.int64(25 + (np.int64(b[i]) - 112) * 24 + np.int64(b[i + 1]) - 65), np.int64(2)
    return np.int64(0), np.int64(0)


@njit(cache=True)
def scan(b, ry, rx, rn, rs):
    """The one pass over the body bytes ``b`` (uint8): the _FIELDS figures above, and the
    live runs' rows, columns, lengths and states in ``ry``, ``rx``, ``rn``, ``rs`` (room for
    one run a byte).  Runs past the plane's edge are not recorded (an error follows)."""
    kind, table = _KIND, _STATE
    res = np.zeros(_FIELDS, np.int64)
    n = b.shape[0]
    x = y = runs = cells = top = left = big = 0
    bottom = right = -1
    top = left = PLANE
    high = wide = -1
    ended = False
    i = 0
    while i < n:
        c = b[i]
        if kind[c] == 1:
            i += 1
            continue
        start = i
        count = 0
        digits = 0
        if 49 <= c <= 57:
            while i < n and kind[b[i]] == 2 and digits < 6:
                count = count * 10 + np.int64(b[i]) - 48
                digits += 1
                i += 1
        if i >= n:
            res[0], res[1] = SYNTAX, start
            return res
        state, length = _symbol(b, i, kind, table)
        if length == 0:
            res[0], res[1] = SYNTAX, start
            return res
        if digits == 0:
            count = 1
        sym = b[i]
        i += length
        if sym == 33:  # '!'
            res[2] = start
            ended = True
            break
        if sym == 36:  # '$'
            y += count
            x = 0
            continue
        if state > MAX_STATE and high < 0:
            high = start + digits + 1
        if (x + count > PLANE or y >= PLANE) and wide < 0:
            wide = start
        if state > 0 and wide < 0:
            ry[runs], rx[runs], rn[runs], rs[runs] = y, x, count, state
            runs += 1
            cells += count
            top = min(top, y)
            bottom = max(bottom, y)
            left = min(left, x)
            right = max(right, x + count - 1)
            big = max(big, state)
        x += count
    if not ended:
        res[0], res[1] = SYNTAX, n
        return res
    if high >= 0:
        res[0], res[1] = HIGH_STATE, high
    elif wide >= 0:
        res[0], res[1] = TOO_WIDE, wide
    res[3], res[4], res[5], res[6], res[7], res[8], res[9] = (runs, cells, top, bottom,
                                                              left, right, big)
    return res


@njit(cache=True)
def to_grid(ry, rx, rn, rs, runs, grid, top, left):
    """The first ``runs`` runs written into ``grid`` (rows from ``top``, columns from
    ``left``)."""
    for k in range(runs):
        y = ry[k] - top
        for x in range(rx[k] - left, rx[k] - left + rn[k]):
            grid[y, x] = rs[k]


@njit(cache=True)
def to_cells(ry, rx, rn, rs, runs, cx, cy, ct, top, left):
    """The first ``runs`` runs as cell arrays, relative to (left, top)."""
    i = 0
    for k in range(runs):
        for j in range(rn[k]):
            cx[i], cy[i], ct[i] = rx[k] + j - left, ry[k] - top, rs[k]
            i += 1
