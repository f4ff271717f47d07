"""Hostile save states, by attack class, against every program that saves its state (issue
38: a state from a stranger ran code of the attacker's choosing). Each program's real state
is saved, then attacked and loaded back through the command line's ``--load-state`` in this
process, and through a recording that carries it (``camlab88 replay``). Whatever the attack,
after the load:

- no file has appeared outside the test's directory (every path a state could hold points
  into a watched directory beside it, or to an absolute path that must stay absent);
- no module has been newly imported (``sys.modules`` before and after);
- the run went on (status 0) or was refused with the documented status (2 for a state
  refused; 1 for a replay whose recorded program failed) and one line naming the file.
"""

from __future__ import annotations

import json
import os
import sys
import uuid
import zlib
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import pytest

from camlab88.emulator.machine.state_file import MAGIC, pack
from camlab88.protocols.session.format import dumps, read
from fuzz.states import close_state, open_state, run_cli
from tests.states.support import inputs_of

LIMIT_S = 60.0
HERE = Path(__file__).resolve().parent


def _visualise(d: Path) -> list[str]:
    inputs_of("examples/figures/fig-6.7.session", d)
    return ["snooker", "visualise", "pink_shot.cp", "example.views", "--headless"]


def _replay(d: Path) -> list[str]:
    inputs_of("examples/figures/fig-6.7.session", d)
    return ["snooker", "replay", "pink_shot.cp", "--headless", "--last", "20"]


def _sigma(d: Path) -> list[str]:
    inputs_of("tests/data/sessions/sigma_run.session", d)
    return ["sigma", "run", "--headless", "--in", "picture.sigma", "--seconds", "0.4"]


def _kas_view(d: Path) -> list[str]:
    assert run_cli(["kas", "demo", "--out", "seq.kas"], LIMIT_S)[0] == 0
    return ["kas", "view", "seq.kas", "--headless", "--every"]


def _kas_edit(d: Path) -> list[str]:
    inputs_of("tests/data/sessions/kas_edit.session", d)
    return ["kas", "edit", "key.kas", "--script", "edit_all.txt", "--headless", "--seed", "1"]


def _kas_path(d: Path) -> list[str]:
    inputs_of("examples/figures/fig-3.6.session", d)
    return ["kas", "path", "flag_a.kas", "flag_b.kas", "--out", "flag_path.kas",
            "--no-library", "--headless", "--script", "fig-3.6.script"]


def _kas_paint(d: Path) -> list[str]:
    inputs_of("examples/figures/fig-3.7.session", d)
    return ["kas", "paint", "face.kas", "--headless", "--script", "fig-3.7.script"]


def _camera(d: Path) -> list[str]:
    data = HERE.parent / "data" / "snooker_camera"
    (d / "cam.ccl").write_bytes((data / "thesis_example.ccl").read_bytes())
    (d / "shot.cp").write_bytes((data / "pink_shot.checkpoint").read_bytes())
    (d / "e.events").write_text("wait 10\nkey down\ntype veiw\nwait 10\nkey down\n"
                                "type xx\nwait 10\n")
    return ["snooker", "camera", "cam.ccl", "shot.cp", "--headless", "--events", "e.events"]


def _actors(d: Path) -> list[str]:
    (d / "m.actors").write_text("rules maze\nactor 1 wall\n  colour 9 9 9\n  box 1 1 1\n"
                                "end\n")
    (d / "e.events").write_text("wait 5\nclick left 32 472\nwait 3\nkey s\nwait 3\n"
                                "click left 96 300\nwait 5\n")
    return ["ca", "actors", "m.actors", "--headless", "--events", "e.events"]


def _events(argv: list[str]) -> Callable[[Path], list[str]]:
    def make(d: Path) -> list[str]:
        (d / "e.events").write_text("frames 2\nclick middle 400 300\nframes 2\n"
                                    "key space\nframes 4\n")
        return [*argv, "--events", "e.events"]
    return make


def _ca_menu(d: Path) -> list[str]:
    """Saved while Alter display waits on its choice menu (the menu's values in the state)."""
    from camlab88.apps.ca.program.demo import choose, leave_editing

    (d / "e.events").write_text("frames 3\n" + leave_editing() + choose("Alter display") +
                                "frames 3\nmove 300 160\nframes 8\n")
    return ["ca", "program", "--headless", "--pattern", "glider", "--events", "e.events"]


