"""camlab88 warm-up: its JIT steps run with the ahead-of-time path off (so numba's cache
holds every kernel even where extensions exist), then the extensions are built."""

from __future__ import annotations

import argparse
import os

from camlab88.base import aot_load

import camlab88.commands.warmup as warmup
from camlab88.commands.warmup import aot


def test_jit_steps_then_the_build(monkeypatch) -> None:
    seen = []
    monkeypatch.setenv(aot_load.OFF_VARIABLE, "1")
    monkeypatch.setattr(warmup, "STEPS", (("toy", "toy:step"),))
    monkeypatch.setattr(warmup, "_step", lambda step, run: seen.append(
        ("step", os.environ.get(aot_load.OFF_VARIABLE))) or "")
    monkeypatch.setattr(aot, "build_step", lambda i, n: seen.append(
        ("build", os.environ.get(aot_load.OFF_VARIABLE), i, n)))
    assert warmup._run(argparse.Namespace()) == 0
    assert seen == [("step", "0"), ("build", "1", 2, 2)]
