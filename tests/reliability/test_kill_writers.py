"""SIGKILL at seeded random moments, for each kind of writer: the file on disk is always the
old one or a whole new one (never torn, never a mix inside one file), and the temporary
files a killed writer leaves are swept by the next write. A writer runs in a child process
that saves new versions in a loop; the test kills it after a random delay (seed 2027).

Writers: the atomic write every save uses (sessions, keyframes, checkpoints, PNGs), a PNG
sequence (AtomicBatch, each file old or new), the line recorder (``--record-line``,
streamed to its temporary file), and ``camlab88 ca run --png`` end to end."""

from __future__ import annotations

import os
import random
import signal
import subprocess
import sys
import time
from collections.abc import Iterator
from pathlib import Path

import pytest

from camlab88.base.atomicfile import sweep_stale, write_atomic

ROOT = Path(__file__).resolve().parents[2]
SEED = 2027
KILLS = 16  # per writer: about a second each at most
OLD = b"the old file\n"
SIZE = 1 << 20  # each new version: 1 MiB, so a kill often lands mid-write

_CHILD = {
    "write_atomic": """
from camlab88.base.atomicfile import write_atomic
print("ready", flush=True)
for k in range(10**6):
    write_atomic(TARGET, (b"%08d" % k) * (SIZE // 8))
""",
    "batch": """
from camlab88.base.atomicfile import AtomicBatch
print("ready", flush=True)
for k in range(10**6):
    with AtomicBatch() as batch:
        for i in range(3):
            batch.add(f"{TARGET}_{i}", (b"%08d" % k) * (SIZE // 8 // 3))
""",
    "line recorder": """
from fractions import Fraction
from camlab88.protocols.link import LineSettings
from camlab88.protocols.link.recording import Recorder
print("ready", flush=True)
for k in range(10**6):
    r = Recorder(TARGET, LineSettings(baud=9600))
    for i in range(500):
        r.record(Fraction(i + 1, 10), ">", b"%08d" % k)
    r.close()
""",
}


def _version(data: bytes, size: int) -> bool:
    """One whole version: a single 8-digit stamp repeated to ``size`` bytes."""
    return len(data) == size and data == data[:8] * (size // 8)


def _line_recording(data: bytes) -> bool:
    from camlab88.protocols.link.recording import parse_recording

    parse_recording(data.decode("ascii"))  # raises on a torn file
    return data.endswith(b"end 500\n")


def _kill_at_random(child: str, target: Path, delays: list[float]) -> Iterator[float]:
    code = f"TARGET = {str(target)!r}\nSIZE = {SIZE}\n" + child
    for delay in delays:
        proc = subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE,
                                env={**os.environ, "PYTHONPATH": str(ROOT)})
        assert proc.stdout is not None and proc.stdout.readline() == b"ready\n"
        time.sleep(delay)
        proc.send_signal(signal.SIGKILL)
        proc.wait(timeout=30)
        proc.stdout.close()
        yield delay  # the caller checks the files after each kill


@pytest.mark.parametrize("writer", sorted(_CHILD))
def test_a_writer_killed_at_random_leaves_the_old_file_or_the_whole_new_one(
        tmp_path: Path, writer: str) -> None:
    rng = random.Random(f"{SEED} {writer}")
    target = tmp_path / "out.bin"
    names = [Path(f"{target}_{i}") for i in range(3)] if writer == "batch" else [target]
    for name in names:
        name.write_bytes(OLD)
    new = 0
    for _ in _kill_at_random(_CHILD[writer], target,
                             [rng.uniform(0.0, 0.25) for _ in range(KILLS)]):
        for name in names:
            data = name.read_bytes()
            whole = (_line_recording(data) if writer == "line recorder"
                     else _version(data, len(data)) and len(data) >= SIZE // 3 - 8)
            assert data == OLD or whole, (name, len(data))
            new += data != OLD
    assert new > 0, "no kill came after a whole new version: the delays are too short"
    for name in names:  # the next write sweeps every temporary a killed writer left
        write_atomic(name, b"after")
        sweep_stale(name)
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(n.name for n in names)


def test_ca_run_png_killed_at_random_leaves_the_old_picture_or_the_new_one(
        tmp_path: Path) -> None:
    rng = random.Random(f"{SEED} ca run")
    png = tmp_path / "ca.png"
    png.write_bytes(OLD)
    argv = [sys.executable, "-m", "camlab88", "ca", "run", "--rules", "life", "--pattern",
            "glider", "--generations", "40", "--zoom", "24", "--png", str(png)]
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    seen = set()
    for _ in range(4):
        proc = subprocess.Popen(argv, env=env, stdout=subprocess.DEVNULL,
                                stderr=subprocess.DEVNULL)
        time.sleep(rng.uniform(0.5, 3.0))
        proc.send_signal(signal.SIGKILL)
        proc.wait(timeout=30)
        data = png.read_bytes()
        if data != OLD:
            from camlab88.apps.snooker.film.pngcheck import png_size

            assert png_size(data) is not None, "a torn PNG"
        seen.add(data == OLD)
    assert subprocess.run(argv, env=env, capture_output=True, timeout=300,
                          check=False).returncode == 0
    assert sorted(p.name for p in tmp_path.iterdir()) == ["ca.png"]
