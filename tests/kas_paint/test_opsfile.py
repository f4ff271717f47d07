"""The operations file: round trip, errors with file:line:column, truncation, and hand
reordering changing what is in front."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from camlab88.apps.kas.paint import opsfile
from camlab88.apps.kas.paint.ops import Op, OpsFile
from camlab88.apps.kas.paint.palette import Palette
from camlab88.apps.kas.paint.program import PaintProgram
from tests.kas_paint.helpers import one_frame, t5688_line

TEXT = """KAS paint 1
# two overlapping squares
palette 3
colour 0 0 0 0
colour 1 255 0 0
colour 2 0 0 255
gap 0.0
painted 1
ops 2
fill 1 colour 1
fill 2 colour 2 seeds 0.5 0.5
frame 1 ops 1
touch 2.5 2.5 colour 2
end
"""

coord = st.floats(-5, 5, allow_nan=False).map(lambda v: round(v, 3))
op_st = st.one_of(
    st.builds(lambda c, k: Op("fill", k, chains=tuple(c)), st.lists(st.integers(1, 9),
              min_size=1, max_size=4), st.integers(0, 2)),
    st.builds(lambda c, k: Op("line", k, chains=tuple(c)), st.lists(st.integers(1, 9),
              min_size=1, max_size=3), st.integers(0, 2)),
    st.builds(lambda x, y, k: Op("region", k, at=(x, y)), coord, coord, st.integers(0, 2)))


@settings(max_examples=60, deadline=None)
@given(st.lists(op_st, max_size=8), st.floats(0, 1, allow_nan=False))
def test_round_trip(ops: list[Op], gap: float) -> None:
    f = OpsFile(Palette([(0, 0, 0), (1, 2, 3), (250, 251, 252)]), ops, {}, gap, 3)
    g = opsfile.parse(opsfile.ops_text(f))
    assert g.ops == f.ops and g.gap == f.gap and g.palette == f.palette and g.painted == 3
    assert opsfile.ops_text(g) == opsfile.ops_text(f)


def test_parse_example_and_save_atomic(tmp_path) -> None:
    f = opsfile.parse(TEXT, "x.ops")
    assert [o.kind for o in f.ops] == ["fill", "fill"] and f.ops[1].seeds == ((0.5, 0.5),)
    assert f.frame_ops[1][0] == Op("touch", 2, at=(2.5, 2.5), frame=1)
    p = tmp_path / "a.ops"
    opsfile.save(p, f)
    assert opsfile.load(p).ops == f.ops


@pytest.mark.parametrize("bad, where", [
    (TEXT.replace("fill 1 colour 1", "fill 1 colour 7"), "x.ops:10:15:"),
    (TEXT.replace("fill 1 colour 1", "fill x colour 1"), "x.ops:10:6:"),
    (TEXT.replace("fill 1 colour 1", "fil 1 colour 1"), "x.ops:10:1:"),
    (TEXT.replace("colour 1 255 0 0", "colour 1 256 0 0"), "x.ops:5:10:"),
    (TEXT.replace("fill 2 colour 2 seeds 0.5 0.5", "fill 2 colour 2 seeds 0.5"), "x.ops:11:17:"),
    (TEXT.replace("gap 0.0", "gap nan"), "x.ops:7:5:"),
    (TEXT.replace("touch", "region").replace("frame 1 ops 1", "frame 1 ops 2"), "x.ops:14:1:"),
    (TEXT[:TEXT.index("end")], "x.ops:14:1: file ends before"),
    (TEXT + "more\n", "x.ops:15:1: text after 'end'"),
])
def test_errors_name_line_and_column(bad: str, where: str) -> None:
    with pytest.raises(opsfile.OpsFileError) as e:
        opsfile.parse(bad, "x.ops")
    assert str(e.value).startswith(where), str(e.value)


def test_chain_that_does_not_exist_is_refused_before_painting() -> None:
    seq = one_frame(np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0]]))
    f = opsfile.parse(TEXT.replace("fill 2 colour 2", "fill 1 12 colour 2"), "x.ops")
    with pytest.raises(opsfile.OpsFileError, match=r"^x\.ops:11:8: line-chain 12 does not"):
        opsfile.check(f, seq)


def _squares() -> list[np.ndarray]:
    a = np.array([[0, 0], [2, 0], [2, 2], [0, 2]], dtype=float)
    return [a - 1.5, a - 0.5]


def _centre_colour(text: str) -> int:
    seq = one_frame(*_squares())
    f = opsfile.parse(text, "x.ops")
    opsfile.check(f, seq)
    line, term = t5688_line()
    prog = PaintProgram(seq, f)
    line.send(prog.setup())
    line.send(prog.frame(1)[0] + prog.show(1))
    # the squares overlap around (0, 0): which is in front?
    return int(term.planes[256, 768 + 384] & 0x1F)


@pytest.mark.claim(
    "§3.3: the order of shading is that of the first frame's colouring, and can be altered by "
    "editing the operations file",
    measured="two operations swapped by hand in the file: the other one comes out in front",
    verdict="agrees")
def test_hand_reordering_changes_front_to_back() -> None:
    text = TEXT.replace("frame 1 ops 1\ntouch 2.5 2.5 colour 2\n", "")
    assert _centre_colour(text) == 2
    swapped = text.replace("fill 1 colour 1\nfill 2 colour 2 seeds 0.5 0.5\n",
                           "fill 2 colour 2 seeds 0.5 0.5\nfill 1 colour 1\n")
    assert _centre_colour(swapped) == 1


@pytest.mark.claim(
    "§3.3: palette entries edited by mixing defined colours or by stepping red, green and blue",
    measured="the mixed and stepped entries' RGB values",
    verdict="agrees")
def test_palette_mix_and_rgb_steps() -> None:
    p = Palette([(0, 0, 0), (255, 0, 0), (0, 0, 255), (9, 9, 9)])
    assert p.mix(3, {1: 1, 2: 3}) == (64, 0, 191)
    assert p.step(3, "green", 10) == (64, 10, 191)
    assert p.step(3, "blue", 100) == (64, 10, 255)
    assert p.proportions(1) == (1.0, 0.0, 0.0)
    with pytest.raises(ValueError, match="colour 7 is not in the palette"):
        p.step(7, "red", 1)


def test_frames_outside_the_sequence_are_refused_with_their_place() -> None:
    seq = one_frame(*_squares())
    with pytest.raises(opsfile.OpsFileError, match=r"^x\.ops:8:9: painted frame 4 outside 1\.\.1"):
        opsfile.check(opsfile.parse(TEXT.replace("painted 1", "painted 4"), "x.ops"), seq)
    with pytest.raises(opsfile.OpsFileError, match=r"^x\.ops:12:7: frame 3 outside 1\.\.1"):
        opsfile.check(opsfile.parse(TEXT.replace("frame 1 ops", "frame 3 ops"), "x.ops"), seq)


@settings(max_examples=300, deadline=None)
@given(st.data())
def test_any_damage_is_a_clear_error(data: st.DataObject) -> None:
    """Cut, changed or inserted text never crashes the reader: it parses or it raises an
    OpsFileError naming a line and column inside the file (or just after its end)."""
    lines = TEXT.splitlines()
    i = data.draw(st.integers(0, len(lines) - 1))
    how = data.draw(st.sampled_from(["cut", "replace", "insert"]))
    junk = data.draw(st.text(st.characters(codec="utf-8", exclude_categories=("Cs",)),
                             max_size=20))
    if how == "cut":
        lines = lines[:i]
    elif how == "replace":
        lines[i] = junk
    else:
        lines.insert(i, junk)
    text = "\n".join(lines) + "\n"
    try:
        opsfile.parse(text, "x.ops")
    except opsfile.OpsFileError as exc:
        assert 1 <= exc.line <= len(text.splitlines()) + 1 and exc.col >= 1
