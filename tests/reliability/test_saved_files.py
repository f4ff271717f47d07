"""Leftovers (docs/reliability.md): a killed writer's temporary file is swept up by the next
write; GIF and MP4 export use a unique temporary name; a PNG sequence appears as a whole."""

from __future__ import annotations

import os
import subprocess
import sys

import pytest

from camlab88.base.atomicfile import AtomicBatch, atomic_path, write_atomic


def _dead_pid() -> int:
    proc = subprocess.Popen([sys.executable, "-c", "pass"])
    proc.wait()
    return proc.pid  # finished and reaped: no process has this id now (for a while)


def test_a_killed_writers_temporary_file_is_swept_by_the_next_write(tmp_path) -> None:
    stale = tmp_path / f".out.png.{_dead_pid()}.k3j2.tmp"
    stale.write_bytes(b"half a picture")
    alive = tmp_path / f".out.png.{os.getppid()}.x1y2.tmp"  # a writer still running
    alive.write_bytes(b"in progress")
    write_atomic(tmp_path / "out.png", b"whole")
    assert not stale.exists() and alive.exists()
    assert (tmp_path / "out.png").read_bytes() == b"whole"


def test_atomic_path_keeps_the_suffix_and_leaves_nothing_on_failure(tmp_path) -> None:
    target = tmp_path / "film.gif"
    with atomic_path(target) as tmp:
        assert tmp.suffix == ".gif" and tmp.parent == tmp_path and tmp != target
        tmp.write_bytes(b"GIF89a")
    assert target.read_bytes() == b"GIF89a"
    with pytest.raises(RuntimeError), atomic_path(target) as tmp:
        tmp.write_bytes(b"broken")
        raise RuntimeError("encoder died")
    assert target.read_bytes() == b"GIF89a" and sorted(os.listdir(tmp_path)) == ["film.gif"]


def test_a_failed_batch_leaves_every_old_file(tmp_path) -> None:
    old = [tmp_path / f"seq_{i:04d}.png" for i in (1, 2, 3)]
    for p in old:
        p.write_bytes(b"old")
    with pytest.raises(RuntimeError), AtomicBatch() as batch:
        batch.add(old[0], b"new")
        batch.add(old[1], b"new")
        raise RuntimeError("killed mid-sequence")
    assert [p.read_bytes() for p in old] == [b"old"] * 3
    assert sorted(os.listdir(tmp_path)) == [p.name for p in old]


def test_a_png_sequence_export_replaces_the_whole_old_sequence(tmp_path) -> None:
    from camlab88.apps.kas import files
    from camlab88.apps.kas.export import export
    from camlab88.apps.kas.model import AnimSequence

    lib = os.path.join(os.path.dirname(files.__file__), "library")
    a = files.load_keyframe(os.path.join(lib, "walk_a.kas"))
    out = tmp_path / "seq.png"
    export(AnimSequence([a, a, a], 25.0), out, width=64, render_frame=None)
    assert len(list(tmp_path.glob("seq_*.png"))) == 3
    export(AnimSequence([a, a], 25.0), out, width=64)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["seq_0001.png", "seq_0002.png"]
