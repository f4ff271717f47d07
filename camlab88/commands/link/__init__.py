"""``camlab88 link ...``: inspect link recordings and test connections (protocols.link.cli)."""

from __future__ import annotations

ACTIONS = ("dump", "stream", "echo")
HELP = "serial-line tools: dump recordings, extract streams, echo device"
DESCRIPTION = "Tools for the emulated serial line (see docs/link.md)."

