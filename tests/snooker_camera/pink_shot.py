"""The shipped shot of the thesis's example camera script (apps.snooker.visualiser.demo makes
it with the motion program's aiming tools).  Regenerate the shipped files (a test checks
they are what it makes):
    .venv/bin/python -m tests.snooker_camera.pink_shot
"""

from __future__ import annotations

from pathlib import Path

from camlab88.apps.snooker.visualiser.demo import example_shot as make

DATA = Path(__file__).resolve().parents[1] / "data" / "snooker_camera"
CHECKPOINT = DATA / "pink_shot.checkpoint"
SESSION = DATA / "pink_shot.session.json"
__all__ = ["make"]


def main() -> None:
    s = make()
    s.checkpoint().write(CHECKPOINT)
    s.save(SESSION)
    print(f"wrote {CHECKPOINT} ({s.checkpoint().n_frames} frames) and {SESSION}")


if __name__ == "__main__":
    main()
