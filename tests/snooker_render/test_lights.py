from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from apps.snooker.render.lights import LightsError, canopy, parse_lights, read_lights


@pytest.mark.claim(
    "§6.4.1: multiple lights, commonly four bulbs in a canopy above the table",
    measured="the default lights: four point sources above the table",
    verdict="agrees")
def test_canopy_is_four_bulbs_above_the_table() -> None:
    c = canopy()
    assert c.positions.shape == (4, 3) and np.all(c.positions[:, 2] > 0.5)


def test_parse_forms() -> None:
    lights = parse_lights("# two bulbs\nambient 0.1\n0 0 1\n1 0.5 1.2 0.4\n-1 0 1 0.1 0.2 0.3\n")
    assert lights.positions.tolist() == [[0, 0, 1], [1, 0.5, 1.2], [-1, 0, 1]]
    assert lights.colours[1].tolist() == [0.4] * 3
    assert lights.colours[2].tolist() == [0.1, 0.2, 0.3]
    assert lights.ambient.tolist() == [0.1] * 3


@pytest.mark.parametrize(("text", "where"), [
    ("0 0 1\n0 0\n", "f.txt:2:1:"),
    ("0 0 1\n1 x 1\n", "f.txt:2:3:"),
    ("0 0 -1\n", "f.txt:1:5:"),
    ("0 0 1 -2\n", "f.txt:1:7:"),
    ("# nothing\n", "f.txt:1:1:"),
    ("ambient\n", "f.txt:1:1:"),
    ("0 0 1 nan\n", "f.txt:1:7:"),
])
def test_errors_name_file_line_and_column(text: str, where: str) -> None:
    with pytest.raises(LightsError, match="^" + where):
        parse_lights(text, "f.txt")


def test_read_lights_errors(tmp_path: Path) -> None:
    with pytest.raises(LightsError, match="missing.txt:0:0: cannot read"):
        read_lights(tmp_path / "missing.txt")
    bad = tmp_path / "bad.txt"
    bad.write_bytes(b"0 0 1\n\xff\n")
    with pytest.raises(LightsError, match="bad.txt:1:"):
        read_lights(bad)


@settings(max_examples=200, deadline=None)
@given(st.text(alphabet=st.sampled_from(list("0123456789 .-eE#\nambientx\t")), max_size=60))
def test_parser_never_fails_otherwise(text: str) -> None:
    try:
        lights = parse_lights(text, "h")
    except LightsError as exc:
        assert str(exc).startswith("h:")
    else:
        assert len(lights.positions) >= 1 and np.all(lights.positions[:, 2] > 0)
