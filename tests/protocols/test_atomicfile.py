"""camlab88.base.atomicfile: the old file survives any failure; the new one lands whole."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from camlab88.base.atomicfile import atomic_output, write_atomic


def test_write_replaces_whole_and_leaves_no_temporary(tmp_path: Path) -> None:
    p = tmp_path / "a.txt"
    write_atomic(p, "old")
    write_atomic(p, b"new bytes")
    assert p.read_bytes() == b"new bytes"
    assert sorted(x.name for x in tmp_path.iterdir()) == ["a.txt"]


def test_failure_mid_write_keeps_the_old_file(tmp_path: Path) -> None:
    p = tmp_path / "a.txt"
    write_atomic(p, "precious")
    with pytest.raises(RuntimeError), atomic_output(p, "w", encoding="utf-8") as fh:
        fh.write("half of the new")
        raise RuntimeError("disk full")
    assert p.read_text() == "precious"
    assert sorted(x.name for x in tmp_path.iterdir()) == ["a.txt"]


def test_mode_follows_the_umask_not_mkstemp(tmp_path: Path) -> None:
    old = os.umask(0o022)
    try:
        write_atomic(tmp_path / "m", "x")
    finally:
        os.umask(old)
    assert (tmp_path / "m").stat().st_mode & 0o777 == 0o644


def test_missing_directory_is_an_error_naming_it(tmp_path: Path) -> None:
    with pytest.raises(FileNotFoundError):
        write_atomic(tmp_path / "nope" / "x", "x")
