"""Misspelt library names get "did you mean" and a missing --frames is named as missing."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from camlab88.apps.ca.library import pattern_path, rules_path
from camlab88.apps.kas import library, timing
from camlab88.base.suggest import did_you_mean


def test_kas_names_near_a_misspelling_are_suggested() -> None:
    with pytest.raises(FileNotFoundError) as err:
        library.resolve("wlak_a")
    assert "did you mean 'walk_a'" in str(err.value)
    assert "Errno" not in str(err.value)
    assert str(err.value).startswith("wlak_a: no such file, and no library entry")


def test_kas_paths_and_library_names_still_resolve(tmp_path: Path) -> None:
    assert library.resolve("walk_a") == library.LIBRARY / "walk_a.kas"
    mine = tmp_path / "mine.kas"
    mine.write_text("x")
    assert library.resolve(mine) == mine
    with pytest.raises(FileNotFoundError, match=r"^.*/nothere\.kas: no such file$"):
        library.resolve(tmp_path / "nothere.kas")


def test_ca_rule_and_pattern_names_suggest() -> None:
    with pytest.raises(FileNotFoundError, match="did you mean 'life'"):
        rules_path("lfie")
    with pytest.raises(FileNotFoundError, match="did you mean 'gosper_gun'"):
        pattern_path("gosper_gn.rle")
    with pytest.raises(FileNotFoundError) as err:
        rules_path("zzzzzz")
    assert "did you mean" not in str(err.value) and "(library: circuits" in str(err.value)


def test_did_you_mean_wording() -> None:
    assert did_you_mean("walk_c", ["walk_a", "walk_b", "xyz"]) == \
        "; did you mean 'walk_b' or 'walk_a'?"  # nearest first (a tie: difflib's order)
    assert did_you_mean("qqq", ["walk"]) == ""


def test_a_missing_frame_count_is_named_as_missing() -> None:
    with pytest.raises(ValueError, match="--frames N is missing"):
        timing.fractions(timing.curve("ease-in"), None)
    with pytest.raises(ValueError, match="at least 2 .*not 1"):
        timing.fractions(timing.curve("ease-in"), 1)
    assert np.allclose(timing.fractions(None, 3), [0.0, 0.5, 1.0])
