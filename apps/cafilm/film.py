"""A film of the automaton with actors: frames as pure tasks (picklable film + frame number ->
PNG bytes), rendered on snooker's film machinery (a local pool or Dask, resumable through
its manifest, checked PNGs written atomically).

Frame numbering: with F frames per generation and N generations the film has N * F + 1
frames; frame n (from 1) shows generation time (n - 1) / F, so frame 1 is generation 0 as
loaded and the last frame is generation N.
"""

from __future__ import annotations

import hashlib
import os
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from camlab88.apps.actors.model import ActorSet, format_actors
from camlab88.apps.actors.render import Look, Shot, Stage, render_frame
from camlab88.apps.cafilm.camera import GenerationViews
from camlab88.apps.cafilm.motion import change, facing, lineage, posed
from camlab88.apps.cafilm.timeline import Timeline
from camlab88.apps.snooker.render.lights import Lights


@dataclass(frozen=True, eq=False)
class CaFilm:
    actors: ActorSet
    timeline: Timeline
    tile_colours: dict[int, tuple[int, int, int]]  # states drawn as tiles
    lights: Lights
    views: GenerationViews
    per_generation: int = 8
    glide: frozenset[int] | None = None
    look: Look = Look()

    @property
    def n_frames(self) -> int:
        return self.timeline.last * self.per_generation + 1


@dataclass(frozen=True)
class FilmFrame:
    """One frame to render (the fields snooker's scheduler reads: frame, width, height)."""

    frame: int
    width: int
    height: int


def tasks(film: CaFilm) -> list[FilmFrame]:
    return [FilmFrame(n, film.look.width, film.look.height) for n in range(1, film.n_frames + 1)]


def phase(film: CaFilm, frame: int) -> tuple[int, float]:
    """(generation g, phase u in [0, 1]) of frame ``frame``: between g and g + 1."""
    j = frame - 1
    f = film.per_generation
    g = min(j // f, max(film.timeline.last - 1, 0))
    return g, (j - g * f) / f


def stage_at(film: CaFilm, frame: int) -> tuple[Stage, Shot]:
    g, u = phase(film, frame)
    gens = film.timeline.generations
    ch = change(gens[g], gens[min(g + 1, len(gens) - 1)], film.glide)
    individual = any(a.phase == "individual" for a in film.actors.actors.values())
    born = lineage(list(gens), g, film.glide) if individual else None
    turning = any(a.face == "glide" for a in film.actors.actors.values())
    faces = facing(list(gens), g, film.glide) if turning else None
    placed, cells = posed(ch, u, film.actors, frame - 1, born, g, faces)
    grey = (128, 128, 128)
    tiles = tuple((c, r, film.tile_colours.get(s, grey)) for c, r, s in cells)
    stage = Stage(film.actors, film.timeline.floor, film.lights, placed, tiles)
    return stage, film.views.at((frame - 1) / film.per_generation)


def render_image(film: CaFilm, frame: int) -> np.ndarray:
    stage, shot = stage_at(film, frame)
    return render_frame(stage, shot, film.look)


def compile_here(film: CaFilm) -> None:
    """Render the first frame small in this process: on a cold numba cache the renderer's
    kernels compile once, here, under one notice, and the workers load them from the cache
    instead of each compiling them (kernel signatures depend on types, not on sizes)."""
    from dataclasses import replace

    stage, shot = stage_at(film, 1)
    render_frame(stage, shot, replace(film.look, width=16, height=12))


def render_png(film: CaFilm, task: FilmFrame) -> bytes:
    """The backends' render function: picklable inputs -> PNG bytes, the same anywhere."""
    from camlab88.base.png import png_bytes

    return png_bytes(render_image(film, task.frame))


def digest(film: CaFilm) -> str:
    """Everything a frame depends on, hashed: a resumed film re-renders what changed."""
    h = hashlib.sha256(format_actors(film.actors).encode())
    for gen in film.timeline.generations:
        for a in (gen.cols, gen.rows, gen.states):
            h.update(np.ascontiguousarray(a, dtype=np.int64).tobytes())
        h.update(b"|")
    for a in (film.lights.positions, film.lights.colours, film.lights.ambient,
              film.views.observer, film.views.viewpoint, film.views.focal):
        h.update(np.ascontiguousarray(a, dtype=np.float64).tobytes())
    h.update(repr((film.timeline.floor, sorted(film.tile_colours.items()), film.per_generation,
                   sorted(film.glide) if film.glide is not None else None,
                   film.look)).encode())
    return h.hexdigest()


def shoot(film: CaFilm, out_dir: str | os.PathLike[str], dask: str | None = None,
          workers: int | None = None, progress=None):  # -> snooker's FilmReport
    """Render every frame not already on disk into ``out_dir/frame_NNNNN.png``."""
    from camlab88.apps.snooker.film.backends import open_backend
    from camlab88.apps.snooker.film.schedule import render_film

    backend = open_backend(film, dask, workers, render=render_png)
    if backend.workers > 1 or dask is not None:
        compile_here(film)
    try:
        return render_film(tasks(film), Path(out_dir), backend, digest(film),
                           progress)
    finally:
        backend.close()
