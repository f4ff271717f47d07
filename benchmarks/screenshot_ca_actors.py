"""The README's picture of `ca film`: Life's glider gun as chessmen under four lights, the
film's last frame at generation 60 (examples/ca/chess.actors, examples/ca/gun.ccl), 768 x 512
truecolour, written to docs/images/ca_actors_gun.png.

Run: .venv/bin/python benchmarks/screenshot_ca_actors.py
"""

from __future__ import annotations

import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from camlab88.apps.cafilm.build import FilmSpec, build  # noqa: E402
from camlab88.apps.cafilm.film import render_image  # noqa: E402
from camlab88.base.png import write_png  # noqa: E402


def main() -> int:
    film = build(FilmSpec("life", "gosper_gun", 60, str(ROOT / "examples/ca/chess.actors"),
                          str(ROOT / "examples/ca/gun.ccl")))
    out = ROOT / "docs" / "images" / "ca_actors_gun.png"
    write_png(render_image(film, film.n_frames), out)
    print(f"wrote {out} (frame {film.n_frames} of {film.n_frames})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
