"""The session-recording corpus's recording begun from a state (fuzz/make_corpus.py,
``_resumed_recording``: ``sigma run --load-state s.c88state --record``): its header names
the state, its file record carries it by content, and ``camlab88 replay --check`` agrees
with it. Damaged, it gives the documented status (docs/exit_status.md) and no traceback:
damage the reader sees (the file record's data or checksum, a cut, the ``--load-state``
taken out of the command line) is one line naming ``file:line``, status 2; a state that
reads as a file but that its program refuses (cut, another version, other inputs, a code
reference, missing) is the replay's one verdict line naming the recording, status 1, and
below it what the replayed program said, naming the state (docs/reliability.md,
"Replays")."""

from __future__ import annotations

import json
from collections.abc import Callable
from pathlib import Path

import pytest

from camlab88.emulator.harness.sigma_line import SigmaLineTarget
from camlab88.emulator.machine.state_file import pack, unpack
from camlab88.protocols.session.format import dumps, read
from fuzz.make_corpus import RESUMED
from fuzz.states import run_cli
from fuzz.targets import CORPUS

SEED = CORPUS / "session-recording" / RESUMED
STATE = "s.c88state"
LIMIT_S = 60.0


def test_the_seed_begins_from_a_state_it_carries_by_content() -> None:
    rec = read(SEED)
    assert rec.argv[-2:] == ["--load-state", STATE]
    head, _ = unpack(rec.files[STATE], "program")
    assert head["program"] == "camlab88 sigma run"
    # (a state version raised since: make the corpus again, or its replay fails)
    assert head["state_version"] == SigmaLineTarget.STATE_VERSION


def _replay(tmp_path: Path, text: str) -> tuple[int, list[str]]:
    path = tmp_path / "r.session"
    path.write_text(text)
    code, err = run_cli(["replay", str(path), "--check", "--headless"], LIMIT_S)
    assert "Traceback" not in err, err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["r.session"]  # (nothing beside)
    return code, [line for line in err.splitlines() if line.strip()]


def test_the_seed_replays_with_check(tmp_path: Path) -> None:
    code, lines = _replay(tmp_path, SEED.read_text())
    assert code == 0 and lines == [], lines


def _lines() -> list[str]:
    return SEED.read_text().splitlines(keepends=True)


def _state_record(change: Callable[[dict], None]) -> str:
    lines = _lines()
    at = next(i for i, line in enumerate(lines) if f'"name":"{STATE}"' in line)
    record = json.loads(lines[at])
    change(record)
    lines[at] = json.dumps(record, separators=(",", ":")) + "\n"
    return "".join(lines)


def _flip(record: dict) -> None:
    data = record["data"]
    record["data"] = data[:40] + ("B" if data[40] == "A" else "A") + data[41:]


READER_DAMAGE: dict[str, Callable[[], str]] = {
    "the state's data": lambda: _state_record(_flip),
    "the state's checksum": lambda: _state_record(lambda r: r.update(sha256="0" * 64)),
    "a cut in the state's record": lambda: "".join(_lines())[:len(_lines()[0]) + 2000],
    "--load-state taken out": lambda: SEED.read_text().replace(f',"--load-state","{STATE}"',
                                                               ""),
}


@pytest.mark.parametrize("damage", sorted(READER_DAMAGE))
def test_damage_the_reader_sees_is_one_line_naming_the_line_status_2(tmp_path: Path,
                                                                     damage: str) -> None:
    code, lines = _replay(tmp_path, READER_DAMAGE[damage]())
    assert code == 2 and len(lines) == 1, (code, lines)
    assert lines[0].startswith(f"camlab88 replay: {tmp_path / 'r.session'}:"), lines


def _with_state(change: Callable[[bytes], bytes | None]) -> str:
    rec = read(SEED)
    data = change(rec.files[STATE])
    if data is None:
        del rec.files[STATE]
    else:
        rec.files[STATE] = data
    return dumps(rec)


def _head(**changes) -> Callable[[bytes], bytes]:
    def change(data: bytes) -> bytes:
        head, parts = unpack(data, "program")
        return pack("program", {k: v for k, v in head.items() if k not in (
            "blobs", "format_version", "device")} | changes, parts)
    return change


STATE_DAMAGE: dict[str, tuple[Callable[[bytes], bytes | None], str]] = {
    "cut in half": (lambda d: d[:len(d) // 2], "not loaded"),
    "another version": (_head(state_version=9), "it is a state of version 9"),
    "other inputs": (_head(args=["sigma", "run", "--in", "/etc/passwd"]),
                     "saved with other arguments"),
    "a code reference": (_head(values={"code": ["camlab88.base.atomicfile", "write_atomic",
                                                1]}), "not the declared ones"),
    "missing": (lambda d: None, f"cannot read {STATE}"),
}


@pytest.mark.parametrize("damage", sorted(STATE_DAMAGE))
def test_a_state_its_program_refuses_is_the_verdict_line_status_1(tmp_path: Path,
                                                                  damage: str) -> None:
    change, said = STATE_DAMAGE[damage]
    code, lines = _replay(tmp_path, _with_state(change))
    assert code == 1, (code, lines)
    verdict, *program = lines
    assert verdict.startswith(f"camlab88 replay: {tmp_path / 'r.session'}: "), lines
    assert program and all(line.startswith("  the replayed program said: ")
                           for line in program), lines
    assert said in program[-1] and STATE in program[-1], lines
