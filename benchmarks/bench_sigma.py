"""Sigma benchmarks: abbreviated-mode saving, decode+draw throughput, full-screen flood fill.

Run: python benchmarks/bench_sigma.py   (figures go to docs/perf/sigma.md by hand)
"""

from __future__ import annotations

import math
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from camlab88.commands.demo import sigma_demo_stream  # noqa: E402
from camlab88.emulator.sigma import Terminal  # noqa: E402
from camlab88.emulator.sigma.raster import boundary_fill  # noqa: E402
from camlab88.protocols.sigma import Encoder  # noqa: E402
from camlab88.protocols.sigma.abbreviated import encode_points, new_state, scan_points  # noqa: E402
from tests.sigma.streams import gks_plot, pgplot_plot  # noqa: E402

LINE_CPS = 960  # 9600 baud 8N1


# ---------------------------------------------------------------- drawings
def kas_keyframe(seed: int = 1) -> list[list[tuple[int, int]]]:
    """Line-chains as a tablet gives them: points a few pixels apart along smooth strokes."""
    rng = np.random.default_rng(seed)
    chains = []
    for _ in range(40):
        x, y = (float(v) for v in rng.uniform(100, 600, 2))
        heading = rng.uniform(0, 2 * math.pi)
        pts = []
        for _ in range(int(rng.integers(20, 80))):
            heading += rng.normal(0, 0.25)
            x = min(max(x + 4 * math.cos(heading), 0), 767)
            y = min(max(y + 4 * math.sin(heading), 0), 511)
            pts.append((int(x), int(y)))
        chains.append(pts)
    return chains


def graph_plot() -> list[list[tuple[int, int]]]:
    """A PGPLOT-style graph: box, ticks and three curves sampled every 4 pixels."""
    chains = [[(80, 60), (700, 60), (700, 480), (80, 480), (80, 60)]]
    chains += [[(80 + 62 * k, 60), (80 + 62 * k, 70)] for k in range(11)]
    for f in (1.0, 2.0, 3.5):
        chains.append([(80 + i * 4, 270 + int(150 * math.sin(f * i / 25))) for i in range(156)])
    return chains


