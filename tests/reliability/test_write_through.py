"""Output paths that are not regular files: a FIFO (or a device, as ``/dev/stdout``) is
written into, never replaced by a renamed temporary file; a symbolic link stays a link and
its target gets the new content; a directory is refused naming the user's path (never the
temporary file). And every temporary file, ``--record-line``'s included, has the name the
stale-temp sweep knows, so a SIGKILLed writer's leftovers go with the next write. (No test
here points at a real device node: before the fix it would have been replaced.)"""

from __future__ import annotations

import os
import signal
import stat
import subprocess
import sys
import threading
from pathlib import Path

import pytest

from camlab88.base.atomicfile import AtomicBatch, atomic_path, sweep_stale, write_atomic

ROOT = Path(__file__).resolve().parents[2]


def _read_fifo(fifo: Path, got: list[bytes]) -> threading.Thread:
    def read() -> None:
        with open(fifo, "rb") as fh:
            got.append(fh.read())
    reader = threading.Thread(target=read, daemon=True)
    reader.start()
    return reader


@pytest.mark.parametrize("how", ["write_atomic", "batch", "atomic_path"])
def test_a_fifo_is_written_into_and_stays_a_fifo(tmp_path: Path, how: str) -> None:
    fifo = tmp_path / "pipe"
    os.mkfifo(fifo)
    got: list[bytes] = []
    reader = _read_fifo(fifo, got)
    if how == "write_atomic":
        write_atomic(fifo, b"frame bytes")
    elif how == "batch":
        with AtomicBatch() as batch:
            batch.add(fifo, b"frame bytes")
    else:
        with atomic_path(fifo) as name:
            Path(name).write_bytes(b"frame bytes")
    reader.join(5)
    assert got == [b"frame bytes"]
    assert stat.S_ISFIFO(os.lstat(fifo).st_mode)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["pipe"]


def test_a_symlink_stays_a_link_and_its_target_gets_the_content(tmp_path: Path) -> None:
    real = tmp_path / "real" / "seq.kas"
    real.parent.mkdir()
    real.write_bytes(b"old")
    link = tmp_path / "seq.kas"
    link.symlink_to(real)
    write_atomic(link, b"new")
    assert link.is_symlink() and real.read_bytes() == b"new"
    fifo = tmp_path / "pipe"
    os.mkfifo(fifo)
    to_fifo = tmp_path / "to_pipe"
    to_fifo.symlink_to(fifo)
    got: list[bytes] = []
    reader = _read_fifo(fifo, got)
    write_atomic(to_fifo, b"through")
    reader.join(5)
    assert got == [b"through"] and to_fifo.is_symlink()


def test_a_directory_is_refused_naming_the_users_path(tmp_path: Path) -> None:
    target = tmp_path / "seq.kas"
    target.mkdir()
    with pytest.raises(IsADirectoryError) as caught:
        write_atomic(target, b"x")
    assert caught.value.filename == str(target)
    assert ".tmp" not in str(caught.value)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["seq.kas"]


def test_a_missing_directory_is_reported_naming_the_users_path(tmp_path: Path) -> None:
    target = tmp_path / "nowhere" / "seq.kas"
    with pytest.raises(FileNotFoundError) as caught:
        write_atomic(target, b"x")
    assert caught.value.filename == str(target) and ".tmp" not in str(caught.value)


def test_a_killed_line_recorder_leaves_a_temporary_the_sweep_removes(tmp_path: Path) -> None:
    path = tmp_path / "line.rec"
    code = ("import os, signal\n"
            "from camlab88.protocols.link import LineSettings\n"
            "from camlab88.protocols.link.recording import Recorder\n"
            f"r = Recorder({str(path)!r}, LineSettings(baud=9600))\n"
            "r.record(1, '>', b'abc')\n"
            "os.kill(os.getpid(), signal.SIGKILL)\n")
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    done = subprocess.run([sys.executable, "-c", code], env=env, timeout=60, check=False)
    assert done.returncode == -signal.SIGKILL
    left = [p.name for p in tmp_path.iterdir()]
    assert len(left) == 1 and left[0].startswith(".line.rec.") and not path.exists()
    assert [p.name for p in sweep_stale(path)] == left
    assert list(tmp_path.iterdir()) == []
