"""Hypothesis: random scripts -- random text, and random sequences of CCL's own words and
punctuation -- never crash the interpreter: they give a full result or errors with
positions inside the script."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from camlab88.apps.snooker.camera import ccl
from camlab88.apps.snooker.camera.cursor import KEYWORDS
from camlab88.apps.snooker.camera.errors import CclErrors
from tests.snooker_camera.helpers import pink_rolls

MOTION = pink_rolls()
WORDS = sorted(KEYWORDS) + [":", ";", "(", ")", ",", "#", "+", "-", "0", "1", "3", "9", "20",
                            "21", "2.5", "-1", "1e400", "1e-300", "veiwpoint", "\n"]


def check(text: str) -> None:
    r = ccl.run(text, MOTION)
    assert r.observer.shape == (20, 3) and r.viewpoint.shape == (20, 3)
    assert r.focal.shape == (20,)
    assert np.all(np.isfinite(r.observer)) and np.all(np.isfinite(r.viewpoint))
    assert np.all((r.focal >= 8) & (r.focal <= 2000))
    lines = text.count("\n") + 1
    for e in r.errors:
        assert 1 <= e.line <= lines and e.col >= 1 and e.message
    try:
        ccl.compile_script(text, MOTION)
    except CclErrors as exc:
        assert exc.errors


@settings(max_examples=300, deadline=None)
@given(st.lists(st.sampled_from(WORDS), max_size=40))
def test_random_word_salad(words: list[str]) -> None:
    check(":" + " ".join(words))


@settings(max_examples=200, deadline=None)
@given(st.text(max_size=200))
def test_random_text(text: str) -> None:
    check(text)


@settings(max_examples=200, deadline=None)
@given(st.lists(st.sampled_from([
    "until 5", "from 3 until 9", "until pink ball stops", "from cueball strikes until end",
    "observer at camera 3", "viewpoint following pink ball + (0,0,1)", "focal length of 8",
    "observer moving from (0,0,1) to red 2", "camera 3 at hitball - (1,1,1)",
    "coords top left pocket 100 100 100", "viewpoint at (#1,2,3)", "until all balls stop",
    "from any ball starts until frame 20", "observer at (0,0,0)", "viewpoint at (0,0,0)",
]), max_size=12), st.lists(st.sampled_from([":", ";"]), min_size=12, max_size=12))
def test_random_well_formed_commands(parts: list[str], seps: list[str]) -> None:
    check(":" + "".join(p + s for p, s in zip(parts, seps)))
