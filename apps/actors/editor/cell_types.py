"""The cell types the editor offers (a rule set's states) and the actor a state starts with.

The command reads the rule set (apps.actors never imports apps.ca) and passes each state's
number, name and colour; a state the actors file has but the rules do not name is offered
too, so nothing in the file becomes unreachable."""

from __future__ import annotations

import re
from dataclasses import dataclass, replace

from camlab88.apps.actors.model import DEFAULT_MATERIAL, Actor, Part

TILE = Part("box", size=(0.9, 0.9, 0.04))  # how a state without an actor is shown


@dataclass(frozen=True)
class CellType:
    state: int
    name: str
    colour: tuple[int, int, int]


def offered(types: list[CellType], actors: dict[int, Actor]) -> list[CellType]:
    """The rule set's types, plus any state only the actors file has, by state number."""
    known = {t.state: t for t in types}
    for s, a in actors.items():
        known.setdefault(s, CellType(s, a.name, a.colour))
    return [known[s] for s in sorted(known)]


def actor_name(name: str) -> str:
    """A cell type's name as an actor's (the file's names: letters, digits, ``_ . + -``)."""
    return (re.sub(r"[^A-Za-z0-9_.+-]", "_", name).lstrip(".+-") or "actor")[:64]


def new_actor(t: CellType) -> Actor:
    """The actor a state gets when it is first edited: no parts yet."""
    return Actor(t.state, actor_name(t.name), t.colour, DEFAULT_MATERIAL, ())


def tile(t: CellType) -> Actor:
    """What the preview shows for a state without an actor: its coloured square tile."""
    return Actor(t.state, actor_name(t.name), t.colour, DEFAULT_MATERIAL, (TILE,))


def first_lathe(actor: Actor) -> int | None:
    """The index of the lathe part the editor draws (the first), if any."""
    return next((i for i, p in enumerate(actor.parts) if p.kind == "lathe"), None)


def with_profile(actor: Actor, profile: tuple[tuple[float, float], ...]) -> Actor:
    """``actor`` with its first lathe part's profile replaced (a lathe part added in front
    when it has none; dropped when the profile has fewer than two points)."""
    parts = list(actor.parts)
    i = first_lathe(actor)
    if len(profile) >= 2:
        new = Part("lathe", profile) if i is None else Part(
            "lathe", profile, parts[i].size, parts[i].offset, parts[i].swing)
        if i is None:
            parts.insert(0, new)
        else:
            parts[i] = new
    elif i is not None:
        del parts[i]
    return replace(actor, parts=tuple(parts))  # its cycles, phase and facing kept
