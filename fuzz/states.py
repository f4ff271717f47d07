"""Mutated whole-program states (``.c88state``) loaded by the real commands, in process,
through ``--load-state FILE``: every outcome must be a clean run (status 0) or a refusal
(status 1 or 2) on one line naming the file — never a traceback, a hang or memory without
bound.

A state is an envelope (emulator.machine.state_file) whose header holds the program's
declared values and whose deflated parts hold the machines' own states, so a byte flipped
in the file is almost always refused by zlib's checksum and goes no deeper. The fuzzers
therefore work on the state *opened*: one JSON line (the header), then the parts inflated,
each length-prefixed. ``close_state`` packs it again before the command reads it, so a
mutation lands in a value, the harness's place or a machine's state and is read by the
schema check and the program itself.
"""

from __future__ import annotations

import contextlib
import io
import json
import os
import random
import select
import signal
import traceback
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parents[1]
STREAM = ROOT / "examples" / "sigma" / "pgplot_goc.sig"

# program -> a short headless run of it (a state is saved from it and loaded into it). The
# editors' states are their input log (emulator.harness.input_log): a load runs the session
# again, so their runs are short; they and the players of files (kas view, snooker
# visualise and replay) run in editor_inputs(), their files named as they are there (the
# actors editor's status names its file as given once it has saved, `s` below, and its
# state's picture with it: a state of it loads only where that name reads the same).
PROGRAMS: dict[str, list[str]] = {
    "ca-program": ["ca", "program", "--pattern", "glider", "--headless", "--stop-after", "2"],
    "snooker-play": ["snooker", "play", "--headless", "--stop-after", "2"],
    "sigma-run": ["sigma", "run", "--headless", "--in", str(STREAM), "--seconds", "0.3"],
    "rainbow-run": ["rainbow", "run", "--headless", "--stop-after", "3", "--demo", "pads"],
    "kas-edit": ["kas", "edit", "key.kas", "--script", "edit_all.txt", "--headless", "--seed",
                 "1"],
    "kas-path": ["kas", "path", "flag_a.kas", "flag_b.kas", "--out", "flag_path.kas",
                 "--no-library", "--headless", "--script", "fig-3.6.script"],
    "kas-paint": ["kas", "paint", "face.kas", "--headless", "--script", "fig-3.7.script"],
    "snooker-camera": ["snooker", "camera", "cam.ccl", "shot.cp", "--headless", "--events",
                       "camera.events"],
    "ca-actors": ["ca", "actors", "m.actors", "--headless", "--events", "actors.events"],
    "kas-view": ["kas", "view", "seq.kas", "--headless", "--every"],
    "snooker-visualise": ["snooker", "visualise", "pink_shot.cp", "example.views", "--headless"],
    "snooker-replay": ["snooker", "replay", "pink_shot.cp", "--headless", "--last", "20"],
}
SAVE_AT = {"kas-view": ["--at", "0.3"]}  # its line test ends with nothing left to save
IN_INPUTS = frozenset(["kas-edit", "kas-path", "kas-paint", "snooker-camera", "ca-actors",
                       "kas-view", "snooker-visualise", "snooker-replay"])
COMMANDS = {"camlab88 ca program": "ca-program", "camlab88 snooker": "snooker-play",
            "camlab88 sigma run": "sigma-run", "camlab88 rainbow run": "rainbow-run",
            "camlab88 kas edit": "kas-edit", "camlab88 kas path": "kas-path",
            "camlab88 kas paint": "kas-paint", "camlab88 snooker camera": "snooker-camera",
            "camlab88 ca actors": "ca-actors", "camlab88 kas view": "kas-view",
            "camlab88 snooker visualise": "snooker-visualise",
            "camlab88 snooker replay": "snooker-replay"}  # as a state names its program
_LENGTH = 4  # bytes of each part's length prefix in an opened state


class Hang(Exception):
    """A command took longer than its bound."""


def _alarm(signum: int, frame: object) -> None:
    raise Hang


def run_cli(argv: list[str], limit: float) -> tuple[int, str]:
    """``camlab88.cli.main(argv)`` in process: (exit status, stderr). A command's one-line
    refusal (SystemExit with a message) counts as status 2, as ``camlab88.cli.entry`` ends
    it; any other exception propagates (a traceback is a finding); Hang after ``limit`` s."""
    from camlab88.cli import main

    err = io.StringIO()
    old = signal.signal(signal.SIGALRM, _alarm)
    signal.setitimer(signal.ITIMER_REAL, limit)
    try:
        with contextlib.redirect_stderr(err), contextlib.redirect_stdout(io.StringIO()):
            try:
                code = main(argv)
            except SystemExit as exc:
                if isinstance(exc.code, str):
                    err.write(exc.code + "\n")
                code = exc.code if isinstance(exc.code, int) else 2
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, old)
    return code, err.getvalue()


