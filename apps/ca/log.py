"""Log, Checkpoint and Script files of the ``ca`` program (thesis section 7.3.1), as pure model.

A *log* lists every animator intervention with the generation at which it happened (rule
changes, edits, pattern loads, clears, random population, advance areas) and, with
``RecordPansAndZooms``, viewport moves and zoom changes.  A *script* is a log read back and
replayed.  A *checkpoint* holds the complete state at one generation; its file name is the
log name followed by the generation number, as the thesis says.

The log's header (after the magic line) records the run's plane edges and seed, so a
script replays with the same ones (``edges wrap``, ``seed 0``); logs without them still read.

Events recorded at generation g happened while generation g was displayed, i.e. before the
step to g + 1.  Replaying to generation N applies every event up to and including N.
"""

from __future__ import annotations

import os
import re
from collections.abc import Callable, Iterable
from dataclasses import dataclass

import numpy as np

from camlab88.apps.ca.engine import EDGES, SIDE, Engine, Rect
from camlab88.apps.ca.patterns import Pattern, format_rle, parse_rle
from camlab88.apps.ca.rules import parse_rules
from camlab88.apps.ca.seed import SEED_MAX, SEED_MIN
from camlab88.apps.ca.seed import check_seed as _seed_in_range
from camlab88.base.atomicfile import write_atomic
from camlab88.base.textinput import parse_int, quote, read_text

LOG_MAGIC = "CAMLAB88-CA-LOG 1"
CHECKPOINT_MAGIC = "CAMLAB88-CA-CHECKPOINT 1"
VIEW_EVENTS = ("view", "zoom")


class LogError(ValueError):
    """A log, script or checkpoint file is malformed (names file and line)."""


# a generation, count or coordinate in a log beyond this is damage, not a session
MAX_LOG_NUMBER = (1 << 31) - 1


def _read(path: str | os.PathLike) -> str:
    return read_text(path, error=LogError)


@dataclass(frozen=True)
class LogSettings:
    """The run settings a log header records (None: an older log that did not)."""

    edges: str | None = None
    seed: int | None = None


@dataclass(frozen=True)
class Event:
    generation: int
    kind: str  # rules, edit, load, erase, clear, populate, advance, view, zoom
    args: tuple  # see _FORMATS
    text: str = ""  # rules: the rule text; load/erase: the pattern as one-line RLE


def _is_number(text: str) -> bool:
    """ASCII digits only: str.isdigit() also accepts '²', which int() refuses."""
    return text.isascii() and text.isdigit()


def _rect_args(rect: Rect | None) -> tuple:
    return ("all",) if rect is None else (rect.x0, rect.y0, rect.x1, rect.y1)


def _rect(args: tuple) -> Rect | None:
    if args[:1] == ("all",):
        return None
    if len(args) < 4:
        raise LogError(f"a rectangle is 'all' or four corners x0 y0 x1 y1, not {quote(args)}")
    return Rect(*(parse_int(str(a), "a rectangle", -MAX_LOG_NUMBER - 1, MAX_LOG_NUMBER,
                            LogError, "corner") for a in args[:4]))


# -- making events (what the program calls as the animator intervenes) -----------------------

def ev_rules(gen: int, name: str, text: str) -> Event:
    return Event(gen, "rules", (name.replace(" ", "_") or "-",), text)


def ev_edit(gen: int, x: int, y: int, value: int) -> Event:
    return Event(gen, "edit", (x, y, value))


def ev_load(gen: int, name: str, x: int, y: int, orientation: str, pattern: Pattern,
            erase: bool = False) -> Event:
    p = pattern.normalised()
    if p.ts.size and int(p.ts.max()) > 255:  # beyond RLE's states: x,y,type triples
        body = ";".join(f"{x},{y},{t}" for x, y, t in zip(p.xs.tolist(), p.ys.tolist(),
                                                           p.ts.tolist()))
    else:
        body = "".join(line for line in format_rle(Pattern(p.xs, p.ys, p.ts)).splitlines()
                       if not line.startswith("#") and not line.startswith("x ="))
    body = f"{p.ref[0]},{p.ref[1]}:{body}"  # reference point, then the cells
    return Event(gen, "erase" if erase else "load",
                 (name.replace(" ", "_") or "-", x, y, orientation), body)


