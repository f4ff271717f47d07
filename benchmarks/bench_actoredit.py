"""The actor editor's frame costs: a turntable picture at the preview's size, its reduction
to 256 colours, and editor frames with and without a new picture (in-process Rainbow).

Run by hand: ``python benchmarks/bench_actoredit.py``. Prints a Markdown table (medians).
"""

from __future__ import annotations

import os
import platform
import statistics
import tempfile

from _bench import times

from camlab88.apps.actors.editor import layout as L
from camlab88.apps.actors.editor.cell_types import CellType
from camlab88.apps.actors.editor.program import PREVIEW_EVERY, ActorEditor
from camlab88.apps.actors.editor.quantise import quantise
from camlab88.apps.actors.model import read_actors
from camlab88.apps.actors.preview import turntable
from camlab88.emulator.machine import RainbowMachine

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CHESS = os.path.join(ROOT, "examples", "ca", "chess.actors")
SIZE = (L.PREVIEW[2], L.PREVIEW[3])


def median_ms(fn, repeat: int = 12) -> float:
    return 1000 * statistics.median(times(fn, repeat))


def main() -> None:
    actors = read_actors(CHESS).actors
    turntable(actors[1], 0, SIZE)  # compile the renderer's kernels
    print(f"Machine: {platform.machine()}, {os.cpu_count()} cores, Python "
          f"{platform.python_version()}; load average {os.getloadavg()[0]:.2f}\n")
    print("| actor | turntable picture 368x296 (ms) | 256 colours (ms) |")
    print("|---|---|---|")
    for _state, a in sorted(actors.items()):
        pic = turntable(a, 30, SIZE)
        render = median_ms(lambda a=a: turntable(a, 30, SIZE))
        print(f"| {a.name} ({len(a.parts)} parts) | {render:.0f} "
              f"| {median_ms(lambda pic=pic: quantise(pic)):.1f} |")
    with tempfile.TemporaryDirectory() as tmp:
        import shutil

        path = os.path.join(tmp, "chess.actors")
        shutil.copy(CHESS, path)
        session = RainbowMachine()
        ed = ActorEditor(session.client, path, [CellType(1, "form 1", (0, 255, 0))], "life")
        ts = times(ed.frame, 8 * PREVIEW_EVERY)
        new = [t for i, t in enumerate(ts) if i % PREVIEW_EVERY == 0][1:]
        rest = [t for i, t in enumerate(ts) if i % PREVIEW_EVERY][1:]
        print(f"\nEditor frame with a new picture: {1000 * statistics.median(new):.0f} ms; "
              f"without: {1000 * statistics.median(rest):.1f} ms (pawn, medians of "
              f"{len(new)} and {len(rest)}).")


if __name__ == "__main__":
    main()
