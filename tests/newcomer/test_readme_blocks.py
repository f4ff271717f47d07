"""README blocks outside the walkthrough that the repeat newcomer trial (docs/newcomer_trial.md)
typed as printed: the KAS synopsis block names only files that exist or that an earlier line
of it makes, and the set-up says how `camlab88` gets on the PATH."""

from __future__ import annotations

import shlex
import shutil
from pathlib import Path

import pytest

from camlab88.cli import main

ROOT = Path(__file__).resolve().parents[2]
README = (ROOT / "README.md").read_text(encoding="utf-8")


def _block(start: str, end: str) -> list[list[str]]:
    body = README[README.index(start):README.index(end)]
    return [shlex.split(line.strip(), comments=True) for line in body.splitlines()
            if line.startswith("    camlab88 ")]


def test_the_walkthrough_says_how_camlab88_gets_on_the_path() -> None:
    start = README.index("## First ten minutes")
    assert ".venv/bin/activate" in README[start:start + 600]


def test_the_kas_block_runs_in_order(tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
                                     capsys: pytest.CaptureFixture[str]) -> None:
    commands = _block("## KAS — the keyframe animation suite", "The programs also run on")
    assert len(commands) >= 10
    shutil.copytree(ROOT / "examples", tmp_path / "examples")
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("CAMLAB88_KAS_LIBRARY", str(tmp_path / "library"))
    for argv in commands:
        rc = main(argv[1:])
        out, err = capsys.readouterr()
        assert rc == 0, f"{shlex.join(argv)}\n{out}\n{err}"
    assert (tmp_path / "library" / "walk_arc.kas").is_file()
    assert (tmp_path / "key.kas").is_file()  # what the next block's `kas edit key.kas` opens