def ev_clear(gen: int, rect: Rect | None) -> Event:
    return Event(gen, "clear", _rect_args(rect))


def ev_populate(gen: int, rect: Rect, density: float, weights: dict[int, float],
                seed: int) -> Event:
    w = ",".join(f"{k}:{v!r}" for k, v in sorted(weights.items()))
    return Event(gen, "populate", (*_rect_args(rect), repr(float(density)), w, seed))


def ev_advance(gen: int, rect: Rect | None) -> Event:
    return Event(gen, "advance", _rect_args(rect))


def ev_view(gen: int, x: int, y: int) -> Event:
    return Event(gen, "view", (x, y))


def ev_zoom(gen: int, zoom: str) -> Event:
    return Event(gen, "zoom", (zoom,))


# -- applying events ----------------------------------------------------------------------

def populate(engine: Engine, rect: Rect, density: float, weights: dict[int, float],
             seed: int) -> None:
    """Random population of the thesis's menu: overall density, relative densities."""
    if rect.width * rect.height > 1 << 26:
        raise ValueError("randomly populated area is limited to 2**26 cells")
    if not 0 <= density <= 1:
        raise ValueError("density must be between 0 and 1")
    forms = sorted(k for k, v in weights.items() if v > 0)
    if not forms:
        raise ValueError("give a positive relative density for at least one life-form")
    p = np.array([weights[k] for k in forms], np.float64)
    rng = np.random.Generator(np.random.PCG64(seed))
    alive = rng.random((rect.height, rect.width)) < density
    kinds = rng.choice(np.array(forms, np.int64), size=(rect.height, rect.width), p=p / p.sum())
    ys, xs = np.nonzero(alive)
    engine.clear(rect)
    engine.set_cells((xs + rect.x0) % SIDE, (ys + rect.y0) % SIDE, kinds[ys, xs])


def apply_event(engine: Engine, ev: Event) -> None:
    """Apply one non-viewing event to the engine."""
    a = ev.args
    if ev.kind == "rules":
        engine.set_rules(parse_rules(ev.text, source=f"log rules {a[0]}"))
    elif ev.kind == "edit":
        engine.set(int(a[0]), int(a[1]), int(a[2]))
    elif ev.kind in ("load", "erase"):
        ref, _, body = ev.text.partition(":")
        if body.endswith("!"):
            p = parse_rle("x = 0, y = 0\n" + body)
        else:
            triples = [tuple(int(v) for v in c.split(",")) for c in body.split(";") if c]
            p = Pattern.from_cells(triples)
        rx, ry = (int(v) for v in ref.split(","))
        p.ref = (rx, ry)
        xs, ys, ts = p.placed(int(a[1]), int(a[2]), str(a[3]))
        engine.set_cells(xs, ys, ts if ev.kind == "load" else 0)
    elif ev.kind == "clear":
        engine.clear(_rect(a))
    elif ev.kind == "populate":
        weights = {int(k): float(v) for k, v in (w.split(":") for w in str(a[5]).split(","))}
        populate(engine, _rect(a), float(a[4]), weights, int(a[6]))
    elif ev.kind == "advance":
        engine.set_advance_area(_rect(a))
    elif ev.kind not in VIEW_EVENTS:
        raise LogError(f"unknown event kind {ev.kind!r}")


def replay(engine: Engine, events: Iterable[Event], target: int,
           on_view: Callable[[Event], None] | None = None) -> Engine:
    """Advance ``engine`` to generation ``target``, applying the script's events on the way.

    Events before the engine's current generation are skipped (they are already in a
    checkpoint), except viewing events, which go to ``on_view`` (ReplayPansAndZooms) in
    order so the view is right when the replay starts from a checkpoint.
    """
    if target < engine.generation:
        raise ValueError(f"cannot replay backwards from {engine.generation} to {target}")
    events = list(events)
    if on_view is not None:  # a checkpoint holds no view: repeat the earlier view events
        for ev in events:
            if ev.kind in VIEW_EVENTS and ev.generation < engine.generation:
                on_view(ev)
    pending = sorted((e for e in events if e.generation >= engine.generation),
                     key=lambda e: e.generation)  # stable: same-generation order kept
    i = 0
    while True:
        while i < len(pending) and pending[i].generation == engine.generation:
            ev = pending[i]
            if ev.kind in VIEW_EVENTS:
                if on_view is not None:
                    on_view(ev)
            else:
                apply_event(engine, ev)
            i += 1
        if engine.generation >= target:
            return engine
        engine.step()


