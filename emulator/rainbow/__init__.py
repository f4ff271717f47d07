"""The Rainbow workstation: graphics memory, pad graph, band-structure compiler, video
processor and input controller (pure numpy + numba; no pygame)."""

from emulator.rainbow.device import FRAME_MS, Rainbow
from emulator.rainbow.errors import GraphError, OutOfVideoMemory, RainbowError
from emulator.rainbow.graph import SCREEN, SCREEN_H, SCREEN_W
from emulator.rainbow.memory import VideoMemory

__all__ = ["FRAME_MS", "GraphError", "OutOfVideoMemory", "Rainbow", "RainbowError", "SCREEN",
           "SCREEN_H", "SCREEN_W", "VideoMemory"]
