"""CI's fuzz run: every corpus file and a short seeded mutated run of every format,
through the in-process targets and through the real command line, with no traceback, no input
taking over 20 s and no memory growth over 1 GB. The long coverage-guided runs are by hand
(``python fuzz/run.py --seconds N``; figures in docs/reliability.md)."""

from __future__ import annotations

import contextlib
import io
import random
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path

import pytest

from camlab88.cli import main
from fuzz.engine import Hang, _alarm, _rss_mb, fuzz
from fuzz.mutate import mutate
from fuzz.targets import CORPUS, TARGETS

ROOT = Path(__file__).resolve().parents[2]
IN_PROCESS_INPUTS = 150  # per format: 31 formats, about 4500 inputs
# the terminal draws every order of a 7 KB demo stream; a command runs for each state
SLOW = {"sigma-stream": 40, "cli-load-state": 12}
CLI_INPUTS = 40  # mutated inputs per command line below, besides the corpus files
HANG_S = 20.0
MEMORY_MB = 1024.0
GLIDER = ROOT / "apps" / "ca" / "library" / "glider.cells"
LIFE = ROOT / "apps" / "ca" / "library" / "life.rules"
WALK_A = ROOT / "apps" / "kas" / "library" / "walk_a.kas"
WALK_B = ROOT / "apps" / "kas" / "library" / "walk_b.kas"

Argv = Callable[[Path, Path], list[str]]


def _walk4(scratch: Path) -> str:
    """A 4-frame walk sequence (what the kas-paint-ops seeds were painted on)."""
    path = scratch / "walk4.kas"
    if not path.exists():
        from camlab88.apps.kas import files
        from camlab88.apps.kas.inbetween import inbetween

        lib = ROOT / "apps" / "kas" / "library"
        files.save_sequence(path, inbetween(files.load_keyframe(WALK_A), files.load_keyframe(
            WALK_B), path=files.load_path(lib / "walk_path.kas"), frames=4))
    return str(path)


# corpus format -> how the command line takes such a file (input path, scratch directory)
COMMANDS: dict[str, Argv] = {
    "rainbow-scene": lambda f, d: ["rainbow", "render", str(f), "--out", str(d / "o.png")],
    "rainbow-recording": lambda f, d: ["rainbow", "replay", str(f), "--headless"],
    "link-recording": lambda f, d: ["link", "dump", str(f)],
    "sigma-stream": lambda f, d: ["sigma", "render", "--in", str(f), "--out", str(d / "o.png")],
    "kas-keyframe": lambda f, d: ["kas", "inbetween", str(f), str(WALK_B), "--frames", "3",
                                  "--out", str(d / "o.kas")],
    "kas-path": lambda f, d: ["kas", "inbetween", str(WALK_A), str(WALK_B), "--path", str(f),
                              "--frames", "3", "--out", str(d / "o.kas")],
    "kas-timing": lambda f, d: ["kas", "inbetween", str(WALK_A), str(WALK_B), "--timing",
                                str(f), "--out", str(d / "o.kas")],  # ticks fix the count
    "snooker-checkpoint": lambda f, d: ["snooker", "replay", str(f), "--headless",
                                        "--stop-after", "2"],
    "snooker-session": lambda f, d: ["snooker", "simulate", "--from", str(f), "--shot", "cue",
                                     "0.2", "0", "--max-seconds", "2", "--out",
                                     str(d / "o.cp")],
    "ca-rules": lambda f, d: ["ca", "run", "--rules", str(f), "--pattern", str(GLIDER),
                              "--generations", "2"],
    "ca-native": lambda f, d: ["ca", "convert", str(f), str(d / "o.rle")],
    "ca-rle": lambda f, d: ["ca", "run", "--rules", str(LIFE), "--pattern", str(f),
                            "--generations", "2"],
    "ca-cells": lambda f, d: ["ca", "convert", str(f), str(d / "o.pat")],
    "ca-mc": lambda f, d: ["ca", "run", "--rules", str(LIFE), "--pattern", str(f),
                           "--generations", "2"],
    "ca-log": lambda f, d: ["ca", "replay", "--script", str(f), "--generation", "2"],
    "kas-paint-ops": lambda f, d: ["kas", "paint", _walk4(d), "--ops", str(f), "--headless",
                                   "--replay"],
    "session-recording": lambda f, d: ["replay", str(f), "--check", "--headless"],
    "ca-actors": lambda f, d: ["ca", "film", "life", "glider", "--actors", str(f),
                               "--generations", "1", "--frames-per-generation", "1",
                               "--size", "16x16", "--samples", "1", "--workers", "1",
                               "--out", str(d / "o.gif")],
}
# corpus files that are for the reader only: every_record.session's screen hashes are made
# up (it is there to give the reader input events), so a --check replay rightly fails it
READER_ONLY = {"session-recording": {"every_record.session"}}
SUFFIX = {"ca-native": ".pat", "ca-rle": ".rle", "ca-cells": ".cells", "ca-rules": ".rules",
          "ca-mc": ".mc",
          "snooker-checkpoint": ".cp", "snooker-session": ".json", "rainbow-scene": ".json",
          "kas-keyframe": ".kas", "kas-path": ".kas", "kas-timing": ".kas",
          "kas-paint-ops": ".ops", "session-recording": ".session", "ca-actors": ".actors"}