# -- log files --------------------------------------------------------------------------------

def format_log(events: Iterable[Event], record_views: bool = True,
               settings: LogSettings | None = None) -> str:
    out = [LOG_MAGIC]
    if settings is not None and settings.edges is not None:
        out.append(f"edges {settings.edges}")
    if settings is not None and settings.seed is not None:
        out.append(f"seed {settings.seed}")
    for ev in events:
        if ev.kind in VIEW_EVENTS and not record_views:
            continue
        head = " ".join(str(x) for x in (ev.generation, ev.kind, *ev.args))
        if ev.kind == "rules":
            lines = ev.text.splitlines()
            out.append(f"{head} {len(lines)}")
            out += ["|" + line for line in lines]
        elif ev.kind in ("load", "erase"):
            out.append(f"{head} {ev.text}")
        else:
            out.append(head)
    return "\n".join(out) + "\n"


_ARITY = {"edit": 3, "clear": None, "advance": None, "populate": 7, "view": 2, "zoom": 1,
          "load": 5, "erase": 5, "rules": 2}


def _parse_header(lines: list[str], source: str) -> tuple[LogSettings, int]:
    """The magic line and the optional 'edges' and 'seed' lines; returns the settings and
    the index of the first event line."""
    if not lines or lines[0].strip() != LOG_MAGIC:
        raise LogError(f"{source}:1: expected '{LOG_MAGIC}'")
    edges: str | None = None
    seed: int | None = None
    i = 1
    while i < len(lines):
        word, _, rest = lines[i].strip().partition(" ")
        if word == "edges":
            if rest.strip() not in EDGES:
                raise LogError(f"{source}:{i + 1}: edges must be wrap or bounded, "
                               f"found {quote(rest.strip())}")
            edges = rest.strip()
        elif word == "seed":
            if not re.fullmatch(r"-?[0-9]+", rest.strip()):
                raise LogError(f"{source}:{i + 1}: expected 'seed <integer>', found "
                               f"{quote(lines[i])}")
            seed = parse_int(rest, f"{source}:{i + 1}", SEED_MIN, SEED_MAX, LogError, "seed")
        else:
            break
        i += 1
    return LogSettings(edges, seed), i


def check_seed(seed: int, name: str = "--seed") -> int:
    """A seed the engine's kernels can take (an int64); the command line's ``--seed`` should
    go through this too."""
    return _seed_in_range(seed, name, LogError)


def parse_log_settings(text: str, source: str = "<log>") -> LogSettings:
    return _parse_header(text.splitlines(), source)[0]


def read_log_settings(path: str | os.PathLike) -> LogSettings:
    return parse_log_settings(_read(path), os.fspath(path))


def parse_log(text: str, source: str = "<log>") -> list[Event]:
    lines = text.splitlines()
    _, i = _parse_header(lines, source)
    events: list[Event] = []
    while i < len(lines):
        raw = lines[i]
        i += 1
        if not raw.strip():
            continue
        parts = raw.split()
        if len(parts) < 2 or not re.fullmatch(r"[0-9]+", parts[0]):
            raise LogError(f"{source}:{i}: expected 'generation kind ...', found {quote(raw)}")
        here = f"{source}:{i}"

        def num(text: str, lo: int = -MAX_LOG_NUMBER - 1, hi: int = MAX_LOG_NUMBER,
                here: str = here) -> int:
            return parse_int(text, here, lo, hi, LogError)

        gen, kind, args = num(parts[0], 0), parts[1], parts[2:]
        if kind not in _ARITY:
            raise LogError(f"{source}:{i}: unknown event {quote(kind, 24)}")
        want = _ARITY[kind]
        if want is None:
            want = 1 if args[:1] == ["all"] else 4
        if len(args) != want:
            raise LogError(f"{source}:{i}: {kind} takes {want} fields, found {len(args)}")
        try:
            if kind == "rules":
                n = num(args[1])
                body = lines[i:i + n]
                if len(body) != n or not all(b.startswith("|") for b in body):
                    raise LogError(f"{source}:{i}: expected {n} rule lines starting with '|'")
                i += n
                events.append(Event(gen, kind, (args[0],), "\n".join(b[1:] for b in body)))
            elif kind in ("load", "erase"):
                events.append(Event(gen, kind, (args[0], num(args[1]), num(args[2]), args[3]),
                                    args[4]))
            elif kind == "populate":
                events.append(Event(gen, kind, (*(num(a) for a in args[:4]), args[4], args[5],
                                                num(args[6], SEED_MIN, SEED_MAX))))
            elif kind == "zoom":
                events.append(Event(gen, kind, (args[0],)))
            elif kind in ("clear", "advance") and args == ["all"]:
                events.append(Event(gen, kind, ("all",)))
            else:
                events.append(Event(gen, kind, tuple(num(a) for a in args)))
        except ValueError as exc:
            if isinstance(exc, LogError):
                raise
            raise LogError(f"{source}:{i}: bad number in {quote(raw)}") from None
    return events


