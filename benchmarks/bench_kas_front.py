"""KAS device front: how fast the fronts run and how many characters they put on the line.

Run by hand: python benchmarks/bench_kas_front.py
"""

from __future__ import annotations

import time
from pathlib import Path

from camlab88.apps.kas import demo
from camlab88.apps.kas.editor import Editor
from camlab88.apps.kas.program import EditorFront, LineTest, Session, parse_timed_script
from camlab88.apps.kas.program.draw import encode
from camlab88.apps.kas.program.viewer import VIEW_CLIP, ViewerHost, chain_prims, frame_points_px
from camlab88.emulator.harness.sigma import SigmaSessionRun
from camlab88.emulator.harness.sigma_batch import host_periods
from camlab88.emulator.machine import SigmaMachine
from camlab88.protocols.link import LineSettings
from camlab88.protocols.sigma import Encoder

ROOT = Path(__file__).resolve().parent.parent


def editor_session() -> None:
    text = (ROOT / "tests/data/kas_front/edit_all.txt").read_text()
    t0 = time.perf_counter()
    front = EditorFront(Editor(seed=1))
    machine = SigmaMachine("t5684")
    s = SigmaSessionRun(machine, Session(front, machine.host))
    s.run_script(parse_timed_script(text, "edit_all"))
    wall = time.perf_counter() - t0
    sent = sum(len(d) for _, d in s.session.sent)
    first = len(s.session.sent[0][1])
    print(f"editor, edit_all.txt: {float(machine.now):.2f} s of line time in {wall:.2f} s "
          f"wall; {len(s.session.sent)} writes, {sent} characters ({first} for the start-up "
          "screen), "
          f"{front.painter.stats['erased']} erase blocks")


def viewer() -> None:
    seq = demo.build()
    test = LineTest(seq)
    sizes = test.sizes()
    t0 = time.perf_counter()
    for baud in (9600, 19200, 38400, 115200):
        rep = test.run("realtime", baud)
        print(f"viewer, demo ({len(seq)} frames, mean {sum(sizes) / len(sizes):.0f} "
              f"characters a frame incl. 84 for the LUT swap): {baud} baud -> "
              f"{len(rep.shown)} shown, {len(rep.dropped)} dropped")
    t1 = time.perf_counter()
    machine = SigmaMachine("t5684")
    host = ViewerHost(test, "every", machine.host, LineSettings(baud=9600))
    frames = list(host_periods(machine, host, host.period))
    t2 = time.perf_counter()
    print(f"viewer: four real-time runs (host side) {t1 - t0:.3f} s; every-frame run fed to the "
          f"emulated terminal, {len(frames)} periods: {t2 - t1:.2f} s wall")
    enc = Encoder()
    ags = ngs = 0
    for f in seq.frames:
        for pts, cols in frame_points_px(f):
            for p in chain_prims(pts, cols, VIEW_CLIP):
                ags += len(encode(enc, p))
                xy = list(zip(p.data[0::2], p.data[1::2], strict=True))
                ngs += len(enc.colour(p.colour) + enc.polyline(xy if len(xy) > 1 else xy * 2))
    print(f"abbreviated vs normal graphics mode, demo vectors: {ags} vs {ngs} characters "
          f"({ags / ngs:.2f})")


if __name__ == "__main__":
    print("machine: 2-core x86_64 sandbox;", time.strftime("%Y-%m-%d"))
    editor_session()
    viewer()
