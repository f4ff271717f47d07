"""base.lockstep: a callback-driven program's frames as a generator, computed no further
than the frame taken; its errors raised in the taker; closing it early ends its thread."""

from __future__ import annotations

import threading

import numpy as np
import pytest

from camlab88.base.lockstep import lockstep


def _program(state: dict, n: int = 5, fail_at: int | None = None):
    def run(show):
        for k in range(n):
            state["k"] = k
            if k == fail_at:
                raise ValueError(f"failed at {k}")
            show(np.array([k]))
    return run


def test_the_program_is_never_ahead_of_the_frame_taken() -> None:
    state: dict = {}
    got = []
    for frame in lockstep(_program(state)):
        assert state["k"] == int(frame[0])
        got.append(int(frame[0]))
    assert got == [0, 1, 2, 3, 4]


def test_an_error_is_raised_in_the_taker() -> None:
    with pytest.raises(ValueError, match="failed at 2"):
        list(lockstep(_program({}, fail_at=2)))


def test_closing_early_ends_the_programs_thread() -> None:
    frames = lockstep(_program({}, n=1000))
    next(frames)
    frames.close()
    for t in threading.enumerate():
        if t.name == "camlab88 lockstep":
            t.join(timeout=10)
            assert not t.is_alive()
