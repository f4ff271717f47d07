"""Motion on two levels (thesis 8.1: "performing the animation on two levels").

Level one, the automaton: between generation g and g + 1 the film has F frames (the
in-between). A cell whose state is the same in both stays. A cell that appears (or whose
state changes, as the new state) is *born*: its actor grows from scale 0 to 1. A cell that
disappears (or whose state changes, as the old state) *dies*: its actor shrinks from 1 to 0.
For a *moving* state (``glide``; all states unless the film says otherwise) a death and a
birth of that state in neighbouring cells are one actor *gliding* from the first cell to the
second at full size. Which death goes with which birth, deterministically: every pair of a
death and a birth of the same moving state at most one cell apart (8-neighbourhood) is a
candidate; candidates are taken in order of distance (orthogonal neighbours before diagonal
ones), then the death's (row, col), then the birth's (row, col), each death and each birth
used at most once. A maze runner's head gliding on as its old cell turns to tail, a
glider's cells sliding diagonally, a blinker's arms swinging round are all this rule.
Growth, shrinking and gliding follow smoothstep(u) = 3u^2 - 2u^3 of the phase u in [0, 1].

Level two, the actor: each actor's own ``Cycle`` s, by film frame number n: ``bob A P``
lifts it A * (1 - cos(2 pi n / P)) / 2 (0..A, never into the floor), ``turn D P`` turns it
D * n / P degrees; a part that ``swing`` s (a limb) turns about its pivot by
A sin(2 pi (n / P + phase)). An actor whose ``phase`` is ``together`` moves in step with every
actor of its state (one clock, the film's frame n); ``individual`` gives each actor its own
clock, n + a shift from the cell and generation it was born in (``lineage``: an actor
gliding on keeps its birth, so its clock never jumps), so a crowd of walkers does not march
in step (thesis 8.1: "each actor undergoing its own independent motion").

An actor that ``face`` s ``glide`` turns to face the way it moves (``heading``: its own -y,
the side the default camera sees, along the glide): during a glide it turns from the
heading it had (0, as modelled, before its first glide) through the smaller angle, in the
glide's first half, and keeps the new heading while it stands (``facing``: a glide carries
the heading on). An actor born beside a death of its own state (a maze runner splitting at
a junction) is born facing away from that cell.

A state without an actor is a tile on the board, shown as the earlier generation's until
the phase reaches one half, then as the later's.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from camlab88.apps.actors.model import ActorSet, Cycle
from camlab88.apps.actors.render import Placed
from camlab88.apps.cafilm.timeline import Generation

Cell = tuple[int, int]  # (col, row)


@dataclass(frozen=True)
class Change:
    """What happens between two generations."""

    stays: tuple[tuple[Cell, int], ...]
    births: tuple[tuple[Cell, int], ...]
    deaths: tuple[tuple[Cell, int], ...]
    glides: tuple[tuple[Cell, Cell, int], ...]  # (from, to, state)


def smoothstep(u: float) -> float:
    u = min(max(u, 0.0), 1.0)
    return u * u * (3.0 - 2.0 * u)


def change(a: Generation, b: Generation, glide: frozenset[int] | None = None) -> Change:
    """``glide``: the moving states (None: every state)."""
    old, new = a.as_dict(), b.as_dict()
    stays = sorted((c, s) for c, s in old.items() if new.get(c) == s)
    deaths = [(c, s) for c, s in old.items() if new.get(c) != s]
    births = [(c, s) for c, s in new.items() if old.get(c) != s]
    pairs = []
    for (dc, ds) in deaths:
        if glide is not None and ds not in glide:
            continue
        for (bc, bs) in births:
            dx, dy = bc[0] - dc[0], bc[1] - dc[1]
            if bs == ds and max(abs(dx), abs(dy)) == 1:
                pairs.append((dx * dx + dy * dy, dc[1], dc[0], bc[1], bc[0], dc, bc, ds))
    pairs.sort(key=lambda p: p[:5])
    used_d: set[Cell] = set()
    used_b: set[Cell] = set()
    glides = []
    for *_key, dc, bc, s in pairs:
        if dc in used_d or bc in used_b:
            continue
        used_d.add(dc)
        used_b.add(bc)
        glides.append((dc, bc, s))
    return Change(tuple(stays),
                  tuple(sorted(x for x in births if x[0] not in used_b)),
                  tuple(sorted(x for x in deaths if x[0] not in used_d)),
                  tuple(sorted(glides)))


Birth = tuple[Cell, int]  # (the cell an actor was born in, the generation)
SHIFT_FRAMES = 997  # an individual clock's shift is under this many frames


def lineage(gens: list[Generation], g: int, glide: frozenset[int] | None = None
            ) -> dict[Cell, Birth]:
    """Each living cell of generation ``g``: where and when its actor was born (a glide
    carries the birth on; generation 0's cells are born there at 0)."""
    born = {c: (c, 0) for c in gens[0].as_dict()}
    for k in range(min(g, len(gens) - 1)):
        ch = change(gens[k], gens[k + 1], glide)
        nxt = {c: born.get(c, (c, k)) for c, _ in ch.stays}
        for c0, c1, _ in ch.glides:
            nxt[c1] = born.get(c0, (c0, k))
        for c, _ in ch.births:
            nxt[c] = (c, k + 1)
        born = nxt
    return born


def clock_shift(birth: Birth) -> int:
    """An individual actor's clock shift in frames, from its birth (a fixed hash: the
    same film renders the same in any process)."""
    (col, row), gen = birth
    h = (col * 73856093) ^ (row * 19349663) ^ (gen * 83492791)
    return (h & 0x7FFFFFFF) % SHIFT_FRAMES


def heading(frm: Cell, to: Cell) -> float:
    """Degrees about z that turn an actor's front (its own -y) from ``frm`` toward ``to``:
    0 down the rows (the world's -Y), 90 along the columns (+X), 180 up the rows."""
    return math.degrees(math.atan2(to[0] - frm[0], to[1] - frm[1]))


def parents(ch: Change) -> dict[Cell, Cell]:
    """Each birth's parent: the nearest cell of its state that died (gliding on or not), at
    most one cell away; ties as the glides' pairing (orthogonal first, then row, col)."""
    died = [(c, s) for c, s in ch.deaths] + [(c0, s) for c0, _c1, s in ch.glides]
    out = {}
    for bc, bs in ch.births:
        near = [((dc[0] - bc[0]) ** 2 + (dc[1] - bc[1]) ** 2, dc[1], dc[0], dc)
                for dc, ds in died
                if ds == bs and max(abs(dc[0] - bc[0]), abs(dc[1] - bc[1])) == 1]
        if near:
            out[bc] = min(near)[3]
    return out


def facing(gens: list[Generation], g: int, glide: frozenset[int] | None = None
           ) -> dict[Cell, float]:
    """The heading of each living cell of generation ``g`` that has glided or was born
    beside a parent (``heading``; a cell that stays keeps its own; absent: 0)."""
    faces: dict[Cell, float] = {}
    for k in range(min(g, len(gens) - 1)):
        ch = change(gens[k], gens[k + 1], glide)
        nxt = {c: faces[c] for c, _ in ch.stays if c in faces}
        for c0, c1, _ in ch.glides:
            nxt[c1] = heading(c0, c1)
        for c, p in parents(ch).items():
            nxt[c] = heading(p, c)
        faces = nxt
    return faces


def _turning(h0: float, h1: float, u: float) -> float:
    """From heading h0 to h1 through the smaller angle, done by the glide's half way."""
    delta = (h1 - h0 + 180.0) % 360.0 - 180.0
    return h0 + delta * smoothstep(2.0 * u)


def cycle_pose(cycles: tuple[Cycle, ...], frame: float) -> tuple[float, float]:
    """(turn degrees, lift cells) of an actor's own motion at film frame ``frame``."""
    turn = lift = 0.0
    for c in cycles:
        if c.kind == "turn":
            turn += c.amount * frame / c.period
        elif c.kind == "bob":
            lift += c.amount * (1.0 - math.cos(2.0 * math.pi * frame / c.period)) / 2.0
    return turn, lift


def posed(ch: Change, u: float, actors: ActorSet, frame: int,
          born: dict[Cell, Birth] | None = None, g: int = 0,
          faces: dict[Cell, float] | None = None,
          ) -> tuple[tuple[Placed, ...], tuple[tuple[int, int, int], ...]]:
    """(actors placed, tile cells (col, row, state)) at phase ``u`` of the change from
    generation ``g``; ``born``: ``lineage`` of generation g (needed only by actors whose
    phase is individual; without it each is born where it stands at g); ``faces``:
    ``facing`` of generation g (needed only by actors that face their glide)."""
    e = smoothstep(u)
    have = actors.actors
    born = born or {}
    faces = faces or {}
    placed: list[Placed] = []
    tiles: list[tuple[int, int, int]] = []

    def put(state: int, col: float, row: float, scale: float, birth: Birth,
            head: float = 0.0) -> None:
        a = have[state]
        clock = frame + (clock_shift(birth) if a.phase == "individual" else 0)
        turn, lift = cycle_pose(a.cycles, clock)
        if a.face == "glide":
            turn += head
        placed.append(Placed(state, col, row, scale, turn, lift, clock))

    def was(cell: Cell) -> Birth:
        return born.get(cell, (cell, g))

    for (col, row), s in ch.stays:
        if s in have:
            put(s, col, row, 1.0, was((col, row)), faces.get((col, row), 0.0))
        else:
            tiles.append((col, row, s))
    for (col, row), s in ch.deaths:
        if s in have:
            if e < 1.0:
                put(s, col, row, 1.0 - e, was((col, row)), faces.get((col, row), 0.0))
        elif u < 0.5:
            tiles.append((col, row, s))
    mother = parents(ch)
    for (col, row), s in ch.births:
        if s in have:
            if e > 0.0:
                p = mother.get((col, row))
                put(s, col, row, e, ((col, row), g + 1),
                    heading(p, (col, row)) if p is not None else 0.0)
        elif u >= 0.5:
            tiles.append((col, row, s))
    for (c0, r0), (c1, r1), s in ch.glides:
        if s in have:
            put(s, c0 + (c1 - c0) * e, r0 + (r1 - r0) * e, 1.0, was((c0, r0)),
                _turning(faces.get((c0, r0), 0.0), heading((c0, r0), (c1, r1)), u))
        else:
            tiles.append((c0, r0, s) if u < 0.5 else (c1, r1, s))
    return tuple(placed), tuple(tiles)
