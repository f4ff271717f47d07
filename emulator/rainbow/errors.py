"""Errors the Rainbow raises back to a program; none of them leaves the device in a bad state."""

from __future__ import annotations


class RainbowError(Exception):
    """A pad-library call the device refused (bad node, bad argument, ...)."""


class OutOfVideoMemory(RainbowError):
    """No free rectangle of graphics memory in the planes a pad asked for."""


class GraphError(RainbowError):
    """An edit that would break the pad graph (a cycle, an unknown node or arc)."""
