"""A small film of a glider under chess actors, built as the command builds it."""

from __future__ import annotations

from pathlib import Path

from camlab88.apps.cafilm.build import FilmSpec, build
from camlab88.apps.cafilm.film import CaFilm

ROOT = Path(__file__).resolve().parents[2]
CHESS = str(ROOT / "examples" / "ca" / "chess.actors")


def glider_film(generations: int = 2, per_generation: int = 2, size: tuple[int, int] = (96, 64),
                **kw: object) -> CaFilm:
    spec = FilmSpec("life", "glider", generations, CHESS, per_generation=per_generation,
                    size=size, **kw)
    return build(spec)
