"""HashLife's tables by address (apps/ca/hashlife/kernels.py: ``address``, ``matrix_at``,
``vector_at``): the arrays come back as the same memory, with their shapes and element
types, writable, for each dtype HashLife uses; and none of those arrays, which own nothing,
can reach Python: only ``node_tables`` and ``all_tables`` make them, only kernels that
return an integer call those, and after real jumps of both kinds every compiled signature
of every kernel reaching them returns an integer."""

from __future__ import annotations

import ast
import inspect

import numpy as np
from camlab88.apps.ca.engine import CENTRE, Engine
from camlab88.apps.ca.hashlife import kernels
from camlab88.apps.ca.library import pattern_path, rules_path
from camlab88.apps.ca.patterns import read_pattern
from camlab88.apps.ca.rules import load_rules
from numba import njit, types
from numba.core.registry import CPUDispatcher


@njit(cache=False)
def _through_addresses(a, b, c):
    return _round_trip(kernels.address(a), kernels.address(b), kernels.address(c),
                       a.shape[0], a.shape[1], b.shape[0], c.shape[0], c.shape[1])


# As HashLife's kernels run: without reference counts, so it returns no array (an array
# handed back from such a kernel would be released twice by a caller that counts them).
@njit(_nrt=False, cache=False)
def _round_trip(pa, pb, pc, ra, ca, nb, rc, cc):
    a = kernels.matrix_at(pa, ra, ca, np.int32(0))
    b = kernels.vector_at(pb, nb, np.int64(0))
    c = kernels.matrix_at(pc, rc, cc, np.uint64(0))
    a[ra - 1, ca - 1] += 1  # writes land in the caller's arrays
    b[nb - 1] = -b[0]
    c[1, 2] = c[rc - 1, cc - 1] + np.uint64(1)
    return (a[2, 3] + b[5] + np.int64(c[0, 1]), a.strides[0], a.strides[1], b.strides[0],
            c.strides[0], c.strides[1])


def test_views_are_the_arrays_themselves() -> None:
    a = np.arange(4 * 8, dtype=np.int32).reshape(4, 8)
    b = np.arange(10, 20, dtype=np.int64)
    c = np.arange(6 * 5, dtype=np.uint64).reshape(6, 5)
    total, *strides = _through_addresses(a, b, c)
    assert total == a[2, 3] + b[5] + c[0, 1]
    assert strides == [*a.strides, *b.strides, *c.strides]
    assert a[3, 7] == 4 * 8 - 1 + 1 and b[9] == -10 and c[1, 2] == 6 * 5 - 1 + 1


def _calls() -> dict[str, set[str]]:
    """Each function of kernels.py -> the module-level names it calls."""
    tree = ast.parse(inspect.getsource(kernels))
    return {f.name: {c.func.id for c in ast.walk(f)
                     if isinstance(c, ast.Call) and isinstance(c.func, ast.Name)}
            for f in tree.body if isinstance(f, ast.FunctionDef)}


MAKERS = {"node_tables", "all_tables"}  # the only kernels that build arrays from addresses


def _reaching() -> set[str]:
    """Every kernel (and template) that calls a maker, directly or through others."""
    calls = _calls()
    reach = set(MAKERS)
    while True:
        more = {f for f, called in calls.items() if called & reach} - reach
        if not more:
            return reach
        reach |= more


def test_only_the_makers_build_arrays_from_addresses() -> None:
    calls = _calls()
    builders = {f for f, called in calls.items() if called & {"matrix_at", "vector_at"}}
    assert builders == MAKERS
    # the makers' arrays leave them only as their return value, to their callers
    callers = {f for f, called in calls.items() if called & MAKERS} - MAKERS
    assert callers == {"_recursion", "advance_bits", "advance_values"}


def test_every_kernel_reaching_the_views_returns_an_integer() -> None:
    for rules_name, pattern in (("life", "gosper_gun"), ("turing_primes", "primes_25")):
        engine = Engine(load_rules(rules_path(rules_name)), algorithm="hashlife")
        placed = read_pattern(pattern_path(pattern))
        grid = placed.placed_grid(CENTRE, CENTRE, "identity")
        if grid is not None:
            engine.set_grid(*grid)
        else:
            engine.set_cells(*placed.placed(CENTRE, CENTRE, "identity"))
        engine.step(64)
    reaching = _reaching() - MAKERS - {"_recursion", "_entry"}
    reaching |= {"recursion_bits", "recursion_values", "step_bits", "step_values"}
    checked = 0
    for name in sorted(reaching):
        kernel = getattr(kernels, name)
        assert isinstance(kernel, CPUDispatcher), name
        assert kernel.targetoptions.get("_nrt") is False, name  # no reference counts
        for signature in kernel.nopython_signatures:
            assert isinstance(signature.return_type, types.Integer), (name, signature)
            checked += 1
    assert checked >= 6
