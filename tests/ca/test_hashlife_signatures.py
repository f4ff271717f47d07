"""Every HashLife kernel Python calls is declared with the exact types it is called with:
each export compiled eagerly from its declared signature alone (as an ahead-of-time build
would) and put in place of the lazy kernel, real jumps of both kinds of leaf still run and
give the direct engine's answers (a call with other types would find no matching
definition)."""

from __future__ import annotations

import importlib
import sys

import numba
import pytest
from camlab88.apps.ca.engine import CENTRE, Engine
from camlab88.apps.ca.library import pattern_path, rules_path
from camlab88.apps.ca.patterns import read_pattern
from camlab88.apps.ca.rules import load_rules
from camlab88.base.kernel_set import KernelSet
from numba.core import sigutils

MODULES = ["store", "upkeep", "evolve", "cellgrid", "census", "grid", "cells", "listing",
           "leaf", "bits.leaves", "bits.window"]


def _eager_exports(monkeypatch: pytest.MonkeyPatch) -> int:
    """Compile every export from its signature, then bind it wherever the lazy one was."""
    eager = {}
    for name in MODULES:
        module = importlib.import_module(f"camlab88.apps.ca.hashlife.{name}")
        kernels = module.kernels
        assert isinstance(kernels, KernelSet)
        for fn_name, signature in kernels.exports.items():
            lazy = kernels.kernels[fn_name]
            # The lazy kernel of that signature first (from the cache): a recursive kernel's
            # eager copy calls it by name (the session's cache guard fails the run if the
            # declared signature is not the one real calls made).
            # By the argument types alone, as a call compiles it: a signature with its
            # return type is another key in numba's cache index (a second "signature").
            lazy.compile(tuple(sigutils.normalize_signature(signature)[0]))
            options = {k: v for k, v in lazy.targetoptions.items()
                       if k not in ("cache", "nopython")}
            eager[id(lazy)] = numba.njit(signature, **options)(lazy.py_func)
    for name, module in list(sys.modules.items()):
        if name.startswith("camlab88.apps.ca.hashlife"):
            for attr, value in list(vars(module).items()):
                if id(value) in eager:
                    monkeypatch.setattr(module, attr, eager[id(value)])
    return len(eager)


CASES = [("life", "gosper_gun", 300), ("life", "acorn", 1000),
         ("turing_primes", "primes_25", 256), ("circuits", "adder_demo", 64)]


def test_exports_compiled_from_their_signatures_run_real_jumps(
        monkeypatch: pytest.MonkeyPatch) -> None:
    assert _eager_exports(monkeypatch) >= 15
    for rules_name, pattern, generations in CASES:
        rules = load_rules(rules_path(rules_name))
        placed = read_pattern(pattern_path(pattern))
        for edges in ("wrap", "bounded"):
            ref = Engine(rules, edges=edges)
            grid = placed.placed_grid(CENTRE, CENTRE, "identity")
            if grid is not None:  # as `ca run` places it: the binary path's dense window
                ref.set_grid(*grid)
            else:
                ref.set_cells(*placed.placed(CENTRE, CENTRE, "identity"))
            jumped = ref.copy()
            jumped.algorithm = "hashlife"
            jumped.step(generations)
            jumped.stats()
            jumped.tree.store.make_room([])  # the collector, keeping the engine's tree
            jumped.step(generations)
            ref.step_direct(2 * generations)
            assert jumped.same_state(ref), (rules_name, pattern, edges)