@pytest.mark.parametrize("name", sorted(TARGETS))
def test_every_format_has_seeds_and_survives_a_mutated_run(name: str, tmp_path) -> None:
    target = TARGETS[name]
    assert target.seeds(), f"no seed files in {target.corpus}"
    report = fuzz(target, inputs=SLOW.get(name, IN_PROCESS_INPUTS), seed=1, timeout=HANG_S,
                  memory_mb=MEMORY_MB, findings=tmp_path)
    assert report.findings == [], report.findings


# the first run of a command compiles its numba kernels (a fresh cache per test run): the
# corpus files get this long, the mutated inputs HANG_S
WARM_UP_S = 300.0


def _run_cli(argv: list[str], limit: float = HANG_S) -> tuple[int, str]:
    """main() in process: its exit status and stderr; any escaping exception fails."""
    err, out = io.StringIO(), io.StringIO()
    import signal

    old = signal.signal(signal.SIGALRM, _alarm)
    signal.setitimer(signal.ITIMER_REAL, limit)
    try:
        with contextlib.redirect_stderr(err), contextlib.redirect_stdout(out):
            try:
                code = main(argv)
            except SystemExit as exc:  # argparse and the commands' own clean exits
                code = exc.code if isinstance(exc.code, int) else 1
    except Hang:
        pytest.fail(f"no answer within {limit:g} s: camlab88 {' '.join(argv)}")
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, old)
    return code, err.getvalue()


@pytest.mark.parametrize("name", sorted(COMMANDS))
def test_the_command_line_takes_mutated_files_without_a_traceback(name: str, tmp_path) -> None:
    skip = READER_ONLY.get(name, set())
    seeds = [p.read_bytes() for p in sorted(TARGETS[name].corpus.iterdir()) if p.name not in skip]
    rng = random.Random(f"cli:{name}")
    inputs = seeds + [mutate(rng.choice(seeds), rng) for _ in range(CLI_INPUTS)]
    path = tmp_path / f"input{SUFFIX.get(name, '')}"
    base = _rss_mb()
    for k, data in enumerate(inputs):
        path.write_bytes(data)
        code, err = _run_cli(COMMANDS[name](path, tmp_path),
                             WARM_UP_S if k < len(seeds) else HANG_S)
        assert "Traceback" not in err, err
        if k < len(seeds):
            assert code == 0, f"corpus file {k} of {name} was refused: {err}"
        else:
            assert code in (0, 1, 2), (code, err)
            assert code == 0 or err.strip(), "a refusal must say why"
        assert _rss_mb() - base < MEMORY_MB, f"memory grew past {MEMORY_MB} MB on input {k}"


@pytest.mark.parametrize("name", ["rainbow-scene", "link-recording", "ca-rle"])
def test_a_real_process_reports_bad_input_without_a_traceback(name: str, tmp_path) -> None:
    """A few real subprocesses: what a user sees, start-up and exit code included."""
    rng = random.Random(f"process:{name}")
    seed = TARGETS[name].seeds()[0]
    path = tmp_path / f"input{SUFFIX.get(name, '')}"
    for _ in range(2):
        path.write_bytes(mutate(seed, rng) + b"\xff")  # never valid UTF-8
        proc = subprocess.run([sys.executable, "-m", "camlab88", *COMMANDS[name](path, tmp_path)],
                              capture_output=True, text=True, timeout=120, cwd=ROOT)
        assert proc.returncode in (1, 2), proc
        assert "Traceback" not in proc.stderr and str(path) in proc.stderr, proc.stderr


def test_the_corpus_has_a_directory_for_every_target() -> None:
    assert {p.name for p in CORPUS.iterdir() if p.is_dir()} == set(TARGETS)
