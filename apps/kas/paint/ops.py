"""Colouring operations and the operations file's contents (thesis §3.3).

The order of the operations is the "in front of" order: later operations paint over
earlier ones.  Sequence operations apply to every frame by chain number; a frame's own
operations (graphical edits of that frame) follow them in that frame only.  The seed points
a sequence operation used in each frame are kept "on a frame by frame basis" (§3.3) as
``Seeds`` records, so a replay needs no recomputation and a frame's seeds can be edited by
hand.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from camlab88.apps.kas.paint.palette import Palette

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


def op_key(op: Op) -> tuple[object, ...]:
    """What identifies a sequence operation for its per-frame seeds: kind and chains (or
    point).  Not its colour nor its place in the file, so recolouring or reordering the
    sequence operations by hand keeps each frame's seeds with their operation."""
    return (op.kind, op.chains) if op.kind in ("fill", "line") else (op.kind, op.at)


@dataclass(frozen=True)
class Seeds:
    """The seed points (field inches) one sequence operation used in one frame; ``key`` is
    its ``op_key``.  Two sequence operations with the same key take their frame's records
    with that key in order."""

    key: tuple[object, ...]
    seeds: tuple[Point, ...]
    line_no: int = field(default=0, compare=False)
    col: int = field(default=0, compare=False)


@dataclass
class OpsFile:
    """The palette, the gap-closing tolerance (inches), the painted frame (1-based), the
    sequence operations in order, each frame's own operations, and the seeds each sequence
    operation used in each frame."""

    palette: Palette = field(default_factory=Palette)
    ops: list[Op] = field(default_factory=list)
    frame_ops: dict[int, list[Op]] = field(default_factory=dict)
    gap: float = 0.0
    painted: int = 1
    name: str = "<operations>"
    # where the 'painted' value and each 'frame N' number stand in the file (line, column)
    at: dict[str, tuple[int, int]] = field(default_factory=dict, compare=False)
    frame_seeds: dict[int, list[Seeds]] = field(default_factory=dict)

    def ops_for(self, frame: int) -> list[Op]:
        """Everything to do in ``frame`` (1-based), front-most last."""
        return self.ops + self.frame_ops.get(frame, [])

    def recorded_seeds(self, frame: int, index: int) -> Seeds | None:
        """The seeds recorded in ``frame`` for sequence operation ``index`` (0-based), if
        any: the k-th record with its key for the k-th operation with that key."""
        key = op_key(self.ops[index])
        k = sum(op_key(o) == key for o in self.ops[:index])
        same = [r for r in self.frame_seeds.get(frame, []) if r.key == key]
        return same[k] if k < len(same) else None
