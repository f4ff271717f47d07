"""What a replay page costs, as the user meets it (whole processes, start-up included, CPU of
the process and its children, ffmpeg among them): a 30-second Sigma session at 768x512
(the three shipped host streams played down a 9600-baud line, drawing for 24 s) made into
a page with H.264 and with VP9, against a plain ``replay --frames`` of the same session;
the sizes; and with ``--gallery`` the whole figure gallery.

Targets (issue "Replay in any browser"): the 30-s page <= 2 MB, --html <= 2x --frames,
the gallery <= 60 MB. Run by hand: ``python benchmarks/bench_replay_web.py [--gallery]``;
exit 1 when a target is missed. Prints a Markdown table for docs/replay-web.md.
"""

from __future__ import annotations

import os
import platform
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
STREAMS = ["ral_gks_t5684.sig", "pgplot_goc.sig", "crystals_cameron.sig"]
PAGE_LIMIT, COST_LIMIT, GALLERY_LIMIT = 2_000_000, 2.0, 60_000_000


def run(*words: str, cwd: Path) -> tuple[float, float]:
    """Wall and CPU seconds (the process and its children) of one ``camlab88`` command."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    subprocess.run([sys.executable, "-m", "camlab88", *words], cwd=cwd, check=True,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return wall, (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def best(*words: str, cwd: Path, repeat: int = 3) -> tuple[float, float]:
    """The least CPU of ``repeat`` runs (the machine is shared), with its wall time."""
    return min((run(*words, cwd=cwd) for _ in range(repeat)), key=lambda r: r[1])


def main() -> int:
    missed = []
    with tempfile.TemporaryDirectory() as tmp:
        top = Path(tmp)
        stream = top / "busy.sig"
        stream.write_bytes(b"".join((ROOT / "examples" / "sigma" / s).read_bytes()
                                    for s in STREAMS))
        run("sigma", "run", "--headless", "--in", "busy.sig", "--seconds", "30",
            "--speed", "50", "--record", "s30.session", cwd=top)
        run("replay", "s30.session", "--headless", cwd=top)  # kernels compiled and cached
        print(f"Machine: {platform.machine()}, {os.cpu_count()} cores, Python "
              f"{platform.python_version()}; load average {os.getloadavg()[0]:.2f}\n")
        print("| 30-s Sigma session, 768x512, 751 frames | wall (s) | CPU (s) | "
              "x --frames | page | video |")
        print("|---|---|---|---|---|---|")
        plain = best("replay", "s30.session", "--headless", cwd=top)
        frames = best("replay", "s30.session", "--headless", "--frames", "f", cwd=top)
        print(f"| replay (nothing written) | {plain[0]:.2f} | {plain[1]:.2f} | "
              f"{plain[1] / frames[1]:.2f} | | |")
        print(f"| replay --frames DIR (PNGs) | {frames[0]:.2f} | {frames[1]:.2f} | 1.00 | | "
              f"{sum(p.stat().st_size for p in (top / 'f').iterdir()) / 1e6:.2f} MB |")
        for codec in ("h264", "vp9"):
            cost = best("replay", "s30.session", "--html", f"{codec}.html",
                        "--html-codec", codec, cwd=top)
            run("replay", "s30.session", "--html", f"{codec}_dir", "--html-codec", codec,
                cwd=top)
            page = (top / f"{codec}.html").stat().st_size
            video = next((top / f"{codec}_dir").glob("session.*")).stat().st_size
            ratio = cost[1] / frames[1]
            print(f"| replay --html ({codec}) | {cost[0]:.2f} | {cost[1]:.2f} | {ratio:.2f} | "
                  f"{page / 1e6:.2f} MB | {video / 1e6:.2f} MB |")
            if page > PAGE_LIMIT or ratio > COST_LIMIT:
                missed.append(f"{codec}: page {page / 1e6:.2f} MB, {ratio:.2f}x --frames")
        if "--gallery" in sys.argv:
            wall, cpu = run("figures", "--html", "gallery", cwd=top)
            size = sum(p.stat().st_size for p in (top / "gallery").iterdir())
            print(f"\nfigures --html (the whole gallery): {wall:.1f} s wall, {cpu:.1f} s CPU, "
                  f"{size / 1e6:.1f} MB in {len(list((top / 'gallery').iterdir()))} files")
            if size > GALLERY_LIMIT:
                missed.append(f"gallery {size / 1e6:.1f} MB")
    for m in missed:
        print(f"target missed: {m}", file=sys.stderr)
    return 1 if missed else 0


if __name__ == "__main__":
    sys.exit(main())