def run_program(program: str, more: list[str], limit: float) -> tuple[int, str]:
    """``program``'s short run with ``more`` arguments (one reading files in editor_inputs()
    there)."""
    if program not in IN_INPUTS:
        return run_cli([*PROGRAMS[program], *more], limit)
    old = Path.cwd()
    os.chdir(editor_inputs())
    try:
        return run_cli([*PROGRAMS[program], *more], limit)
    finally:
        os.chdir(old)


_INPUTS: list[Path] = []  # (the folder, once made)


def editor_inputs() -> Path:
    """A folder of the editors' input files, made once per process and removed at its exit
    (the kas editors' from the shipped recordings; the camera tool's from its test data;
    short scripts and an actors file written here). The editors write in it too (kas path's
    --out)."""
    if _INPUTS:
        return _INPUTS[0]
    import atexit
    import shutil
    import tempfile

    from camlab88.protocols.session import read

    folder = Path(tempfile.mkdtemp(prefix="camlab88-fuzz-editors-"))
    atexit.register(shutil.rmtree, folder, True)
    for recording in ("tests/data/sessions/kas_edit.session", "examples/figures/fig-3.6.session",
                      "examples/figures/fig-3.7.session", "examples/figures/fig-6.7.session"):
        for name, data in read(ROOT / recording).files.items():
            (folder / name).write_bytes(data)
    camera = ROOT / "tests" / "data" / "snooker_camera"
    for name, data in _EDITOR_TEXTS.items():
        (folder / name).write_text(data)
    (folder / "cam.ccl").write_bytes((camera / "thesis_example.ccl").read_bytes())
    (folder / "shot.cp").write_bytes((camera / "pink_shot.checkpoint").read_bytes())
    (folder / "seq.kas").write_bytes((ROOT / "tests" / "data" / "states" / "seq.kas").read_bytes())
    _INPUTS.append(folder)
    return folder


# the camera tool's and actors editor's sessions (as tests/states/test_hostile_states.py's)
_EDITOR_TEXTS = {
    "camera.events": "wait 10\nkey down\ntype veiw\nwait 10\nkey down\ntype xx\nwait 10\n",
    "m.actors": "rules maze\nactor 1 wall\n  colour 9 9 9\n  box 1 1 1\nend\n",
    "actors.events": "wait 5\nclick left 32 472\nwait 3\nkey s\nwait 3\n"
                     "click left 96 300\nwait 5\n",
}


def save_state(program: str, path: Path, limit: float = 300.0) -> bytes:
    """A real state of ``program``: its short run, saved at the end (or at SAVE_AT)."""
    code, err = run_program(program, ["--save-state", str(path.absolute()),
                                      *SAVE_AT.get(program, [])], limit)
    if code != 0:
        raise RuntimeError(f"{program}: could not save a state: {err}")
    return path.read_bytes()


def load_state(program: str, path: Path, limit: float) -> tuple[int, str]:
    """``program``'s short run continued from the state file ``path``."""
    return run_program(program, ["--load-state", str(path.absolute())], limit)


def verdict(path: Path, code: int, err: str) -> str | None:
    """None if the outcome keeps the rule; else what is wrong with it."""
    if "Traceback" in err:
        return f"a traceback (status {code}): {err[-400:]}"
    if code == 0:
        return None
    if code not in (1, 2):
        return f"exit status {code}: {err[-400:]}"
    if str(path) not in err:
        return f"a refusal (status {code}) that does not name the file: {err[-400:]!r}"
    return None


def check_isolated(program: str, data: bytes, path: Path, limit: float,
                   memory_mb: float) -> str | None:
    """Load ``data`` (a state file's bytes) into ``program`` in a forked copy of this
    process; None if the outcome keeps the rule, else the finding (a traceback, a bad
    status, a refusal not naming the file, no answer within ``limit`` s, or more than
    ``memory_mb`` MB above this process). A load no longer leaks into the next one (a
    refused state changes nothing, and none is written into module-level objects:
    tests/states/test_refused_loads.py); the fork stays for what one process cannot do:
    kill a run stuck in compiled code (the alarm cannot reach it) and bound one load's
    memory without ending the fuzzing process."""
    from fuzz.engine import rss_now_mb

    base = rss_now_mb()
    r, w = os.pipe()
    pid = os.fork()
    if pid == 0:  # the child: report and leave at once (no cleanup of the parent's state)
        os.close(r)
        try:
            path.write_bytes(data)
            try:
                code, err = load_state(program, path, limit)
                found = verdict(path, code, err)
            except Hang:
                found = f"no answer within {limit:g} s"
            except BaseException as exc:  # anything escaping is the finding
                found = "a traceback: " + "".join(traceback.format_exception(exc))[-1500:]
            os.write(w, (found or "").encode("utf-8", "replace"))
        finally:
            os._exit(0)
    os.close(w)
    try:
        ready, _, _ = select.select([r], [], [], limit + 30.0)
        if not ready:  # stuck where the child's alarm cannot reach (compiled code)
            os.kill(pid, signal.SIGKILL)
        with os.fdopen(r, "rb") as fh:
            out = fh.read().decode("utf-8", "replace")
    finally:
        _, status, usage = os.wait4(pid, 0)
    if not ready:
        return f"no answer within {limit + 30:g} s (killed)"
    if status != 0:
        return f"the child ended with wait status {status}: {out}"
    grew = usage.ru_maxrss / 1024 - base
    if grew > memory_mb:
        return f"memory grew {grew:.0f} MB"
    return out or None


