"""Every `camlab88 ...` line of README.md and of docs/*.md that can wait for someone — a
command with a window, so with `--headless` — typed as printed without a display, ends:
each document's lines run in order in one fresh directory (the repository's examples/ and
tests/data/ beside them, a private HOME and KAS library), each under a time limit, after
the batch lines that make their inputs (a batch command waits for nobody: the long renders
among them are the area tests' business, not run again here). Whether a line succeeds is
the walkthrough's and each area's tests' business; here a line only has to end (no dialogue
waiting for an answer nobody can give, no --screenshot run that never exits) and never show
a traceback.

Skipped, and named: lines with placeholders (`STREAM`, `[--frames DIR]`, `a|b`), and the
live commands that by design wait for the outside world (a pty, a port, a real tablet)
until Ctrl-C."""

from __future__ import annotations

import os
import re
import shlex
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
DOCUMENTS = ["README.md", *sorted(p.relative_to(ROOT).as_posix()
                                  for p in (ROOT / "docs").glob("*.md"))]
# Generous: a first run compiles numba kernels, the demo plays eight acts headless, and the
# machine may be shared (at load 15 here the demo's acts took minutes); a hang never ends.
LIMIT_S = 600
LITERAL_CAPITALS = {"CAMLAB88"}  # `snooker film --titles CAMLAB88` prints the word itself
LIVE = (  # waits for a program, a port or a device outside by design; ends on Ctrl-C
    ("sigma", "run", "--pty"), ("sigma", "run", "--listen"), ("rainbow", "serve", None),
    ("tablet", "emulate", None), ("tablet", "monitor", None), ("tablet", "calibrate", None),
)


def _lines(text: str) -> list[str]:
    """The command lines of code blocks (indented or fenced) that start with `camlab88 `."""
    out, fenced = [], False
    for line in text.replace("\\\n", " ").splitlines():
        if line.startswith("```"):
            fenced = not fenced
        elif re.match(r"    camlab88 [a-z]", line) or fenced and line.startswith("camlab88 "):
            out.append(line.strip())
    return out


def placeholder(argv: list[str]) -> bool:
    """A synopsis line: `[...]`, `a|b`, `...`, or a capitalised name to fill in."""
    for word in argv:
        if any(c in word for c in "[]|") or "..." in word:
            return True
        caps = re.findall(r"[A-Z][A-Z0-9_]*", word)
        if any(c not in LITERAL_CAPITALS for c in caps if len(c) > 1 or c == word):
            return True
    return False


def live(argv: list[str]) -> bool:
    return any(argv[1:3] == [area, action] and (flag is None or flag in argv)
               for area, action, flag in LIVE)


def can_wait(argv: list[str]) -> bool:
    """A command with a window (its --help offers --headless): it could wait for someone."""
    import contextlib
    import io

    from camlab88.cli import main, normalise_argv

    words = normalise_argv(argv[1:])
    head = words[:1] if words[0] in ("demo", "replay", "figures") else words[:2]
    text = io.StringIO()
    with contextlib.redirect_stdout(text), contextlib.suppress(SystemExit):
        main([*head, "--help"])
    return "--headless" in text.getvalue()


def to_run(document: str) -> list[list[str]]:
    """The lines that can wait, and the earlier lines that write a file one of them needs
    (directly, or through another such line)."""
    from tests.test_readme_walkthrough import written

    keep: list[list[str]] = []
    needed: set[str] = set()
    for argv in reversed(commands(document)):
        made = {f.rstrip("/") for f in written(argv)}
        if can_wait(argv) or made & needed or any(f"library:{w}" in made for w in needed):
            keep.append(argv)
            needed |= {w.rstrip("/") for w in argv[1:]}
            needed |= {w.split("@")[0] for w in argv[1:]}  # kas superimpose SEQ@OFFSET
    return keep[::-1]