# program -> (what makes its argv in a directory, when its state is saved)
PROGRAMS: dict[str, tuple[Callable[[Path], list[str]], str]] = {
    "sigma-run": (_sigma, "0.2"),
    "rainbow-run": (lambda d: ["rainbow", "run", "--headless", "--stop-after", "8"], "0.06"),
    "rainbow-run-shelf": (lambda d: ["rainbow", "run", "--headless", "--stop-after", "8",
                                     "--demo", "shelf"], "0.06"),
    "snooker-play": (_events(["snooker", "play", "--headless"]), "0.1"),
    "snooker-visualise": (_visualise, "0.3"),
    "snooker-replay": (_replay, "0.2"),
    "ca-program": (_events(["ca", "program", "--headless", "--pattern", "glider"]), "0.1"),
    "ca-program-menu": (_ca_menu, "0.2"),
    "kas-view": (_kas_view, "0.3"),
    # the editors, whose state is their input log (emulator.harness.input_log)
    "kas-edit": (_kas_edit, "0.3"),
    "kas-path": (_kas_path, "0.3"),
    "kas-paint": (_kas_paint, "0.3"),
    "snooker-camera": (_camera, "0.15"),
    "ca-actors": (_actors, "0.15"),
}


class Place:
    """A program's directory, its argv and its real saved state; ``outside`` is a watched
    directory beside it where no file may appear."""

    def __init__(self, root: Path, name: str) -> None:
        self.dir = root / name
        self.outside = root / f"{name}-outside"
        self.dir.mkdir()
        self.outside.mkdir()
        self.absent = Path(f"/tmp/camlab88-hostile-{uuid.uuid4().hex}")
        make, at = PROGRAMS[name]
        with _cwd(self.dir):
            self.argv = make(self.dir)
            code, err = run_cli([*self.argv, "--save-state", "good.c88state", "--at", at],
                                LIMIT_S)
            assert code == 0, err
            code, err = run_cli([*self.argv, "--load-state", "good.c88state"], LIMIT_S)
            assert code == 0, err  # a warm load: every module it needs is imported now
        self.good = (self.dir / "good.c88state").read_bytes()

    def paths(self) -> list[str]:
        """Path-shaped strings a state might try: into ``outside``, beside the directory,
        absolute."""
        return [str(self.outside / "written"), f"../{self.outside.name}/rel",
                str(self.absent / "x"), str(self.outside)]

    def load(self, data: bytes) -> tuple[int, str]:
        """``data`` as the state file of this program's run: the outcome, checked."""
        evil = self.dir / "evil.c88state"
        evil.write_bytes(data)
        before = set(sys.modules)
        with _cwd(self.dir):
            code, err = run_cli([*self.argv, "--load-state", evil.name], LIMIT_S)
        self.check(code, err, before, "evil.c88state")
        return code, err

    def check(self, code: int, err: str, before: set[str], named: str) -> None:
        new = set(sys.modules) - before
        assert not new, f"the load imported {sorted(new)[:5]}"
        assert not any(self.outside.iterdir()), f"a file appeared in {self.outside}"
        assert not self.absent.exists(), f"{self.absent} appeared"
        assert "Traceback" not in err, err
        if code != 0:
            assert code == 2, (code, err)
            lines = [line for line in err.splitlines() if line.strip()]
            assert len(lines) == 1, err
            assert named in lines[0], err


class _cwd:
    def __init__(self, d: Path) -> None:
        self.d, self.old = d, Path.cwd()

    def __enter__(self) -> None:
        os.chdir(self.d)

    def __exit__(self, *exc: object) -> None:
        os.chdir(self.old)


@pytest.fixture(scope="module", params=sorted(PROGRAMS))
def place(request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory) -> Place:
    return Place(tmp_path_factory.mktemp("hostile"), request.param)


def _opened(place: Place) -> tuple[dict[str, Any], list[bytes]]:
    """The good state opened: its header (with ``parts``, their names) and its parts."""
    opened = open_state(place.good)
    line, _, rest = opened.partition(b"\n")
    parts, k = [], 0
    while k < len(rest):
        n = int.from_bytes(rest[k:k + 4], "big")
        parts.append(rest[k + 4:k + 4 + n])
        k += 4 + n
    return json.loads(line), parts


