"""Hypothesis strategies for valid actor sets (every field in the range the format accepts)."""

from __future__ import annotations

from hypothesis import strategies as st

from camlab88.apps.actors.model import FACES, PHASES, Actor, ActorSet, Cycle, Material, Part

coord = st.floats(-100, 100, allow_nan=False, allow_infinity=False)
positive = st.floats(1e-6, 100, allow_nan=False, allow_infinity=False)
radius = st.floats(0, 100, allow_nan=False, allow_infinity=False)
triple = st.tuples(coord, coord, coord)
size3 = st.tuples(positive, positive, positive)


@st.composite
def lathe(draw) -> Part:
    heights = sorted(draw(st.lists(coord, min_size=2, max_size=12)))
    radii = draw(st.lists(radius, min_size=len(heights), max_size=len(heights)))
    if max(radii) <= 0:
        radii[0] = 0.5
    return Part("lathe", tuple(zip(radii, heights)), draw(size3), draw(triple))


@st.composite
def sphere(draw) -> Part:
    r = draw(positive)
    size = draw(st.one_of(st.just((r, r, r)), size3))
    return Part("sphere", (), size, draw(triple))


extrude = st.builds(lambda pts, size, at: Part("extrude", tuple(pts), size, at),
                    st.lists(st.tuples(coord, coord), min_size=3, max_size=10),
                    st.one_of(size3, positive.map(lambda h: (1, 1, h))), triple)
box = st.builds(lambda size, at: Part("box", (), size, at), size3, triple)
part = st.one_of(lathe(), sphere(), extrude, box)
unit = st.floats(0, 10, allow_nan=False)
material = st.builds(Material, unit, unit, unit, st.floats(0, 1000, allow_nan=False))
cycle = st.one_of(
    st.builds(Cycle, st.just("bob"), coord, st.integers(1, 1_000_000)),
    st.builds(Cycle, st.just("turn"), st.floats(-3600, 3600, allow_nan=False),
              st.integers(1, 1_000_000)))
name = st.from_regex(r"[A-Za-z0-9_][A-Za-z0-9_.+-]{0,20}", fullmatch=True)
colour = st.tuples(st.integers(0, 255), st.integers(0, 255), st.integers(0, 255))


@st.composite
def actor_set(draw) -> ActorSet:
    states = draw(st.lists(st.integers(0, 255), unique=True, max_size=5))
    actors = {s: Actor(s, draw(name), draw(colour), draw(material),
                       tuple(draw(st.lists(part, min_size=1, max_size=4))),
                       tuple(draw(st.lists(cycle, max_size=2))),
                       draw(st.sampled_from(PHASES)), draw(st.sampled_from(FACES)))
              for s in states}
    rules = draw(st.from_regex(r"[A-Za-z0-9_./-]{1,30}", fullmatch=True))
    return ActorSet(rules, actors)
