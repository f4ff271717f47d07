"""The in-process fuzz loop: seeds first, then seeded mutations, each input watched for an
unexpected exception, a hang (SIGALRM after ``timeout`` s) and memory growth."""

from __future__ import annotations

import hashlib
import os
import random
import resource
import signal
import time
import traceback
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

from fuzz.mutate import mutate
from fuzz.targets import Target

FINDINGS = Path(__file__).parent / "findings"


class Hang(Exception):
    """An input took longer than the bound."""


@dataclass
class Report:
    target: str
    inputs: int = 0
    seconds: float = 0.0
    findings: list[str] = field(default_factory=list)
    grew_mb: float = 0.0

    def line(self) -> str:
        rate = self.inputs / self.seconds if self.seconds else 0.0
        return (f"{self.target:20s} {self.inputs:9d} inputs {self.seconds:7.1f} s "
                f"{rate:9.0f}/s  memory +{self.grew_mb:.0f} MB  findings {len(self.findings)}")


def _rss_mb() -> float:
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024  # Linux: KB


def rss_now_mb() -> float:
    """Resident memory now (ru_maxrss is only the peak), from /proc where there is one."""
    try:
        with open("/proc/self/statm") as fh:
            return int(fh.read().split()[1]) * os.sysconf("SC_PAGE_SIZE") / 2**20
    except OSError:
        return 0.0


def _alarm(signum: int, frame: object) -> None:
    raise Hang


def _save(target: Target, data: bytes, why: str, folder: Path) -> str:
    digest = hashlib.sha1(data).hexdigest()[:12]
    out = folder / target.name
    out.mkdir(parents=True, exist_ok=True)
    (out / digest).write_bytes(data)
    return f"{target.name}: {why} (input saved as {out / digest})"


def run_one(target: Target, data: bytes, timeout: float) -> str | None:
    """None if the target handled ``data``; else what went wrong."""
    old = signal.signal(signal.SIGALRM, _alarm)
    signal.setitimer(signal.ITIMER_REAL, timeout)
    try:
        target.check(data)
    except Hang:
        return f"no answer within {timeout:g} s"
    except Exception:  # any other exception is what fuzzing looks for
        return traceback.format_exc(limit=-3).strip().splitlines()[-1]
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, old)
    return None


def fuzz(target: Target, seconds: float | None = None, inputs: int | None = None,
         seed: int = 0, timeout: float = 20.0, memory_mb: float = 1024.0,
         findings: Path = FINDINGS, progress: Callable[[Report], None] | None = None,
         every: float = 60.0) -> Report:
    """Every seed file, then mutations of them until ``seconds`` or ``inputs`` run out;
    ``progress`` (if given) sees the report so far every ``every`` seconds and after each
    new finding, so a run of hours can be watched."""
    rng = random.Random(f"{target.name}:{seed}")
    seeds = target.seeds() or [b""]
    report = Report(target.name)
    start, base = time.monotonic(), _rss_mb()
    k, shown = 0, start
    seen: set[str] = set()
    while True:
        if inputs is not None and k >= inputs + len(seeds):
            break
        if seconds is not None and k >= len(seeds) and time.monotonic() - start >= seconds:
            break
        data = seeds[k] if k < len(seeds) else mutate(rng.choice(seeds), rng)
        why = run_one(target, data, timeout)
        news = why is not None and why not in seen  # one report per distinct failure
        if news:
            seen.add(why)
            report.findings.append(_save(target, data, f"input {k}: {why}", findings))
        report.grew_mb = max(report.grew_mb, _rss_mb() - base)
        if report.grew_mb > memory_mb:
            report.findings.append(_save(target, data, f"memory grew {report.grew_mb:.0f} MB",
                                         findings))
            break
        k += 1
        if progress is not None and (news or time.monotonic() - shown >= every):
            shown = time.monotonic()
            report.inputs, report.seconds = k, shown - start
            progress(report)
    report.inputs, report.seconds = k, time.monotonic() - start
    return report
