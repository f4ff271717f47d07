"""Regenerates the generated files of apps/ca/library/.

Run: python -m camlab88.apps.ca.library_build.

The tests check that the shipped files equal what this produces, so they cannot drift.
"""

from __future__ import annotations

import random
from pathlib import Path

from camlab88.apps.ca import langtons_loops, maze, turing
from camlab88.apps.ca.patterns import Pattern, format_native, format_rle

LIBRARY = Path(__file__).resolve().parent / "library"


def soup(size: int = 48, density: float = 0.35, seed: int = 7) -> Pattern:
    rng = random.Random(seed)
    cells = [(x, y, 1) for y in range(size) for x in range(size) if rng.random() < density]
    return Pattern.from_cells(cells, ref=(size // 2, size // 2), name="grazing soup",
                              rule="overgrazing",
                              comments=[f"random {size}x{size} soup, density {density}, "
                                        f"seed {seed}"])


def generated() -> dict[str, str]:
    files = {"turing_primes.rules": turing.rules_text(),
             "langtons_loops.rules": langtons_loops.rules_text()}
    for n in (25, 23):
        files[f"primes_{n}.pat"] = format_native(turing.pattern(n))
    files["maze_demo.pat"] = format_native(maze.build()[0])
    files["maze_corner.pat"] = format_native(maze.corner())
    files["grazing_soup.rle"] = format_rle(soup())
    try:
        from camlab88.apps.ca import circuits
    except ImportError:  # pragma: no cover - circuits are optional
        return files
    files.update(circuits.library_files())
    return files


def main() -> None:
    for name, text in generated().items():
        (LIBRARY / name).write_text(text, encoding="utf-8")
        print(f"wrote {LIBRARY / name}")


if __name__ == "__main__":
    main()