def read_log(path: str | os.PathLike) -> list[Event]:
    return parse_log(_read(path), os.fspath(path))


class LogWriter:
    """Keeps the session's log on disk, rewritten atomically after every intervention.

    ``history`` continues a session (section 7.3.1's Script then Log): the replayed events
    are written first, verbatim, so the new log holds the whole history even when it is
    the script's own file.  Checkpoints of this log name beyond ``start`` belong to the
    superseded history: they are renamed ``<name><generation>.superseded`` (not deleted)
    so that replaying the new log never starts from one."""

    def __init__(self, path: str | os.PathLike, record_views: bool = False,
                 settings: LogSettings | None = None, history: Iterable[Event] = (),
                 start: int = 0) -> None:
        self.path = os.fspath(path)
        self.record_views = record_views
        self.settings = settings
        self.events: list[Event] = list(history)
        supersede_checkpoints(self.path, start)
        self._write()

    def _write(self) -> None:
        write_atomic(self.path, format_log(self.events, True, self.settings))

    def add(self, ev: Event) -> None:
        if ev.kind in VIEW_EVENTS and not self.record_views:
            return
        self.events.append(ev)
        self._write()


# -- checkpoints ------------------------------------------------------------------------------

def checkpoint_path(log_path: str, generation: int) -> str:
    """The thesis's naming: the log file name with the generation number appended."""
    return f"{log_path}{generation}"


def format_checkpoint(engine: Engine) -> str:
    rules = engine.rules.text if engine.rules is not None else ""
    area = engine.advance_area
    lines = [CHECKPOINT_MAGIC, f"generation {engine.generation}", f"edges {engine.edges}",
             f"seed {engine.seed}",
             "advance " + " ".join(str(v) for v in _rect_args(area))]
    rl = rules.splitlines()
    lines.append(f"rules {len(rl)}")
    lines += ["|" + line for line in rl]
    lines.append(f"cells {engine.population}")
    lines += [f"{x} {y} {t}" for x, y, t in zip(engine.xs.tolist(), engine.ys.tolist(),
                                                 engine.ts.tolist())]
    lines.append("end")
    return "\n".join(lines) + "\n"


def write_checkpoint(log_path: str, engine: Engine) -> str:
    path = checkpoint_path(log_path, engine.generation)
    write_atomic(path, format_checkpoint(engine))
    return path


# a cell of a checkpoint: plane coordinates and a life-form, as format_checkpoint writes them
_CELL = re.compile(r"-?[0-9]{1,10} -?[0-9]{1,10} [0-9]{1,5}")


