"""Every HashLife kernel Python calls is announced (issue 18's repeat trial: a first
`ca run` spent 8–20 s compiling HashLife's kernels without a word), and a run compiles only
the groups it needs."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

from numba.core.registry import CPUDispatcher

import camlab88.apps.ca.hashlife  # noqa: F401 - registers its kernel groups
from camlab88.apps.ca.hashlife import kernels
from camlab88.base import kernel_notice

HL = "camlab88.apps.ca.hashlife.kernels:"  # + a kernel's name

ROOT = Path(__file__).resolve().parents[2]

# The recursion compiles only inside a kind of leaf's entry: that kind's leaf kernel
# announces it (the runs below see the notice); inlined kernels never compile alone.
INSIDE = {"step_bits", "step_values"}


def test_every_hashlife_kernel_is_in_an_announced_group() -> None:
    compiled_alone = {name for name, value in vars(kernels).items()
                      if isinstance(value, CPUDispatcher)
                      and value.targetoptions.get("inline", "never") != "always"}
    assert {"step_bits", "advance_bits", "join"} <= compiled_alone
    groups = kernel_notice._state.groups
    missing = {n for n in compiled_alone - INSIDE if HL + n not in groups}
    assert not missing, f"kernels compiled without the notice: {sorted(missing)}"
    assert not {n for n in INSIDE if HL + n in groups}
    labels = {groups[HL + n].label for n in compiled_alone - INSIDE}
    assert labels == {"HashLife rule", "HashLife", "HashLife bit-leaf", "HashLife value-leaf",
                      "HashLife cell-list", "HashLife cell listing",
                      "HashLife growth and collection"}


def test_every_hashlife_group_completion_is_a_function() -> None:
    """A misnamed completion would only print "not compiled ahead" at a first run's exit."""
    import importlib

    completions = {g.completion for m, g in kernel_notice._state.groups.items()
                   if m.startswith(HL) and g.completion}
    assert len(completions) == 6
    for completion in completions:
        module, _, function = completion.partition(":")
        assert callable(getattr(importlib.import_module(module), function))


LIFE_RUN = """
from numba.core import event
class Log(event.Listener):
    def on_start(self, ev):
        f = ev.data["dispatcher"].py_func
        print("compiled", f.__module__ + ":" + f.__qualname__, flush=True)
    def on_end(self, ev):
        pass
event.register("numba:compile", Log())
from camlab88.apps.ca.engine import CENTRE, Engine
from camlab88.apps.ca.library import pattern_path, rules_path
from camlab88.apps.ca.patterns import read_pattern
from camlab88.apps.ca.rules import load_rules
engine = Engine(load_rules(rules_path("life")), algorithm="hashlife")
engine.set_grid(*read_pattern(pattern_path("gosper_gun")).placed_grid(CENTRE, CENTRE))
engine.step(300)
print("population", engine.stats()["population"])
"""


def test_a_first_life_run_compiles_the_binary_group_alone(tmp_path: Path) -> None:
    """Life's first run as `ca run --json` makes it (the pattern from its grid; the
    completion at its exit included) compiles the jumps' group alone, not the cell lists or
    the collector: each waits, under its own notice, for a run that needs it; one notice."""
    env = dict(os.environ, NUMBA_CACHE_DIR=str(tmp_path / "cache"), PYTHONPATH=str(ROOT))
    done = subprocess.run([sys.executable, "-c", LIFE_RUN], env=env, capture_output=True,
                          text=True, timeout=600)
    assert done.returncode == 0, done.stderr
    compiled = {line.split()[1] for line in done.stdout.splitlines()
                if line.startswith("compiled ")}
    assert {HL + "step_bits", HL + "advance_bits"} <= compiled
    assert not compiled & {HL + n for n in ("morton", "from_cells", "any_live", "rehash",
                                            "collect", "advance_values", "listing")}
    assert "cell-list" not in done.stderr and "collection" not in done.stderr
    assert "value-leaf" not in done.stderr
    assert done.stderr.count("compiling HashLife kernels") == 1


MULTI_STATE_RUN = LIFE_RUN.replace('"life"', '"{rules}"').replace(
    'placed_grid(CENTRE, CENTRE))', 'placed(CENTRE, CENTRE))').replace(
    '"gosper_gun"', '"{pattern}"').replace("set_grid", "set_cells")


def _compiled_run(code: str, cache: Path) -> tuple[set[str], str]:
    env = dict(os.environ, NUMBA_CACHE_DIR=str(cache), PYTHONPATH=str(ROOT))
    done = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True,
                          text=True, timeout=600)
    assert done.returncode == 0, done.stderr
    return {line.split()[1] for line in done.stdout.splitlines()
            if line.startswith("compiled ")}, done.stderr


def test_each_kind_of_leaf_compiles_once_whichever_runs_first(tmp_path: Path) -> None:
    """A multi-state run's first compile leaves the bit leaves alone; another multi-state
    rule set then compiles nothing; Life after them compiles the bit leaves alone, under
    their own notice (what every jump needs was compiled and completed by the first)."""
    cache = tmp_path / "cache"
    circuits = MULTI_STATE_RUN.format(rules="circuits", pattern="adder_demo")
    compiled, notices = _compiled_run(circuits, cache)
    assert {HL + "step_values", HL + "advance_values"} <= compiled
    assert not compiled & {HL + n for n in ("advance_bits", "grid_leaves", "build", "listing",
                                            "rehash", "collect")}
    assert "value-leaf" in notices and "bit-leaf" not in notices
    primes = MULTI_STATE_RUN.format(rules="turing_primes", pattern="primes_25")
    compiled, notices = _compiled_run(primes, cache)
    assert not {m for m in compiled if m.startswith(HL)}, compiled
    assert "compiling" not in notices
    compiled, notices = _compiled_run(LIFE_RUN, cache)
    assert {m for m in compiled if m.startswith(HL)} >= {
        HL + "step_bits", HL + "advance_bits", HL + "grid_leaves"}
    assert not {m for m in compiled if m.startswith(HL)} & {
        HL + n for n in ("join", "towers", "count", "occupy", "levels", "advance_values")}
    assert [line for line in notices.splitlines() if "compiling" in line] == [
        "camlab88: compiling HashLife bit-leaf kernels, once: ~4 s"]
