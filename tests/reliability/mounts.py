"""Small real filesystems for fault tests: a tmpfs filled to its last block (ENOSPC) and a
read-only tmpfs (EROFS). Mounting needs root (CI runs as root); where it is not allowed the
test is skipped saying why — never silently."""

from __future__ import annotations

import contextlib
import errno
import os
import subprocess
from collections.abc import Iterator
from pathlib import Path

import pytest

OLD = b"the user's old file\n"


def fill(folder: Path) -> None:
    """Use every free block of ``folder``'s filesystem."""
    with open(folder / "filler", "wb", buffering=0) as fh:
        with contextlib.suppress(OSError):
            while True:
                fh.write(bytes(4096))
    assert os.statvfs(folder).f_bavail == 0


@contextlib.contextmanager
def _tmpfs(where: Path, old: dict[str, bytes] | None) -> Iterator[Path]:
    """A 256 KiB tmpfs mounted at ``where`` holding the files ``old`` (name: bytes), unmounted
    when the block ends; the test is skipped, saying why, where it cannot be mounted."""
    where.mkdir(parents=True, exist_ok=True)
    if os.geteuid() != 0:
        pytest.skip(f"a tmpfs cannot be mounted at {where}: mounting needs root (CI runs as "
                    "root)")
    done = subprocess.run(["mount", "-t", "tmpfs", "-o", "size=256k,mode=0777", "tmpfs",
                           str(where)], capture_output=True, text=True, timeout=30, check=False)
    if done.returncode != 0:
        pytest.skip(f"a tmpfs cannot be mounted at {where}: {done.stderr.strip()}")
    try:
        for name, data in (old or {}).items():
            (where / name).write_bytes(data)
        yield where
    finally:
        subprocess.run(["umount", "-l", str(where)], capture_output=True, timeout=30,
                       check=False)


@contextlib.contextmanager
def full_disk(base: Path, old: dict[str, bytes] | None = None) -> Iterator[Path]:
    """A 256 KiB tmpfs holding the files ``old`` (name: bytes), then filled."""
    with _tmpfs(base / "full", old) as where:
        fill(where)
        yield where


@contextlib.contextmanager
def read_only(base: Path, old: dict[str, bytes] | None = None) -> Iterator[Path]:
    """A tmpfs holding the files ``old`` (name: bytes), remounted read-only."""
    with _tmpfs(base / "ro", old) as where:
        done = subprocess.run(["mount", "-o", "remount,ro", str(where)], capture_output=True,
                              text=True, timeout=30, check=False)
        if done.returncode != 0:
            pytest.skip(f"cannot remount {where} read-only: {done.stderr.strip()}")
        with pytest.raises(OSError) as caught:
            (where / "probe").write_bytes(b"x")
        assert caught.value.errno == errno.EROFS
        yield where
