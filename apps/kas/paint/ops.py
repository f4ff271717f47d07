"""Colouring operations and the operations file's contents (thesis §3.3).

The order of the operations is the "in front of" order: later operations paint over
earlier ones.  Sequence operations apply to every frame by chain number; a frame's own
operations (graphical edits of that frame) follow them in that frame only.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from apps.kas.paint.palette import Palette

KINDS = ("fill", "line", "region", "touch")
Point = tuple[float, float]


@dataclass(frozen=True)
class Op:
    """One colouring operation.

    ``fill``: the closed shape(s) made by joining the end points of ``chains`` (1-based
    chain numbers), filled from seed points the host finds; ``seeds`` are those found in
    the frame where it was done (recorded, recomputed for every other frame).
    ``line``: the chains themselves drawn in the colour.  ``region``: the face of the
    drawing's lines containing ``at`` in frame ``frame``, followed into other frames.
    ``touch``: point-and-fill by hand at ``at`` (a frame's own operation only).
    ``line_no`` / ``cols`` say where the operation stands in its file (0 = not from a file).
    """

    kind: str
    colour: int
    chains: tuple[int, ...] = ()
    at: Point | None = None
    frame: int | None = None
    seeds: tuple[Point, ...] = ()
    line_no: int = field(default=0, compare=False)
    cols: tuple[int, ...] = field(default=(), compare=False)  # column of each chain number

    def __post_init__(self) -> None:
        if self.kind not in KINDS:
            raise ValueError(f"operation kind is one of {', '.join(KINDS)}, not {self.kind!r}")
        if self.kind in ("fill", "line") and not self.chains:
            raise ValueError(f"a {self.kind} operation names at least one line-chain")
        if self.kind in ("region", "touch") and self.at is None:
            raise ValueError(f"a {self.kind} operation needs a point")


@dataclass
class OpsFile:
    """The palette, the gap-closing tolerance (inches), the painted frame (1-based), the
    sequence operations in order, and each frame's own operations."""

    palette: Palette = field(default_factory=Palette)
    ops: list[Op] = field(default_factory=list)
    frame_ops: dict[int, list[Op]] = field(default_factory=dict)
    gap: float = 0.0
    painted: int = 1
    name: str = "<operations>"
    # where the 'painted' value and each 'frame N' number stand in the file (line, column)
    at: dict[str, tuple[int, int]] = field(default_factory=dict, compare=False)

    def ops_for(self, frame: int) -> list[Op]:
        """Everything to do in ``frame`` (1-based), front-most last."""
        return self.ops + self.frame_ops.get(frame, [])
