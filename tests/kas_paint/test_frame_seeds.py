"""The operations file keeps each frame's seed points (thesis §3.3: "line-chain and colour
numbers, together with seed point coordinates, on a frame by frame basis"): auto-paint records
them, a save/load round trip keeps them, replay paints from them, a frame's seeds edited by
hand change that frame only, and a seed that is not inside its shape (hand-edited or stale)
is listed with its line number instead of leaking; seeds naming no sequence operation are
refused with file:line:column."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from camlab88.apps.kas.model import AnimSequence, Chain, Drawing
from camlab88.apps.kas.paint import areas, opsfile
from camlab88.apps.kas.paint.ops import Op, OpsFile, Seeds
from camlab88.apps.kas.paint.program import PaintProgram
from camlab88.apps.kas.paint.replay import replay
from camlab88.apps.kas.paint.session import PaintSession
from tests.kas_paint.helpers import WALK_FILLS, t5688_line, walk

# a figure-eight (two lobes, left and right of the origin), drawn in two frames
EIGHT_PTS = [(-2, -1), (2, 1), (2, -1), (-2, 1)]
EIGHT = Chain.from_points(EIGHT_PTS)
EIGHT_OPS = [Op("fill", 3, chains=(1,))]


def _colours(seq: AnimSequence, ops: OpsFile) -> tuple[list[np.ndarray], object]:
    (line, term), got = t5688_line(), []

    def shown(n: int, _t: float) -> None:
        x0, y0, x1, y1 = areas.BUFFERS[(n - 1) % 2].box()
        got.append(term.planes[y0:y1 + 1, x0:x1 + 1] & 0x1F)

    rep = replay(PaintProgram(seq, ops), line, on_shown=shown)
    return got, rep


def _lobes(planes: np.ndarray, colour: int) -> tuple[int, int]:
    """Pixels of ``colour`` left and right of the area's centre."""
    mid = areas.AREA_W // 2
    return int(np.sum(planes[:, :mid] == colour)), int(np.sum(planes[:, mid:] == colour))


def _recorded(seq: AnimSequence, ops: OpsFile) -> str:
    s = PaintSession(seq, ops)
    assert s.autopaint() == []
    return opsfile.ops_text(s.ops)


def _two_eights() -> AnimSequence:
    return AnimSequence([Drawing([EIGHT]), Drawing([EIGHT])])


def _two_eights_recorded() -> str:
    """The eight in two frames, its fill painted in the first and auto-painted in the second."""
    return _recorded(_two_eights(), OpsFile(ops=list(EIGHT_OPS), painted=1))


def _second_frames_seeds_edited(start: str, name: str) -> tuple[OpsFile, int]:
    """The two eights' recording, its second frame's seeds line begun ``start`` instead of
    ``seeds fill 1 at``, read as file ``name``; and that line's number."""
    text = _two_eights_recorded().replace("seeds fill 1 at", start, 1)
    f = opsfile.parse(text, name)
    return f, next(r.line_no for r in f.frame_seeds[2])


def test_autopaint_records_every_frames_seeds_and_replay_uses_them() -> None:
    seq = walk(6)
    ops = OpsFile(ops=[*WALK_FILLS, Op("line", 8, chains=(1,))], painted=3)
    text = _recorded(seq, ops)
    back = opsfile.parse(text, "w.ops")
    opsfile.check(back, seq)
    assert sorted(back.frame_seeds) == [1, 2, 4, 5, 6]  # the painted frame: on the op lines
    assert all(len(r) == 2 for r in back.frame_seeds.values())
    assert back.ops[0].seeds and back.ops[1].seeds and not back.ops[2].seeds
    assert opsfile.ops_text(back) == text
    a, ra = _colours(seq, OpsFile(ops=list(ops.ops), painted=3))
    b, rb = _colours(seq, back)
    assert ra.failures == rb.failures == []
    assert all(np.array_equal(x, y) for x, y in zip(a, b, strict=True))


@pytest.mark.claim(
    "§3.3: the operations file stores seed points frame by frame, so local changes in shading can"
    " be made to individual frames",
    measured="a seed removed by hand from one frame's entry changes that frame only",
    verdict="agrees")
