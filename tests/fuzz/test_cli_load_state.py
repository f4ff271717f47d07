"""Damaged whole-program states through the command line's ``--load-state FILE``: real states
of every program that declares one (the CA program, the snooker program, the Sigma
terminal's run, the Rainbow demo, the three players kas view, snooker visualise and snooker
replay, and the five editors whose state is their input log: kas edit, kas path, kas paint,
the snooker camera tool, the CA actors editor: fuzz.states.PROGRAMS), saved by the
commands themselves, then loaded back by the same commands in process after random damage
— to the file's bytes, to its header's declared values (fuzz.states edits them with the
parts opened, so the damage gets past zlib's checksums) and to its parts (the machines' own
states).
Every outcome is a clean run or one line naming the file with status 1 or 2: never a
traceback, a hang or runaway memory. Each load runs in a forked copy of this process: not to
keep a damaged state from leaking into the next example (a refused load changes nothing and
none writes into module-level objects: tests/states/test_refused_loads.py loads them in
process), but to kill a hang in compiled code and to bound each load's memory
(fuzz.states.check_isolated). The long coverage-guided run is fuzz/run.py's
``cli-load-state`` target."""

from __future__ import annotations

import random
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from fuzz.mutate import mutate
from fuzz.states import (
    ODD_VALUES,
    PROGRAMS,
    check_isolated,
    close_state,
    edit_tree,
    load_state,
    open_state,
    program_of,
    save_state,
)
from fuzz.targets import CORPUS

LIMIT_S = 20.0
MEMORY_MB = 1024.0


class Seeds:
    """The saved states by program, with a short repr (hypothesis prints its arguments)."""

    def __init__(self, folder: Path) -> None:
        self.states = {name: save_state(name, folder / f"{name}.c88state") for name in PROGRAMS}

    def __getitem__(self, name: str) -> bytes:
        return self.states[name]

    def __repr__(self) -> str:
        return f"Seeds({sorted(self.states)})"


@pytest.fixture(scope="module")
def seeds(tmp_path_factory: pytest.TempPathFactory) -> Seeds:
    return Seeds(tmp_path_factory.mktemp("states"))


@pytest.fixture(scope="module")
def scratch(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return tmp_path_factory.mktemp("loads") / "input.c88state"


@pytest.mark.parametrize("name", sorted(PROGRAMS))
def test_a_saved_state_loads_back_and_opening_it_changes_nothing(name, seeds, scratch) -> None:
    assert close_state(open_state(seeds[name])) == seeds[name]
    assert program_of(open_state(seeds[name])) == name  # (the long target's choice)
    scratch.write_bytes(seeds[name])
    code, err = load_state(name, scratch, 300.0)
    assert code == 0, err


SEEDS = CORPUS / "cli-load-state"


def test_the_long_target_has_a_seed_of_every_program() -> None:
    assert sorted(p.name for p in SEEDS.iterdir()) == sorted(f"{n}.opened" for n in PROGRAMS)


@pytest.mark.parametrize("name", sorted(PROGRAMS))
def test_the_long_targets_seed_loads_in_this_process(name, scratch) -> None:
    """The committed seeds (fuzz/make_corpus.py) were saved by another process: each loads
    with status 0 here, or the long run would start from a refusal (a state version raised
    since, or a state that loads only where it was saved)."""
    opened = (SEEDS / f"{name}.opened").read_bytes()
    assert program_of(opened) == name
    scratch.write_bytes(close_state(opened))
    code, err = load_state(name, scratch, 300.0)
    assert code == 0, f"{err} (make the seeds again: fuzz/make_corpus.py's _cli_states)"


@pytest.mark.parametrize("name", sorted(PROGRAMS))
def test_a_state_damaged_in_its_envelope_is_refused_naming_the_file(name, seeds,
                                                                    scratch) -> None:
    other = seeds[min(set(PROGRAMS) - {name})]
    for data in (seeds[name][:len(seeds[name]) // 2], b"", other):
        scratch.write_bytes(data)
        code, err = load_state(name, scratch, LIMIT_S)
        assert code == 2 and str(scratch) in err and "Traceback" not in err, err


def test_a_state_whose_program_refuses_its_values_is_refused_naming_the_file(
        seeds, scratch) -> None:
    """A value of the declared kind the program itself refuses (the CA program's edit mode
    is a text, but only one of the program's modes is taken): one line naming the file,
    status 2."""
    data = seeds["ca-program"]
    opened = open_state(data)
    assert b'"edit_mode": "step_up"' in opened
    damaged = close_state(opened.replace(b'"edit_mode": "step_up"', b'"edit_mode": "/x"', 1))
    assert check_isolated("ca-program", damaged, scratch, LIMIT_S, MEMORY_MB) is None
    scratch.write_bytes(damaged)
    code, err = load_state("ca-program", scratch, LIMIT_S)
    assert code == 2 and str(scratch) in err and "not one of the program's" in err, err


json_values = st.sampled_from(ODD_VALUES) | st.integers() | st.floats(allow_nan=False) | \
    st.text(max_size=8)


@settings(max_examples=24, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(name=st.sampled_from(sorted(PROGRAMS)),
       edits=st.lists(st.tuples(st.integers(0, 1 << 30), json_values), min_size=1,
                      max_size=3))
def test_values_changed_in_a_state_never_give_a_traceback(name, edits, seeds,
                                                          scratch) -> None:
    data = edit_tree(seeds[name], edits)
    assert check_isolated(name, data, scratch, LIMIT_S, MEMORY_MB) is None


@settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(name=st.sampled_from(sorted(PROGRAMS)), seed=st.integers(0, 1 << 32))
def test_bytes_changed_in_an_opened_state_never_give_a_traceback(name, seed, seeds,
                                                                 scratch) -> None:
    data = close_state(mutate(open_state(seeds[name]), random.Random(seed)))
    assert check_isolated(name, data, scratch, LIMIT_S, MEMORY_MB) is None
