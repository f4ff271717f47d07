"""Helpers for the save-state tests: every frame's hash from in-process runs, inputs taken
from the shipped recordings (by content), and the save-at-k / load / continue comparison."""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

import pytest

from camlab88.cli import main
from camlab88.emulator.harness import plugins
from camlab88.emulator.harness.loop import Plugin
from camlab88.emulator.harness.session_record import screen_hash
from camlab88.emulator.machine.state_file import unpack
from camlab88.protocols.session import read

ROOT = Path(__file__).resolve().parents[2]
RECORDINGS = sorted([*(ROOT / "examples" / "figures").glob("*.session"),
                     *(ROOT / "tests" / "data" / "sessions").glob("*.session")])


class HashLog(Plugin):
    """Every frame shown, by its number: the hash of its pixels; and, under ``"ticks"``,
    how many ticks this run itself made (a loaded run must not make the saved ones again)."""

    def __init__(self, log: dict) -> None:
        self.log = log
        log["ticks"] = 0

    def on_frame(self, harness, frame) -> None:
        self.log[harness.frames_shown] = screen_hash(frame)

    def post_tick(self, harness) -> None:
        self.log["ticks"] += 1


@contextmanager
def frame_logs(monkeypatch: pytest.MonkeyPatch) -> Iterator[list[dict[int, str]]]:
    """One {frame: hash} per harness run while the context is active."""
    runs: list[dict[int, str]] = []
    real = plugins.standard_plugins

    def with_log(options):
        runs.append({})
        return [*real(options), HashLog(runs[-1])]

    monkeypatch.setattr(plugins, "standard_plugins", with_log)
    yield runs


def inputs_of(recording: str, into: Path) -> Path:
    """The input files a shipped recording carries, written into ``into``."""
    for name, data in read(ROOT / recording).files.items():
        (into / name).write_bytes(data)
    return into


def saved_place(state: Path) -> tuple[int, int]:
    """(ticks, frames shown) when the state was saved."""
    head, _ = unpack(state.read_bytes(), "program")
    return int(head["harness"][0]), int(head["harness"][1])


def assert_continues(monkeypatch: pytest.MonkeyPatch, argv: list[str], at: float,
                     state: Path) -> tuple[dict[int, str], dict[int, str]]:
    """Run ``argv`` saving a state at ``at`` s (the run goes on), then load it into a fresh
    program: the frames after the save are the uninterrupted run's."""
    with frame_logs(monkeypatch) as runs:
        assert main([*argv, "--save-state", str(state), "--at", repr(at)]) == 0
        assert state.is_file(), "no state was saved"
        assert main([*argv, "--load-state", str(state)]) == 0
    full, rest = runs
    ticks, k = saved_place(state)
    assert 0 < ticks < full["ticks"], "the state was not saved inside the run"
    assert rest.pop("ticks") == full.pop("ticks") - ticks, "the loaded run ran from the start"
    assert rest, "the loaded run showed nothing"
    assert sorted(rest) == [n for n in sorted(full) if n > k]
    for n in rest:
        assert rest[n] == full[n], f"frame {n} differs after loading the state of frame {k}"
    return full, rest


def assert_file_dialogue_refused(events: Path, dialogue: str, capsys) -> None:
    """``ca program`` run on ``events`` with --save-state beside them fails in one line
    naming the state file (status 1): ``dialogue`` has been given a file name, which a
    state never holds."""
    from camlab88.cli import main

    state = events.parent / "c.c88state"
    code = main(["ca", "program", "--headless", "--pattern", "glider", "--events",
                 str(events), "--save-state", str(state)])
    err = capsys.readouterr().err.strip().splitlines()
    assert code == 1 and not state.exists()
    assert err[-1].endswith(f"the dialogue {dialogue!r} has been given a file name (it is "
                            "saved once it has ended)"), err
    assert str(state) in err[-1]