def parse_checkpoint(text: str, source: str = "<checkpoint>") -> Engine:
    lines = text.splitlines()

    def field(i: int, name: str) -> str:
        if i >= len(lines) or not lines[i].startswith(name + " "):
            raise LogError(f"{source}:{i + 1}: expected '{name} ...'")
        return lines[i][len(name) + 1:]

    if not lines or lines[0] != CHECKPOINT_MAGIC:
        raise LogError(f"{source}:1: expected '{CHECKPOINT_MAGIC}'")
    try:
        gen = parse_int(field(1, "generation"), f"{source}:2", 0, MAX_LOG_NUMBER, LogError,
                        "generation")
        edges = field(2, "edges")
        if edges not in EDGES:
            raise LogError(f"{source}:3: edges must be wrap or bounded")
        seed = parse_int(field(3, "seed"), f"{source}:4", SEED_MIN, SEED_MAX, LogError, "seed")
        area = _rect(tuple(field(4, "advance").split()))
        n = parse_int(field(5, "rules"), f"{source}:6", 0, len(lines), LogError, "rule lines")
        body = lines[6:6 + n]
        if len(body) != n or not all(b.startswith("|") for b in body):
            raise LogError(f"{source}:7: expected {n} rule lines starting with '|'")
        rules_text = "\n".join(b[1:] for b in body)
        i = 6 + n
        count = parse_int(field(i, "cells"), f"{source}:{i + 1}", 0, len(lines), LogError,
                          "cell count")
        rows = lines[i + 1:i + 1 + count]
        if len(rows) != count or (lines[i + 1 + count:i + 2 + count] != ["end"]):
            raise LogError(f"{source}:{i + 2}: expected {count} cell lines then 'end'")
        if not all(_CELL.fullmatch(r) for r in rows):
            bad = next(k for k, r in enumerate(rows) if not _CELL.fullmatch(r))
            raise LogError(f"{source}:{i + 2 + bad}: expected 'x y life-form', found "
                           f"{quote(rows[bad])}")
        arr = np.array([r.split() for r in rows], np.int64).reshape(count, 3)
    except LogError:
        raise
    except (ValueError, OverflowError) as exc:
        raise LogError(f"{source}: malformed checkpoint ({exc})") from None
    engine = Engine(parse_rules(rules_text, f"{source} rules") if rules_text.strip() else None,
                    edges, seed)
    engine.generation = gen
    engine.advance_area = area
    engine.set_cells(arr[:, 0], arr[:, 1], arr[:, 2])
    return engine


def read_checkpoint(path: str | os.PathLike) -> Engine:
    return parse_checkpoint(_read(path), os.fspath(path))


def _checkpoints(log_path: str) -> list[tuple[int, str]]:
    folder = os.path.dirname(os.path.abspath(log_path))
    base = os.path.basename(log_path)
    if not os.path.isdir(folder):
        return []
    return [(int(name[len(base):]), os.path.join(folder, name)) for name in os.listdir(folder)
            if name.startswith(base) and _is_number(name[len(base):])]


def supersede_checkpoints(log_path: str, after: int) -> list[str]:
    """Rename the checkpoints of ``log_path`` beyond generation ``after``; returns the new
    names."""
    moved = []
    for g, path in _checkpoints(log_path):
        if g > after:
            os.replace(path, path + ".superseded")
            moved.append(path + ".superseded")
    return moved


def latest_checkpoint(log_path: str, target: int) -> str | None:
    """The checkpoint of ``log_path`` with the highest generation <= ``target``."""
    folder = os.path.dirname(os.path.abspath(log_path))
    base = os.path.basename(log_path)
    best: tuple[int, str] | None = None
    for name in os.listdir(folder):
        if name.startswith(base) and _is_number(name[len(base):]):
            g = int(name[len(base):])
            if g <= target and (best is None or g > best[0]):
                best = (g, os.path.join(folder, name))
    return None if best is None else best[1]


def resolve_settings(recorded: LogSettings, edges: str | None, seed: int | None,
                     ) -> tuple[str, int, list[str]]:
    """The edges and seed to replay a script with: the ones its log recorded (a replay must
    repeat the run), else the command line's, else wrap and 0; plus a warning for each
    command-line value that disagrees with the log."""
    warnings = []
    if recorded.edges is not None and edges is not None and edges != recorded.edges:
        warnings.append(f"the script was recorded with edges {recorded.edges}; replaying "
                        f"with them, not the command line's {edges}")
    if recorded.seed is not None and seed is not None and seed != recorded.seed:
        warnings.append(f"the script was recorded with seed {recorded.seed}; replaying with "
                        f"it, not the command line's {seed}")
    final_edges = recorded.edges or edges or "wrap"
    final_seed = check_seed(recorded.seed if recorded.seed is not None else (seed or 0))
    return final_edges, final_seed, warnings


def start_from_script(script_path: str, target: int, fresh: Callable[[], Engine],
                      on_view: Callable[[Event], None] | None = None) -> Engine:
    """The thesis's start-up with a Script: read the latest applicable checkpoint (or start
    fresh), then apply rules and interventions until generation ``target``."""
    events = read_log(script_path)
    cp = latest_checkpoint(script_path, target)
    engine = read_checkpoint(cp) if cp is not None else fresh()
    return replay(engine, events, target, on_view)