def _closed(head: dict[str, Any], parts: list[bytes]) -> bytes:
    body = b"".join(len(p).to_bytes(4, "big") + p for p in parts)
    return close_state(json.dumps(head).encode("utf-8") + b"\n" + body)


def _places(tree: Any, kind: type | tuple[type, ...]) -> Iterator[tuple[Any, Any]]:
    """Every (container, key) in ``tree`` whose value is of ``kind`` (bool is no int)."""
    stack = [tree]
    while stack:
        node = stack.pop()
        for key, value in (node.items() if isinstance(node, dict) else enumerate(node)):
            if isinstance(value, dict | list):
                stack.append(value)
            elif isinstance(value, kind) and not (kind is int and isinstance(value, bool)):
                yield node, key


def _each(place: Place, kind: type, values: list[Any], most: int = 8) -> int:
    """Load the state with each of the first ``most`` places of ``kind`` in its values
    replaced by each of ``values``; returns how many loads ran."""
    head, parts = _opened(place)
    n = len(list(_places(head["values"], kind)))
    runs = 0
    for i in range(min(n, most)):
        for value in values:
            head, parts = _opened(place)
            node, key = list(_places(head["values"], kind))[i]
            node[key] = value
            place.load(_closed(head, parts))
            runs += 1
    return runs


# ---------------------------------------------------------------------------- attacks
CODE = {"O": "camlab88.base.atomicfile:AtomicWriter", "a": [["path", "/tmp/x"]]}
CALLBACK = {"Fn": [], "code": ["camlab88.base.atomicfile", "write_atomic", 1],
            "defaults": {"T": ["/tmp/camlab88-callback", "x"]}}


def test_references_to_code_or_classes_are_refused(place: Place) -> None:
    head, parts = _opened(place)
    head["values"] = CODE
    assert place.load(_closed(head, parts))[0] == 2
    for name in list(head["values"])[:6]:  # each of the first fields in turn
        head, parts = _opened(place)
        head["values"][name] = CODE
        assert place.load(_closed(head, parts))[0] == 2


def test_callbacks_are_refused(place: Place) -> None:
    head, parts = _opened(place)
    for name in list(head["values"])[:6]:
        head, parts = _opened(place)
        head["values"][name] = CALLBACK
        assert place.load(_closed(head, parts))[0] == 2


def test_path_shaped_strings_in_string_fields_choose_no_file(place: Place) -> None:
    _each(place, str, place.paths()[:2], most=12)
    head, parts = _opened(place)
    for node, key in _places(head["values"], str):  # all of them at once
        node[key] = place.paths()[2]
    place.load(_closed(head, parts))
    head, parts = _opened(place)  # and the envelope's own strings
    head["program"] = place.paths()[0]
    assert place.load(_closed(head, parts))[0] == 2


def test_a_state_nested_in_itself_is_refused(place: Place) -> None:
    head, parts = _opened(place)
    if not parts:
        pytest.skip("this program's state has no binary parts to nest into")
    parts[0] = place.good  # a whole state where a machine's (or a text's) part was
    place.load(_closed(head, parts))  # refused or (a text) taken as text: checked alike
    parts[0] = _closed(head, [place.good] + parts[1:])  # twice over
    place.load(_closed(head, parts))


def _packed(head: dict[str, Any], parts: list[bytes],
            extra: tuple[tuple[str, bytes, int], ...] = (), values: bytes | None = None
            ) -> bytes:
    """A state file packed by hand as state_file.pack does (format 2): ``extra`` parts
    (name, deflated bytes, declared length) after the real ones; ``values`` raw JSON."""
    head = dict(head)
    names = head.pop("parts")
    body = [zlib.compress(p, 1) for p in parts]
    blobs = [[n, len(z), len(p)] for n, z, p in zip(names, body, parts, strict=True)]
    for name, data, declared in extra:
        blobs.append([name, len(data), declared])
        body.append(data)
    text = json.dumps(dict(head, values=0, format_version=2, device="program", blobs=blobs),
                      sort_keys=True).encode()
    if values is not None:
        text = text.replace(b'"values": 0', b'"values": ' + values)
    return MAGIC + len(text).to_bytes(4, "big") + text + b"".join(body)


