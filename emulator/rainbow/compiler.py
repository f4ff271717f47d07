"""The compiler: pad graph -> band structure, incremental where it can be.

Instances (graph.py) are the model: a screen pixel shows the instances with the greatest
priority key, concatenated on ties. The compiler turns keys into integer ranks, hands the
instance table to the compiled kernel (_kernels.compile_rows) and splices the result into
the previous structure. Only the rows some instance entered or left are rebuilt: the
affected rows are widened to whole bands plus one band either side, and because bands are
canonical (maximally merged) the splice equals a compile from scratch.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from camlab88.emulator.rainbow.bands import BandStructure
from camlab88.emulator.rainbow.graph import SCREEN_H, SCREEN_W, Instance, Pad, PadGraph


@dataclass
class CompileStats:
    compiles: int = 0
    full: int = 0
    rows_rebuilt: int = 0
    last_rows: int = 0


def _instance_rows(graph: PadGraph, insts: list[Instance]) -> dict[tuple[int, ...], tuple]:
    """Per path: everything about the instance that the band structure depends on."""
    out = {}
    for i in insts:
        pad: Pad = graph.nodes[i.pad]
        mx, my = (pad.alloc.x, pad.alloc.y) if pad.alloc else (0, 0)
        out[i.path] = (i.y0, i.y1, i.x0, i.x1, i.ox, i.oy, i.key, i.pad, mx, my,
                       pad.plane, pad.depth, pad.lut_page)
    return out


def _table(rows: dict[tuple[int, ...], tuple]) -> np.ndarray:
    keys = sorted({r[6] for r in rows.values()})
    rank = {k: n for n, k in enumerate(keys)}
    from camlab88.emulator.rainbow._kernels import INSTANCE_COLUMNS  # numba: on first use

    t = np.empty((len(rows), INSTANCE_COLUMNS), np.int64)
    for n, r in enumerate(rows.values()):
        t[n] = (*r[:6], rank[r[6]], *r[7:])
    return t


class Compiler:
    def __init__(self) -> None:
        self.structure = BandStructure.empty()
        self.stats = CompileStats()
        self._rows: dict[tuple[int, ...], tuple] | None = None

    def compile(self, graph: PadGraph, full: bool = False) -> BandStructure:
        rows = _instance_rows(graph, graph.instances())
        old = self._rows
        self._rows = rows
        self.stats.compiles += 1
        table = _table(rows)
        from camlab88.emulator.rainbow import _kernels  # (numba: imported on first use)

        if old is None or full or len(self.structure) == 0:
            self.stats.full += 1
            self.structure = BandStructure(*_kernels.compile_rows(0, SCREEN_H, SCREEN_W, table))
            self.stats.last_rows = SCREEN_H
            self.stats.rows_rebuilt += SCREEN_H
            return self.structure
        lo, hi = SCREEN_H, 0
        for path in old.keys() | rows.keys():
            a, b = old.get(path), rows.get(path)
            if a == b:
                continue
            for r in (a, b):
                if r is not None:
                    lo, hi = min(lo, r[0]), max(hi, r[1])
        if lo >= hi:
            self.stats.last_rows = 0
            return self.structure
        self.structure = self._splice(lo, hi, table)
        return self.structure

    def _splice(self, lo: int, hi: int, table: np.ndarray) -> BandStructure:
        s = self.structure
        y0s, y1s = s.bands[:, 0], s.bands[:, 1]
        i = max(int(np.searchsorted(y1s, lo, side="right")) - 1, 0)  # band before the first hit
        j = min(int(np.searchsorted(y0s, hi, side="left")), len(s.bands) - 1)  # band after
        ya, yb = int(y0s[i]), int(y1s[j])
        from camlab88.emulator.rainbow._kernels import compile_rows

        nb, ns, nr = compile_rows(ya, yb, SCREEN_W, table)
        self.stats.last_rows = yb - ya
        self.stats.rows_rebuilt += yb - ya
        s_lo, s_hi = int(s.bands[i, 2]), int(s.bands[j, 3])
        r_lo = int(s.spans[s_lo, 3]) if s_lo < len(s.spans) else len(s.sources)
        r_hi = int(s.spans[s_hi - 1, 4]) if s_hi > 0 else 0
        # new pieces are numbered from zero: shift them to follow the kept prefix
        nb = nb.copy()
        nb[:, 2:4] += s_lo
        ns = ns.copy()
        ns[:, 3:5] += r_lo
        tail_b = s.bands[j + 1:].copy()
        tail_b[:, 2:4] += len(ns) - (s_hi - s_lo)
        tail_s = s.spans[s_hi:].copy()
        tail_s[:, 3:5] += len(nr) - (r_hi - r_lo)
        return BandStructure(
            np.concatenate([s.bands[:i], nb, tail_b]),
            np.concatenate([s.spans[:s_lo], ns, tail_s]),
            np.concatenate([s.sources[:r_lo], nr, s.sources[r_hi:]]),
        )


def compile_graph(graph: PadGraph) -> BandStructure:
    """A compile from scratch (what the incremental path must always equal)."""
    return Compiler().compile(graph)