def snooker_outlines() -> list[list[tuple[int, int]]]:
    """Polygons and ball outlines of a table in perspective (long edges + small circles)."""
    chains = [[(100, 80), (668, 80), (600, 430), (168, 430), (100, 80)]]
    for k in range(22):
        cx, cy, r = 200 + 20 * (k % 11), 200 + 40 * (k // 11), 7
        chains.append([(cx + int(r * math.cos(a / 8 * 2 * math.pi)),
                        cy + int(r * math.sin(a / 8 * 2 * math.pi))) for a in range(9)])
    return chains


def ngs_stream(chains: list[list[tuple[int, int]]]) -> bytes:
    e = Encoder()
    return b"".join(e.polyline(c) for c in chains)


def ags_stream(chains: list[list[tuple[int, int]]]) -> bytes:
    return b"".join(b"JH" + encode_points(c) + b"\x1f" for c in chains)


def abbreviated_saving() -> list[tuple[str, int, int, float]]:
    rows = []
    for name, chains in (("KAS keyframe (tablet strokes)", kas_keyframe()),
                         ("PGPLOT-style graph", graph_plot()),
                         ("snooker outlines", snooker_outlines())):
        n, a = len(ngs_stream(chains)), len(ags_stream(chains))
        rows.append((name, n, a, a / n))
    return rows


# ---------------------------------------------------------------- driver-formed streams
_AGS_RUN = re.compile(rb"JH([^\x1f]*)\x1f")
_FLUSH = b"BH+-*/"  # PGPLOT's buffer flush: the pen stays down, the pairs go on after it
_NGS_RUN = re.compile(rb"GI(\d{6})GJ((?:\d{6}|BH\+-\*/)+)")


def _ags_run_as_ngs(m: re.Match[bytes]) -> bytes:
    """One JH ... US run re-sent in standard mode: EK for an ESC M mask, GI first, GJ rest."""
    body = m.group(1)
    extra = b""
    for esc in re.findall(rb"\x1b(.)(...)", body, flags=re.S):
        extra += b"EK" + esc[1] if esc[0] == b"M" else b""
    body = re.sub(rb"\x1b...", b"", body, flags=re.S)
    xy = np.empty((len(body) + 1, 2), dtype=np.int32)
    _, k = scan_points(body, 0, new_state(), xy, 0)
    return extra + Encoder().polyline([(int(x), int(y)) for x, y in xy[:k]])


def _ngs_run_as_ags(m: re.Match[bytes]) -> bytes:
    """One GI pair GJ pairs... run re-sent in abbreviated mode; across a flush the run is
    closed (US) before BH and re-opened after it from its last point (a JH move)."""
    out = b""
    last: list[tuple[int, int]] = []
    for k, digits in enumerate((m.group(1) + m.group(2)).split(_FLUSH)):
        pts = [(int(digits[i:i + 3]) - 100, int(digits[i + 3:i + 6]) - 100)
               for i in range(0, len(digits), 6)]
        if k:
            out += _FLUSH
        if pts:
            out += b"JH" + encode_points(last + pts) + b"\x1f"
            last = pts[-1:]
    return out


def driver_stream_saving() -> list[tuple[str, int, int, float, int, int, float]]:
    """Whole streams as the drivers / the demo form them, vectors re-sent in the other mode.

    Rows: (name, NGS chars, AGS chars, ratio, NGS vector chars, AGS vector chars, ratio)."""
    rows = []
    for name, data, native_ags in (("RAL GKS driver stream (AGS)", gks_plot(), True),
                                   ("PGPLOT GOC driver stream (NGS)", pgplot_plot(), False),
                                   ("camlab88 demo stream (AGS)", sigma_demo_stream(), True)):
        if native_ags:
            ags = data
            ngs = _AGS_RUN.sub(_ags_run_as_ngs, data)
            va = sum(len(m.group(0)) for m in _AGS_RUN.finditer(data))
            vn = sum(len(_ags_run_as_ngs(m)) for m in _AGS_RUN.finditer(data))
        else:
            ngs = data
            ags = _NGS_RUN.sub(_ngs_run_as_ags, data)
            vn = sum(len(m.group(0)) for m in _NGS_RUN.finditer(data))
            va = sum(len(_ngs_run_as_ags(m)) for m in _NGS_RUN.finditer(data))
        a, b = Terminal("t5684"), Terminal("t5684")
        a.feed(ngs)
        b.feed(ags)
        assert np.array_equal(a.frame(), b.frame()), f"{name}: the two forms draw differently"
        rows.append((name, len(ngs), len(ags), len(ags) / len(ngs), vn, va, va / vn))
    return rows


# ---------------------------------------------------------------- throughput
def vector_heavy_stream(target_bytes: int, abbreviated: bool = True) -> bytes:
    rng = np.random.default_rng(5)
    parts = [b"\r+-*/"]
    size = 0
    e = Encoder()
    while size < target_bytes:
        chains = kas_keyframe(int(rng.integers(1 << 30)))
        chunk = e.colour(int(rng.integers(1, 16))) + (
            ags_stream(chains) if abbreviated else ngs_stream(chains))
        parts.append(chunk)
        size += len(chunk)
    return b"".join(parts)


def render_seconds(path: Path, model: str = "t5684") -> float:
    out = Path(tempfile.gettempdir()) / "bench_sigma_out.png"
    t0 = time.perf_counter()
    subprocess.run([sys.executable, "-m", "camlab88", "sigma", "render", "--model", model,
                    "--in", str(path), "--out", str(out)], check=True, cwd=ROOT,
                   stdout=subprocess.DEVNULL)
    return time.perf_counter() - t0


def throughput(mbytes: float, abbreviated: bool = True) -> tuple[int, float, float]:
    data = vector_heavy_stream(int(mbytes * 1e6), abbreviated)
    with tempfile.NamedTemporaryFile(suffix=".sigma", delete=False) as f:
        f.write(data)
        path = Path(f.name)
    try:
        render_seconds(path)  # warm the numba cache
        secs = min(render_seconds(path) for _ in range(5))  # min: the machine is shared
    finally:
        os.unlink(path)
    return len(data), secs, len(data) / secs / LINE_CPS


def startup_seconds(stream: bytes = b"\r+-*/DA") -> float:
    with tempfile.NamedTemporaryFile(suffix=".sigma", delete=False) as f:
        f.write(stream)
        path = Path(f.name)
    try:
        render_seconds(path)
        return min(render_seconds(path) for _ in range(5))
    finally:
        os.unlink(path)


# ---------------------------------------------------------------- fill
def fill_ms(h: int, w: int) -> float:
    pix = np.zeros((h, w), dtype=np.uint8)
    boundary_fill(pix, 1, 1, 1, 0xFF, 15, 0xFF)  # compile
    times = []
    for k in range(30):
        pix[:] = 0 if k % 2 else 2
        t0 = time.perf_counter()
        n = boundary_fill(pix, w // 2, h // 2, 3, 0xFF, 15, 0xFF)
        times.append(time.perf_counter() - t0)
        assert n == h * w
    return statistics.median(times) * 1000


def demo_seconds() -> float:
    with tempfile.TemporaryDirectory() as d:
        t0 = time.perf_counter()
        subprocess.run([sys.executable, "-m", "camlab88", "demo", "--headless", "--out", d],
                       check=True, cwd=ROOT, stdout=subprocess.DEVNULL)
        return time.perf_counter() - t0


def main() -> None:
    print("== abbreviated (AGS) vs standard (NGS) characters")
    for name, n, a, r in abbreviated_saving():
        print(f"{name:32s} NGS {n:7d}  AGS {a:7d}  AGS/NGS {r:.2f}")
    print("== the same, whole driver-formed streams (vectors re-sent in the other mode)")
    for name, n, a, r, vn, va, vr in driver_stream_saving():
        print(f"{name:32s} NGS {n:7d}  AGS {a:7d}  AGS/NGS {r:.2f}   vectors only: "
              f"NGS {vn:6d}  AGS {va:6d}  {vr:.2f}")
    print("== decode + draw throughput, whole process (python -m camlab88 sigma render)")
    print(f"load average at start: {os.getloadavg()[0]:.2f} (2 cores, shared)")
    import importlib.util

    # numba imports scipy, when it is installed, as it loads a kernel (its BLAS probe):
    # about 0.25 s more start-up, so say which case was measured
    print(f"scipy installed: {importlib.util.find_spec('scipy') is not None}")
    print(f"start-up, 7-byte stream that draws nothing: {startup_seconds():.2f} s")
    # one NGS vector and one AGS polyline: the numba kernels are loaded
    one = b"\r+-*/GI100100GJ600500" + ags_stream([[(10, 10), (300, 200)]])
    print(f"start-up, stream with one vector (numba kernels loaded): {startup_seconds(one):.2f} s")
    for mb in (0.5, 1.0, 2.0, 8.0):
        n, secs, mult = throughput(mb)
        print(f"{n / 1e6:.1f} MB vector-heavy AGS stream: {secs:.2f} s = {n / secs / 1e6:.2f} "
              f"MB/s = {mult:.0f}x the 960 chars/s line")
    for mb in (1.0, 2.0):
        n, secs, mult = throughput(mb, abbreviated=False)
        print(f"{n / 1e6:.1f} MB vector-heavy NGS (decimal) stream: {secs:.2f} s = "
              f"{n / secs / 1e6:.2f} MB/s = {mult:.0f}x the 960 chars/s line")
    print("== full-screen boundary flood fill (median of 30)")
    print(f"T5684 768x512:   {fill_ms(512, 768):.2f} ms")
    print(f"T5688 1536x1024: {fill_ms(1024, 1536):.2f} ms")
    print("== camlab88 demo --headless (PNG frames + GIF), whole process")
    print(f"{demo_seconds():.1f} s")
    print(f"load average at end: {os.getloadavg()[0]:.2f}")


if __name__ == "__main__":
    main()
