"""The commands a README section shows (indented lines starting ``camlab88``), split as a
shell would, and run exactly as printed from a scratch folder standing for the repository top."""

from __future__ import annotations

import shlex
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]


def section_commands(heading: str) -> list[list[str]]:
    """Every ``    camlab88 ...`` line between ``## heading`` and the next ``## ``."""
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    section = text.split(f"\n## {heading}", 1)[1].split("\n## ", 1)[0]
    return [shlex.split(line.strip(), comments=True) for line in section.splitlines()
            if line.startswith("    camlab88 ")]


def run_as_printed(commands: list[list[str]], top: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """Run ``commands`` in-process from ``top`` (an empty folder, ``examples/`` linked into it
    as at the repository top, where the README's commands are typed); each must exit 0."""
    from camlab88.cli import main

    (top / "examples").symlink_to(ROOT / "examples")
    monkeypatch.chdir(top)
    for words in commands:
        assert main(words[1:]) == 0, words
