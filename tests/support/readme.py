"""The commands a README section shows (indented lines starting ``camlab88``), split as a
shell would, so a test can run them exactly as printed."""

from __future__ import annotations

import shlex
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def section_commands(heading: str) -> list[list[str]]:
    """Every ``    camlab88 ...`` line between ``## heading`` and the next ``## ``."""
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    section = text.split(f"\n## {heading}", 1)[1].split("\n## ", 1)[0]
    return [shlex.split(line.strip(), comments=True) for line in section.splitlines()
            if line.startswith("    camlab88 ")]