def test_deep_nesting_is_refused_before_parsing(place: Place) -> None:
    head, parts = _opened(place)
    code, err = place.load(_packed(head, parts, values=b"[" * 200_000 + b"]" * 200_000))
    assert code == 2 and "nested deeper" in err


_BOMB: list[bytes] = []


def _bomb() -> bytes:
    if not _BOMB:
        _BOMB.append(zlib.compress(b"\0" * (300 << 20), 9))  # 300 MB of zeros in ~300 kB
    return _BOMB[0]


def test_huge_declared_sizes_and_zip_bombs_are_refused_before_allocating(place: Place
                                                                         ) -> None:
    head, parts = _opened(place)
    values = json.dumps(head["values"]).encode()
    for declared in (300 << 20, 1 << 40, 10):  # the truth (over the cap), huge, a lie
        code, err = place.load(_packed(head, parts, (("bomb", _bomb(), declared),), values))
        assert code == 2, err
    code, err = place.load(pack("program", {}, {}) + b"\0" * (65 << 20))
    assert code == 2 and "bytes" in err


def test_numeric_extremes_are_refused_or_taken_within_their_ranges(place: Place) -> None:
    _each(place, int, [-1, 2**63, -(2**63), 10**30], most=6)
    _each(place, float, [1e308, -1e308], most=4)
    head, parts = _opened(place)
    head["time"] = "1e999999999"  # once a string read by Fraction(): unbounded work
    assert place.load(_closed(head, parts))[0] == 2
    head, parts = _opened(place)
    head["time"] = [10**4000, 1]  # more digits than json reads (one line, no traceback)
    assert place.load(_closed(head, parts))[0] == 2
    head, parts = _opened(place)
    head["harness"] = [2**62, 2**62, [1, 0], [10**600, 3]]
    assert place.load(_closed(head, parts))[0] == 2


def test_wrong_types_and_damaged_parts_are_refused(place: Place) -> None:
    _each(place, str, [0, None, ["x"], {"x": 1}], most=4)
    _each(place, bool, [0, "true", None], most=4)
    head, parts = _opened(place)
    for i, part in enumerate(parts):
        damaged = list(parts)
        damaged[i] = part[: len(part) // 2]  # a machine's own state cut short
        place.load(_closed(head, damaged))
        damaged[i] = bytes(b ^ 0x5A for b in part[:64]) + part[64:]
        place.load(_closed(head, damaged))


def test_another_state_version_is_refused_naming_both(place: Place) -> None:
    head, parts = _opened(place)
    mine = head["state_version"]
    for theirs in (mine + 1, 0, "1", None):
        head["state_version"] = theirs
        code, err = place.load(_closed(head, parts))
        assert code == 2 and f"version {theirs!r}" in err and f"version {mine}" in err, err


def test_a_recording_carrying_each_attack_goes_through_the_same_loader(place: Place) -> None:
    """A session recorded from ``--load-state`` replays with --check; the same recording
    carrying an attacked state is refused by the loader, as a file is."""
    with _cwd(place.dir):
        code, err = run_cli([*place.argv, "--load-state", "good.c88state", "--record",
                             "r.session"], LIMIT_S)
        assert code == 0, err
        code, err = run_cli(["replay", "r.session", "--check"], LIMIT_S)
        assert code == 0, err
    rec = read(place.dir / "r.session")
    name = next(n for n, data in rec.files.items() if data == place.good)
    head, parts = _opened(place)
    attacks = [dict(head, values=CODE), dict(head, values=CALLBACK),
               dict(head, state_version=99)]
    for attacked in attacks:
        rec.files[name] = _closed(attacked, parts)
        (place.dir / "evil.session").write_text(dumps(rec))
        before = set(sys.modules)
        with _cwd(place.dir):
            code, err = run_cli(["replay", "evil.session", "--check"], LIMIT_S)
        assert code == 1, err  # the recorded program refused its state: documented as 1
        assert "not loaded" in err
        new = set(sys.modules) - before
        assert not new, sorted(new)[:5]
        assert not any(place.outside.iterdir())