# ------------------------------------------------------------------ opened states
def open_state(data: bytes) -> bytes:
    """A state file as one JSON line (its header: the program, its arguments, the harness's
    place, the declared values, and the names of its parts), then its binary parts inflated
    (the machines' own states, arrays), each length-prefixed: a mutation lands in a value or
    a part, not in deflate's checksum."""
    from camlab88.emulator.machine.state_file import unpack

    head, blobs = unpack(data, "program")
    line = dict(_bare(head), parts=list(blobs))
    out = bytearray(json.dumps(line, sort_keys=True).encode("utf-8") + b"\n")
    for part in blobs.values():
        out += len(part).to_bytes(_LENGTH, "big") + part
    return bytes(out)


def close_state(opened: bytes) -> bytes:
    """The state file an opened state stands for. A header line that is no longer JSON, or
    not a mapping naming its parts, is passed on as it is (the loader refuses it); parts
    whose lengths no longer add up are cut where the bytes end."""
    from camlab88.emulator.machine.state_file import pack

    line, _, rest = opened.partition(b"\n")
    try:
        head = json.loads(line.decode("utf-8"))
        names = head.pop("parts")
        if not (isinstance(names, list) and all(isinstance(n, str) for n in names)):
            raise TypeError
    except (UnicodeDecodeError, ValueError, KeyError, TypeError, AttributeError,
            RecursionError):
        return opened
    parts: dict[str, bytes] = {}
    k = 0
    for name in names:
        n = int.from_bytes(rest[k:k + _LENGTH], "big")
        parts[name] = rest[k + _LENGTH:k + _LENGTH + n]
        k += _LENGTH + n
    return pack("program", head, parts)


def program_of(opened: bytes) -> str:
    """The program an opened state names (the first one if it names none we run)."""
    line = opened.partition(b"\n")[0]
    for command, name in COMMANDS.items():
        if f'"program": "{command}"'.encode() in line:
            return name
    return next(iter(PROGRAMS))


def _bare(head: dict[str, Any]) -> dict[str, Any]:
    """A header without what ``pack`` writes itself."""
    return {k: v for k, v in head.items() if k not in ("blobs", "format_version", "device")}


# ------------------------------------------------------------------ tree edits
# what a value in a state's tree may be replaced with: other types, edges, huge sizes
ODD_VALUES: tuple[Any, ...] = (
    None, True, False, 0, -1, 1, 2**31, -(2**63), 2**64, 10**30, 0.5, -1e308, 1e308,
    "", "x", "0", "1/0", "-1", "nan", [], {}, [0], [[]], {"": 0}, {"O": "builtins:object"},
    {"R": 0}, {"R": 10**9}, {"L": []}, {"T": [1, 2]}, {"A": "x"}, [-1, -1, -1, -1],
    {"code": ["camlab88.base.atomicfile", "write_atomic", 1]}, "/tmp/x", "../../x",
    ["a0", [2**40]], [10**300, 1], [1, 0],
)


def scalar_places(tree: Any) -> list[tuple[Any, Any]]:
    """Every (container, key) whose value is a scalar or an empty container, in order."""
    out: list[tuple[Any, Any]] = []
    stack = [tree]
    while stack:
        node = stack.pop()
        items = node.items() if isinstance(node, dict) else enumerate(node)
        for key, value in items:
            if isinstance(value, dict | list) and value:
                stack.append(value)
            else:
                out.append((node, key))
    return out


def edit_tree(data: bytes, edits: list[tuple[int, Any]]) -> bytes:
    """The state file with values of its header replaced: each edit is (a place's
    number, taken modulo the number of places; the new value)."""
    opened = open_state(data)
    line, _, rest = opened.partition(b"\n")
    heads = json.loads(line)
    for index, value in edits:
        places = scalar_places(heads)
        node, key = places[index % len(places)]
        node[key] = json.loads(json.dumps(value))  # a copy: ODD_VALUES are shared, and a
        # later edit inside a shared one could make the tree hold itself
    return close_state(json.dumps(heads).encode("utf-8") + b"\n" + rest)


def random_edits(rng: random.Random, count: int) -> list[tuple[int, Any]]:
    """``count`` edits for ``edit_tree``, from ``rng``."""
    out: list[tuple[int, Any]] = []
    for _ in range(count):
        value = rng.choice(ODD_VALUES)
        if rng.random() < 0.3:  # a nearby number instead: passes type checks, not range ones
            value = rng.choice((-1, 1, 7, 255, 256, 65535, 65536)) * rng.choice((1, -1))
        out.append((rng.randrange(1 << 30), value))
    return out
