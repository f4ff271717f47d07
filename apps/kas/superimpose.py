"""The superimposer (§3.1.3): any number of sequences, each with a start offset in frames.

A sequence that has not started yet shows its first frame; one that has ended holds its
last (the thesis's bird-and-flower example).  Frames are combined by appending chains in
the order the sequences are given, so each element keeps its own drawing order.
"""

from __future__ import annotations

from collections.abc import Sequence

from camlab88.apps.kas.model import AnimSequence, Drawing


def frame_index(frame: int, offset: int, length: int) -> int:
    """Which frame of a sequence starting at ``offset`` shows at composite ``frame``."""
    return min(max(frame - offset, 0), length - 1)


def superimpose(parts: Sequence[tuple[AnimSequence, int]]) -> AnimSequence:
    """Combine ``(sequence, offset)`` pairs; offsets are >= 0 frames after the start."""
    if not parts:
        raise ValueError("nothing to superimpose")
    for seq, off in parts:
        if off < 0:
            raise ValueError("start offsets must be zero or positive")
        if not seq.frames:
            raise ValueError("cannot superimpose an empty sequence")
    fps = {s.fps for s, _ in parts}
    if len(fps) != 1:
        raise ValueError(f"sequences have different frame rates: {sorted(fps)}")
    total = max(off + len(seq) for seq, off in parts)
    frames = []
    for f in range(total):
        chains = []
        for seq, off in parts:
            chains.extend(c.copy(keep_uid=False)
                          for c in seq.frames[frame_index(f, off, len(seq))].chains)
        frames.append(Drawing(chains))
    return AnimSequence(frames, fps.pop())


def multiple_image(seq: AnimSequence, copies: int, step: int = 1) -> AnimSequence:
    """A sequence superimposed on itself ``copies`` times, ``step`` frames apart (§3.1.3)."""
    if copies < 1 or step < 0:
        raise ValueError("need at least one copy and a non-negative step")
    return superimpose([(seq, k * step) for k in range(copies)])