def commands(document: str) -> list[list[str]]:
    text = (ROOT / document).read_text(encoding="utf-8")
    out = []
    for line in _lines(text):
        try:
            argv = shlex.split(line, comments=True)
        except ValueError:  # prose that starts with the word, not a command
            continue
        if len(argv) >= 2 and not placeholder(argv) and not live(argv):
            out.append(argv)
    return out


def test_the_selection_is_not_empty_and_skips_only_what_it_says() -> None:
    assert len(commands("README.md")) >= 60
    assert live(["camlab88", "sigma", "run", "--model", "t5688", "--pty"])
    assert not live(["camlab88", "sigma", "run", "--in", "x.sig"])
    assert live(["camlab88", "tablet", "monitor", "emulated:summa-mm"])
    assert placeholder(["camlab88", "sigma", "render", "--in", "STREAM"])
    assert placeholder(["camlab88", "kas", "inbetween", "A", "B"])
    assert not placeholder(["camlab88", "snooker", "film", "--titles", "CAMLAB88"])
    assert not placeholder(["camlab88", "snooker", "simulate", "--shot", "cue", "5", "2"])
    assert can_wait(["camlab88", "snooker", "camera", "my.ccl", "x.json"])
    assert can_wait(["camlab88", "replay", "x.session"])
    assert not can_wait(["camlab88", "snooker", "render", "a.checkpoint", "b.views"])
    run = [" ".join(a[1:3]) for a in to_run("README.md")]
    assert "snooker camera" in run and "ca program" in run and "snooker render" not in run


def _env(home: Path) -> dict[str, str]:
    env = {k: v for k, v in os.environ.items()
           if k not in ("DISPLAY", "WAYLAND_DISPLAY", "SDL_VIDEODRIVER")}
    env.update(HOME=str(home), CAMLAB88_KAS_LIBRARY=str(home / "library"),
               PYTHONFAULTHANDLER="1")
    return env


def _camlab88() -> list[str]:
    script = Path(sys.executable).with_name("camlab88")
    return [str(script)] if script.exists() else [sys.executable, "-m", "camlab88"]


def _run_within(argv: list[str], cwd: Path, env: dict[str, str]) -> str | None:
    """The line's stderr, or None when it was still running after LIMIT_S (then it and
    every process it started, a render's workers too, are ended: its own session)."""
    import signal

    with subprocess.Popen([*_camlab88(), *argv[1:]], cwd=cwd, env=env,
                          stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                          stderr=subprocess.PIPE, text=True, start_new_session=True) as proc:
        try:
            return proc.communicate(timeout=LIMIT_S)[1]
        except subprocess.TimeoutExpired:
            os.killpg(proc.pid, signal.SIGKILL)
            proc.communicate()
            return None


@pytest.mark.parametrize("document", [d for d in DOCUMENTS if to_run(d)])
def test_every_command_of_the_document_ends(document: str, tmp_path: Path) -> None:
    shutil.copytree(ROOT / "examples", tmp_path / "examples")
    shutil.copytree(ROOT / "tests" / "data", tmp_path / "tests" / "data")
    shutil.copytree(ROOT / "benchmarks" / "patterns", tmp_path / "benchmarks" / "patterns")
    for d in ("sigma", "kas", "snooker", "ca"):  # the walkthrough's `mkdir -p` lines
        (tmp_path / d).mkdir()
    (tmp_path / "home").mkdir()
    env = _env(tmp_path / "home")
    hung, tracebacks = [], []
    for argv in to_run(document):
        err = _run_within(argv, tmp_path, env)
        if err is None:
            hung.append(shlex.join(argv))
        elif "Traceback (most recent call last)" in err:
            tracebacks.append(f"{shlex.join(argv)}\n{err[-2000:]}")
    assert not hung, f"{document}: still running after {LIMIT_S} s:\n" + "\n".join(hung)
    assert not tracebacks, f"{document}: a traceback:\n" + "\n\n".join(tracebacks)
