"""The Rainbow workstation: graphics memory, pad graph, band-structure compiler, video
processor and input controller (pure numpy + numba; no pygame)."""

from camlab88.emulator.rainbow.device import FRAME_MS, Rainbow
from camlab88.emulator.rainbow.errors import GraphError, OutOfVideoMemory, RainbowError
from camlab88.emulator.rainbow.graph import SCREEN, SCREEN_H, SCREEN_W
from camlab88.emulator.rainbow.memory import VideoMemory

__all__ = ["FRAME_MS", "GraphError", "OutOfVideoMemory", "Rainbow", "RainbowError", "SCREEN",
           "SCREEN_H", "SCREEN_W", "VideoMemory"]
