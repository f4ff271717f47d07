"""Graphics memory: 8 bit-planes of pixel words, and the allocator that places pads in them.

Memory is a 2-D array of 8-bit words; bit ``p`` of a word is plane ``p``. A pad of depth d
whose lowest plane is p owns planes p..p+d-1 of a rectangle of words, so pads in distinct
planes may share the same words (how the Appendix I transparency example is laid out).
The allocator works on granules of ``GRANULE`` x ``GRANULE`` words and takes the first
free place in row-major order, so placement is deterministic.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from camlab88.emulator.rainbow.errors import OutOfVideoMemory, RainbowError

GRANULE = 8
PLANES = 8

# The relic's 64K x 16-bit words = 1 Mbit = 8 planes of 512 x 256 pixels.
STRICT_SIZE = (512, 256)
# Default: room for several full screens in every plane (the thesis's programs used
# double-buffered full-screen pads and a large panning pad).
DEFAULT_SIZE = (2048, 2048)


@dataclass(frozen=True)
class Allocation:
    x: int
    y: int
    width: int
    height: int
    plane_mask: int


class VideoMemory:
    """8-plane graphics memory with a first-fit rectangle allocator."""

    def __init__(self, width: int = DEFAULT_SIZE[0], height: int = DEFAULT_SIZE[1]) -> None:
        if width <= 0 or height <= 0 or width % GRANULE or height % GRANULE:
            raise RainbowError(
                f"video memory size {width}x{height} must be positive multiples of {GRANULE}"
            )
        self.width = width
        self.height = height
        self.words = np.zeros((height, width), dtype=np.uint8)
        # Per granule: which planes are taken.
        self._used = np.zeros((height // GRANULE, width // GRANULE), dtype=np.uint8)

    def save_state(self) -> dict[str, bytes]:
        """The words and the allocation map, as raw bytes."""
        return {"words": self.words.tobytes(), "used": self._used.tobytes()}

    def load_state(self, state: dict[str, bytes]) -> None:
        """Put back save_state()'s bytes (ValueError if they do not fit this memory)."""
        for name, arr in (("words", self.words), ("used", self._used)):
            if len(state[name]) != arr.nbytes:
                raise ValueError(f"video memory state {name!r} is {len(state[name])} bytes, "
                                 f"this memory needs {arr.nbytes}")
        self.words[...] = np.frombuffer(state["words"], np.uint8).reshape(self.words.shape)
        self._used[...] = np.frombuffer(state["used"], np.uint8).reshape(self._used.shape)

    @classmethod
    def strict(cls) -> VideoMemory:
        return cls(*STRICT_SIZE)

    @property
    def words_16bit(self) -> int:
        """Capacity expressed as the hardware's 16-bit words."""
        return self.width * self.height * PLANES // 16

    def allocate(self, width: int, height: int, plane: int, depth: int) -> Allocation:
        mask = ((1 << depth) - 1) << plane
        gw = -(-width // GRANULE)
        gh = -(-height // GRANULE)
        rows, cols = self._used.shape
        if gw > cols or gh > rows:
            raise OutOfVideoMemory(
                f"a {width}x{height} pad does not fit in {self.width}x{self.height} video memory"
            )
        blocked = ((self._used & mask) != 0).astype(np.int32)
        # Summed-area table: count blocked granules in every gh x gw window at once.
        sat = np.zeros((rows + 1, cols + 1), dtype=np.int32)
        sat[1:, 1:] = blocked.cumsum(0).cumsum(1)
        win = sat[gh:, gw:] - sat[:-gh, gw:] - sat[gh:, :-gw] + sat[:-gh, :-gw]
        free = np.flatnonzero(win.ravel() == 0)
        if free.size == 0:
            raise OutOfVideoMemory(
                f"out of video memory: no free {width}x{height} area in planes "
                f"{plane}..{plane + depth - 1} ({self.words_16bit} 16-bit words in all)"
            )
        gy, gx = divmod(int(free[0]), win.shape[1])
        self._used[gy : gy + gh, gx : gx + gw] |= mask
        x, y = gx * GRANULE, gy * GRANULE
        self.words[y : y + height, x : x + width] &= ~np.uint8(mask)
        return Allocation(x, y, width, height, mask)

    def free(self, a: Allocation) -> None:
        gx, gy = a.x // GRANULE, a.y // GRANULE
        gw = -(-a.width // GRANULE)
        gh = -(-a.height // GRANULE)
        self._used[gy : gy + gh, gx : gx + gw] &= ~np.uint8(a.plane_mask)

