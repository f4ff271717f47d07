"""Fuzz every format for a while: ``python fuzz/run.py --seconds N``.

``--engine atheris`` (the default when atheris is installed) runs each target coverage-guided
in its own process for N seconds; ``--engine mutate`` runs the seeded in-process mutator
(what CI uses). Findings are saved under fuzz/findings/<target>/ and the exit status is 1 if
there were any. Figures: docs/reliability.md.
"""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from fuzz.engine import FINDINGS, Report, fuzz, rss_now_mb  # noqa: E402
from fuzz.targets import TARGETS  # noqa: E402


def _atheris(name: str, seconds: float) -> int:
    with tempfile.TemporaryDirectory(prefix=f"camlab88-fuzz-{name}-") as scratch:
        cmd = [sys.executable, "-m", "fuzz.atheris_target", name,
               f"-max_total_time={int(seconds)}", "-timeout=20", "-rss_limit_mb=2048",
               "-print_final_stats=1", f"-artifact_prefix={ROOT / 'fuzz' / 'findings'}/{name}-",
               scratch, str(TARGETS[name].corpus)]
        (ROOT / "fuzz" / "findings").mkdir(exist_ok=True)
        env = dict(os.environ, PYTHONPATH=str(ROOT))
        return subprocess.call(cmd, cwd=ROOT, env=env)


def _progress(report: Report) -> None:
    print(f"  ... {report.line()}  rss {rss_now_mb():.0f} MB", flush=True)


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--seconds", type=float, default=10.0, help="per target (default 10)")
    p.add_argument("--inputs", type=int, help="mutate engine: stop after this many per target")
    p.add_argument("--target", action="append", choices=sorted(TARGETS),
                   help="only these (repeatable; default all)")
    p.add_argument("--engine", choices=["auto", "atheris", "mutate"], default="auto")
    p.add_argument("--seed", type=int, default=0, help="mutate engine's seed")
    p.add_argument("--findings", type=Path, default=FINDINGS,
                   help="mutate engine: save failing inputs here (default fuzz/findings)")
    p.add_argument("--progress", type=float, metavar="S",
                   help="mutate engine: a progress line every S seconds and at each finding")
    args = p.parse_args(argv)
    engine = args.engine
    if engine == "auto":
        try:
            import atheris  # noqa: F401
            engine = "atheris"
        except ImportError:
            engine = "mutate"
    failed = 0
    for name in args.target or sorted(TARGETS):
        if engine == "atheris":
            failed |= _atheris(name, args.seconds) != 0
            continue
        report = fuzz(TARGETS[name], None if args.inputs else args.seconds, args.inputs,
                      args.seed, findings=args.findings, every=args.progress or 0.0,
                      progress=_progress if args.progress else None)
        print(report.line(), flush=True)
        for f in report.findings:
            print("  " + f)
        failed |= bool(report.findings)
    return int(failed)


if __name__ == "__main__":
    sys.exit(main())
