"""Every command's --help as it was when the parsers were commands.toml tables (issue 41's
change to parsers in code): the texts in tests/data/help_before were written by the TOML
parsers (COLUMNS=100). A test for that change only: dropped once it has landed."""

from __future__ import annotations

import argparse
import contextlib
import io
from pathlib import Path

import pytest
from camlab88 import cli

BEFORE = Path(__file__).resolve().parent / "data" / "help_before"


def _commands() -> list[list[str]]:
    def choices(p: argparse.ArgumentParser) -> dict:
        return next((a.choices for a in p._actions
                     if isinstance(a, argparse._SubParsersAction)), {})

    out: list[list[str]] = [[]]
    for area, parser in choices(cli.build_parser()).items():
        out += [[area], *([area, action] for action in choices(parser))]
    return out


def test_every_command_is_compared() -> None:
    assert {"_".join(w) or "_top" for w in _commands()} == {p.stem for p in BEFORE.glob("*.txt")}


@pytest.mark.parametrize("words", _commands(), ids=lambda w: " ".join(w) or "camlab88")
def test_help_is_as_before(words: list[str], monkeypatch) -> None:
    monkeypatch.setenv("COLUMNS", "100")
    said = io.StringIO()
    with contextlib.redirect_stdout(said), pytest.raises(SystemExit) as done:
        cli._main([*words, "--help"])
    assert done.value.code == 0
    assert said.getvalue() == (BEFORE / f"{'_'.join(words) or '_top'}.txt").read_text()