def test_a_frames_seed_removed_by_hand_fills_one_lobe_in_that_frame_only() -> None:
    moved = Chain.from_points([(x + 0.25, y) for x, y in EIGHT_PTS])
    seq = AnimSequence([Drawing([EIGHT]), Drawing([moved])])
    text = _recorded(seq, OpsFile(ops=list(EIGHT_OPS), painted=1))
    lines = text.splitlines()
    i = next(k for k, ln in enumerate(lines) if ln.startswith("seeds fill 1 at"))
    words = lines[i].split()
    assert len(words) == 8  # two seeds: one per lobe
    xs = [float(words[4]), float(words[6])]
    keep = int(np.argmax(xs))  # keep the right lobe's seed only
    lines[i] = " ".join(words[:4] + words[4 + 2 * keep:6 + 2 * keep])
    edited = opsfile.parse("\n".join(lines) + "\n", "e.ops")
    got, rep = _colours(seq, edited)
    assert rep.failures == []
    left1, right1 = _lobes(got[0], 3)
    left2, right2 = _lobes(got[1], 3)
    assert left1 > 500 and right1 > 500      # frame 1 untouched: both lobes
    assert left2 < left1 / 4 and right2 > 500  # frame 2: the left lobe only outlined


def test_a_seed_outside_the_shape_is_listed_and_nothing_leaks() -> None:
    f, line = _second_frames_seeds_edited("seeds fill 1 at 4.5 3.0", "o.ops")
    got, rep = _colours(_two_eights(), f)
    assert [(x.frame, x.line) for x in rep.failures] == [(2, f.ops[0].line_no)]
    assert f"recorded at line {line} is not inside" in rep.failures[0].reason
    assert np.sum(got[1] == 3) == 0          # the bad frame's fill is not done at all
    assert sum(_lobes(got[0], 3)) > 1000     # the other frame is painted


def test_seeds_for_no_sequence_operation_refused_with_line_and_column() -> None:
    f, line = _second_frames_seeds_edited("seeds fill 2 at", "s.ops")
    with pytest.raises(opsfile.OpsFileError, match=rf"^s\.ops:{line}:7: seeds for 'fill 2' "
                                                   r"but no such sequence operation"):
        opsfile.check(f, _two_eights())


@pytest.mark.parametrize(("line", "col", "msg"), [
    ("frame 2 ops 0 seeds x", 21, "seeds count must be a whole number"),
    ("frame 2 ops 0 seed 1", 1, "expected 'frame N ops K \\[seeds M\\]'"),
])
def test_bad_frame_headers(line: str, col: int, msg: str) -> None:
    text = _two_eights_recorded().replace("frame 2 ops 0 seeds 1", line)
    n = text.splitlines().index(line) + 1
    with pytest.raises(opsfile.OpsFileError, match=rf"^h\.ops:{n}:{col}: {msg}"):
        opsfile.parse(text, "h.ops")


@pytest.mark.parametrize(("tail", "msg"), [
    ("seeds fill 1 at 0.5", "seed coordinates come in pairs"),
    ("seeds fill 1 0.5 0.5", "missing 'at X Y"),
    ("seeds line 1 at 0 0", "expected 'seeds fill C"),
    ("seeds fill at 0 0", "'seeds fill' names at least one line-chain"),
])
def test_bad_seeds_lines(tail: str, msg: str) -> None:
    lines = _two_eights_recorded().splitlines()
    i = next(k for k, ln in enumerate(lines) if ln.startswith("seeds fill 1 at"))
    lines[i] = tail
    with pytest.raises(opsfile.OpsFileError, match=rf"^b\.ops:{i + 1}:\d+: {msg}"):
        opsfile.parse("\n".join(lines) + "\n", "b.ops")


def test_truncated_seeds_section_noticed() -> None:
    text = _two_eights_recorded()
    cut = text[:text.index("seeds fill 1 at")]
    with pytest.raises(opsfile.OpsFileError, match="file ends before a 'seeds' line"):
        opsfile.parse(cut, "t.ops")


_coord = st.floats(-5, 5, allow_nan=False).map(lambda v: round(v, 3))
_seeds = st.lists(st.tuples(_coord, _coord), max_size=4).map(tuple)
_record = st.one_of(
    st.builds(lambda c, s: Seeds(("fill", tuple(c)), s),
              st.lists(st.integers(1, 9), min_size=1, max_size=3), _seeds),
    st.builds(lambda x, y, s: Seeds(("region", (x, y)), s), _coord, _coord, _seeds))


@settings(max_examples=60, deadline=None)
@given(st.dictionaries(st.integers(1, 30), st.lists(_record, min_size=1, max_size=4),
                       max_size=5))
def test_frame_seeds_round_trip(frame_seeds: dict[int, list[Seeds]]) -> None:
    f = OpsFile(ops=[Op("fill", 1, chains=(1,))], painted=2, frame_seeds=frame_seeds)
    g = opsfile.parse(opsfile.ops_text(f))
    assert g.frame_seeds == frame_seeds
    assert opsfile.ops_text(g) == opsfile.ops_text(f)
