"""A film from what the command line names: rules, pattern, actors file, generations,
camera script, lights (every input error is a ValueError subclass naming its file)."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from camlab88.apps.actors.model import ActorSet, read_actors
from camlab88.apps.actors.render import Look, canopy_over
from camlab88.apps.cafilm.camera import auto_views, script_views
from camlab88.apps.cafilm.film import CaFilm
from camlab88.apps.cafilm.timeline import record

MAX_GENERATIONS = 10_000
MAX_PER_GENERATION = 250
MAX_SAMPLES = 4  # along each axis of a pixel
MAX_FRAME_SAMPLES = 1 << 24  # per frame: ~1 GB of buffers (colour, depth, ids, weights)


@dataclass(frozen=True)
class FilmSpec:
    rules: str
    pattern: str
    generations: int
    actors: str | None = None
    camera: str | None = None
    lights: str | None = None
    per_generation: int = 8
    glide: str = "all"  # all | none | comma-separated states
    size: tuple[int, int] = (768, 512)
    samples: int = 2
    edges: str = "wrap"
    seed: int = 0


def parse_glide(text: str) -> frozenset[int] | None:
    """``all`` -> None (every state moves), ``none`` -> {}, ``2,3`` -> {2, 3}."""
    if text == "all":
        return None
    if text == "none":
        return frozenset()
    states = set()
    for word in text.split(","):
        if not (word.isascii() and word.isdigit() and 0 < int(word) <= 255):
            raise ValueError(f"--glide: expected all, none or states 1..255 separated by "
                             f"commas, not {text!r}")
        states.add(int(word))
    return frozenset(states)


def _engine(spec: FilmSpec):  # -> apps.ca.engine.Engine
    from camlab88.apps.ca import library
    from camlab88.apps.ca.engine import CENTRE, Engine
    from camlab88.apps.ca.patterns import read_pattern
    from camlab88.apps.ca.rules import load_rules

    rules = load_rules(library.rules_path(spec.rules))
    pattern = read_pattern(library.pattern_path(spec.pattern))
    engine = Engine(rules, edges=spec.edges, seed=spec.seed)
    grid = pattern.placed_grid(CENTRE, CENTRE)
    engine.set_grid(*grid) if grid is not None else engine.set_cells(
        *pattern.placed(CENTRE, CENTRE))
    return engine


def tile_colours(rules: object, states: set[int]) -> dict[int, tuple[int, int, int]]:
    """The 2-D program's colour of every state that has no actor (its tile)."""
    from camlab88.apps.ca.render import palette

    if not states:
        return {}
    pal = palette(rules, max(states))
    return {s: tuple(int(v) for v in pal[s]) for s in states}


def check_frames(spec: FilmSpec, actors: ActorSet, counts: list[dict[int, int]], lights: int,
                 look: Look) -> None:
    """Refuse (base.budget) a film whose busiest frame — a generation's actors and the next
    one's, as a change between them shows both — would need more memory than the budget
    allows, before any frame is rendered. ``counts``: live cells by state, a generation."""
    from camlab88.apps.actors.render import frame_need
    from camlab88.base import budget

    worst, what = 0, ""
    for a, b in zip(counts, counts[1:] or [{}]):
        both = {s: a.get(s, 0) + b.get(s, 0) for s in a.keys() | b.keys()}
        need, about = frame_need(actors, both, lights, look)
        if need > worst:
            worst, what = need, about
    source = " + ".join(str(p) for p in (spec.actors, spec.lights) if p) or str(spec.pattern)
    budget.check(source, worst, what)


def _counts(states: np.ndarray) -> dict[int, int]:
    found, k = np.unique(np.asarray(states, dtype=np.int64), return_counts=True)
    return dict(zip(found.tolist(), k.tolist()))


def build(spec: FilmSpec) -> CaFilm:
    if not 1 <= spec.generations <= MAX_GENERATIONS:
        raise ValueError(f"--generations must be 1..{MAX_GENERATIONS}")
    if not 1 <= spec.per_generation <= MAX_PER_GENERATION:
        raise ValueError(f"--frames-per-generation must be 1..{MAX_PER_GENERATION}")
    if not 1 <= spec.samples <= MAX_SAMPLES:
        raise ValueError(f"--samples must be 1..{MAX_SAMPLES}")
    w, h = spec.size
    if w * h * spec.samples ** 2 > MAX_FRAME_SAMPLES:
        raise ValueError(f"{w}x{h} at {spec.samples}x{spec.samples} samples a pixel is more "
                         f"than {MAX_FRAME_SAMPLES} samples a frame: a smaller --size or "
                         "fewer --samples")
    from camlab88.apps.ca.log import check_seed

    check_seed(spec.seed)
    glide = parse_glide(spec.glide)
    actors = read_actors(spec.actors) if spec.actors else ActorSet(spec.rules, {})
    camera_text = None
    if spec.camera:
        from camlab88.apps.snooker.camera.ccl import read_script

        camera_text = read_script(spec.camera)
    look = Look(spec.size[0], spec.size[1], spec.samples)
    lights = None
    if spec.lights:  # read before the generations run: its cost does not depend on them
        from camlab88.apps.snooker.render.lights import read_lights

        lights = read_lights(spec.lights, look.shadow_map ** 2 * 8, "with their shadow maps")
    engine = _engine(spec)
    n_lights = len(lights.positions) if lights is not None else 4
    # generation 0 first (no generation run yet), then the busiest pair of the film
    check_frames(spec, actors, [_counts(engine.ts)], n_lights, look)
    timeline = record(engine, spec.generations)
    if lights is None:
        lights = canopy_over(timeline.floor)
    views = (script_views(camera_text, spec.generations, str(spec.camera))
             if camera_text is not None else auto_views(timeline.floor, spec.generations))
    seen = {int(s) for g in timeline.generations for s in g.states.tolist()}
    tiles = tile_colours(engine.rules, seen - set(actors.actors))
    check_frames(spec, actors, [_counts(g.states) for g in timeline.generations],
                 len(lights.positions), look)
    return CaFilm(actors, timeline, tiles, lights, views, spec.per_generation, glide, look)


def rules_note(film: CaFilm, spec: FilmSpec) -> str | None:
    """A note when the actors file was written for other rules (it is still used)."""
    if spec.actors and film.actors.actors and Path(spec.rules).stem != film.actors.rules:
        return (f"note: {spec.actors} is for rules {film.actors.rules!r}; its actors stand "
                f"for the same state numbers under {spec.rules!r}")
    return None
