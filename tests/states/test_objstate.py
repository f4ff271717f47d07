"""camlab88.base.objstate: a graph captured as data and restored in place; what it refuses."""

from __future__ import annotations

import collections
import json
import random
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest

from camlab88.base.objstate import StateError, capture, restore


def _through_json(tree):
    return json.loads(json.dumps(tree, sort_keys=True))


def test_values_round_trip_and_arrays_are_written_in_place() -> None:
    from camlab88.emulator.harness.program_state import StateOptions as Box  # a plain class of ours

    a = Box()
    plane = np.arange(12, dtype=np.uint8).reshape(3, 4)
    a.plane, a.view = plane, plane[1]
    a.values = [1, 2.5, float("inf"), "s", b"x" * 300, Fraction(1, 3), (1, 2), {3},
                frozenset({4}), collections.Counter("aab"), collections.deque([1], 5), None]
    a.rng, a.nprng = random.Random(5), np.random.default_rng(7)
    a.path, a.fn = Path("/x"), len
    a.self_ref = a
    tree, blobs = capture(a)
    want = (a.rng.random(), a.nprng.integers(1 << 30))
    fresh = Box()
    fresh.plane = np.zeros((3, 4), np.uint8)
    fresh.view, fresh.path, fresh.fn = fresh.plane[1], Path("/fresh"), abs
    fresh.rng, fresh.nprng = random.Random(0), np.random.default_rng(0)
    out = restore(fresh, _through_json(tree), blobs)
    assert out is fresh and fresh.self_ref is fresh
    assert (fresh.plane == plane).all() and np.shares_memory(fresh.view, fresh.plane)
    assert fresh.values[:2] == [1, 2.5] and fresh.values[2] == float("inf")
    assert fresh.values[3:] == a.values[3:]
    assert fresh.path == Path("/fresh") and fresh.fn is abs  # never read from a state
    assert (fresh.rng.random(), fresh.nprng.integers(1 << 30)) == want


def test_a_callback_made_while_running_is_made_again_from_its_code() -> None:
    from camlab88.apps.kas.editor import Editor
    from camlab88.apps.kas.editor_edit import bindings

    ed = Editor(None, None, 0)
    bindings(ed)["m"]()  # "move points": waits for two points, then calls back
    tree, blobs = capture(ed)
    fresh = Editor(None, None, 0)
    assert fresh.pending is None
    restore(fresh, _through_json(tree), blobs)
    assert fresh.pending is not None and fresh.pending.done is not ed.pending.done
    assert fresh.pending.done.__code__ is ed.pending.done.__code__
    assert fresh.pending.done.__closure__[0].cell_contents is fresh  # its cell: the new editor
    assert fresh.pending.name == "move points"


def test_a_running_generator_is_named_not_saved() -> None:
    def gen():
        yield 1
        yield 2

    g = gen()
    next(g)
    with pytest.raises(StateError, match=r"state\[1\]: cannot save a running generator"):
        capture([1, g])


@pytest.mark.parametrize("name", ["os:system", "subprocess:Popen", "tests.x:Y",
                                  "camlab88.emulator.nothing_loaded_here:X"])
def test_a_state_never_names_code(name: str) -> None:
    with pytest.raises(StateError, match="not one of this program's"):
        restore(None, {"O": name, "id": 0, "a": []}, [])


def test_a_damaged_tree_is_a_state_error() -> None:
    for tree in ({"L": [{"R": 5}], "id": 0}, {"zz": 1}, [1], {"A#": 3, "dt": "<u1", "sh": [1],
                                                               "id": 0}):
        with pytest.raises(StateError):
            restore(None, tree, [])


def test_a_state_never_chooses_a_file_name_the_command_line_gave() -> None:
    from camlab88.emulator.harness.program_state import StateOptions as Box  # a plain class of ours

    saved = Box()
    saved.out, saved.message = "/etc/passwd", "typed text"
    tree, blobs = capture(saved)
    fresh = Box()
    fresh.out, fresh.message = "walk.ops", ""
    restore(fresh, _through_json(tree), blobs, pinned=frozenset({"walk.ops"}))
    assert (fresh.out, fresh.message) == ("walk.ops", "typed text")


def test_a_delegating_wrapper_made_without_its_delegate_is_no_endless_recursion() -> None:
    """A damaged state can make the line's tap (``__getattr__`` asks its endpoint) without
    the endpoint: reading its attributes must not call that ``__getattr__`` (it called
    itself until the C stack overflowed: a segfault, found by the cli-load-state test)."""
    from camlab88.emulator.harness.sigma_line import OutsideTap

    assert "__getattr__" in vars(OutsideTap)
    tree = {"O": "camlab88.emulator.harness.sigma_line:OutsideTap", "id": 0,
            "a": [["taken", {"L": [], "id": 1}], ["zz", {"R": 99}]]}
    with pytest.raises(StateError, match=r"state.zz: reference 99 before its object"):
        restore(None, tree, [])


def test_a_refused_tree_leaves_every_object_it_had_written_as_it_was() -> None:
    from camlab88.emulator.harness.program_state import StateOptions as Box  # a plain class of ours

    saved, fresh = Box(), Box()
    saved.items, saved.table, saved.seen = [1, 2], {"a": 1}, {3}
    saved.plane, saved.rng = np.ones((2, 2), np.uint8), random.Random(1)
    fresh.items, fresh.table, fresh.seen = [9], {"b": 2}, {4}
    fresh.plane, fresh.rng = np.zeros((2, 2), np.uint8), random.Random(2)
    tree, blobs = capture(saved)
    tree = _through_json(tree)
    tree["a"].append(["broken", {"R": 10**9}])  # the last thing read: all else written
    before = (fresh.items, fresh.table, fresh.seen, fresh.plane, fresh.rng)
    contents = capture(fresh)
    with pytest.raises(StateError, match="state.broken: reference"):
        restore(fresh, tree, blobs)
    assert (fresh.items, fresh.table, fresh.seen, fresh.plane, fresh.rng) == before  # same
    assert capture(fresh) == contents  # and as they were
    assert not hasattr(fresh, "broken")


def test_a_state_is_never_written_into_what_a_module_shares() -> None:
    from camlab88.apps.ca.program.menus import EDIT_ITEMS
    from camlab88.emulator.harness.program_state import StateOptions as Box

    kept = dict(EDIT_ITEMS)
    saved, fresh = Box(), Box()
    saved.items = {"centre": "changed by a state"}
    fresh.items = EDIT_ITEMS  # as a menu holds its module's item list
    restore(fresh, *capture(saved))
    assert EDIT_ITEMS == kept and fresh.items is not EDIT_ITEMS
    assert fresh.items == {"centre": "changed by a state"}
