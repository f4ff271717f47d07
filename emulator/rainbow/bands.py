"""The band structure: the low-level screen description the video processor interprets.

Three integer tables (so the video processor can run over them in compiled code):

- ``bands[i] = (y0, y1, s0, s1)``: screen rows y0..y1-1 share one list of spans,
  ``spans[s0:s1]``.
- ``spans[s] = (x0, x1, page, r0, r1)``: columns x0..x1-1 take their word from the memory
  sources ``sources[r0:r1]`` OR'ed together (a tie between instances: concatenation), and
  index LUT page ``page``. With no sources the span shows the virtual colour
  ``LUT[page * 256]`` (a virtual pad, or nothing mapped: page 0).
- ``sources[r] = (pad, mem_x, mem_y, plane, depth)``: the word at screen (x, y) in the span
  reads memory (mem_x + x - x0, mem_y + y - y0) masked to planes plane..plane+depth-1
  (the pad's value already sits shifted up by ``plane``).

The structure is canonical: rows are merged into a band, and columns into a span, exactly
when their descriptions continue one another, so a structure compiled incrementally equals
one compiled from scratch, table for table.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class Source:
    pad: int
    mem_x: int
    mem_y: int
    plane: int
    depth: int


@dataclass(frozen=True)
class Span:
    x0: int
    x1: int
    page: int
    sources: tuple[Source, ...]


@dataclass(frozen=True)
class Band:
    y0: int
    y1: int
    spans: tuple[Span, ...]


@dataclass
class BandStructure:
    bands: np.ndarray  # (n, 4) int64
    spans: np.ndarray  # (m, 5) int64
    sources: np.ndarray  # (k, 5) int64

    @classmethod
    def empty(cls) -> BandStructure:
        z = np.zeros((0, 4), np.int64)
        return cls(z, np.zeros((0, 5), np.int64), np.zeros((0, 5), np.int64))

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, BandStructure):
            return NotImplemented
        return (np.array_equal(self.bands, other.bands)
                and np.array_equal(self.spans, other.spans)
                and np.array_equal(self.sources, other.sources))

    def __iter__(self) -> Iterator[Band]:
        for y0, y1, s0, s1 in self.bands.tolist():
            spans = []
            for x0, x1, page, r0, r1 in self.spans[s0:s1].tolist():
                srcs = tuple(Source(*r) for r in self.sources[r0:r1].tolist())
                spans.append(Span(x0, x1, page, srcs))
            yield Band(y0, y1, tuple(spans))

    def __len__(self) -> int:
        return len(self.bands)

    def to_text(self) -> str:
        """The documented text form written by ``camlab88 rainbow render --bands``."""
        lines = [
            "# camlab88 Rainbow band structure v1",
            f"# {len(self.bands)} bands, {len(self.spans)} spans, {len(self.sources)} sources",
        ]
        for band in self:
            lines.append(f"band y={band.y0}..{band.y1 - 1} spans={len(band.spans)}")
            for s in band.spans:
                head = f"  span x={s.x0}..{s.x1 - 1} page={s.page}"
                if not s.sources:
                    lines.append(f"{head} virtual colour=LUT[{s.page * 256}]")
                    continue
                tie = " concat" if len(s.sources) > 1 else ""
                lines.append(f"{head}{tie}")
                for r in s.sources:
                    mask = ((1 << r.depth) - 1) << r.plane
                    lines.append(
                        f"    pad={r.pad} mem=({r.mem_x},{r.mem_y}) planes=0x{mask:02x} "
                        f"shift={r.plane}"
                    )
        return "\n".join(lines) + "\n"
