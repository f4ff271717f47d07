"""The §6.2.2 checkpoint file: round trips, the thesis's example, malformed files."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from camlab88.apps.snooker import checkpoint
from camlab88.apps.snooker.checkpoint import Checkpoint, CheckpointError, parse, to_units
from camlab88.apps.snooker.layout import break_off
from camlab88.apps.snooker.physics import simulate_to_rest
from camlab88.apps.snooker.table import Table

DATA = Path(__file__).resolve().parents[1] / "data" / "snooker"
T = Table()


def test_thesis_example_reads() -> None:
    cp = checkpoint.read(DATA / "thesis_example.cp")
    assert cp.n_frames == 3
    assert tuple(cp.positions[0, 0]) == (5000, 6003) and tuple(cp.positions[0, 21]) == (19000, 3000)
    assert tuple(cp.positions[1, 0]) == (5122, 5884)
    assert tuple(cp.positions[1, 6]) == (4998, 5001)  # ball 7, the black
    assert tuple(cp.positions[2, 0]) == (5241, 5768)
    assert tuple(cp.positions[2, 6]) == (4998, 5001)  # did not move in frame 2
    assert tuple(cp.positions[2, 21]) == (19000 - 23, 3000 + 25)
    # And writing it back gives the same text (the thesis's own line format).
    text = (DATA / "thesis_example.cp").read_text()
    assert cp.to_text() == text
    # §6.2.2: 4096 units to the foot (a foot is 0.3048 m): the example's cue ball in metres
    assert np.allclose(checkpoint.to_metres(cp.positions[0, 0]),
                       np.array([5000, 6003]) / 4096 * 0.3048)


def test_simulated_break_round_trips_exactly(tmp_path) -> None:
    frames, _ = simulate_to_rest(T, break_off(T, 5.0))
    cp = Checkpoint.from_metres([f.pos for f in frames])
    path = tmp_path / "break.cp"
    cp.write(path)
    back = checkpoint.read(path)
    # Summing the deltas reproduces every frame's rounded position exactly.
    for k, f in enumerate(frames):
        assert np.array_equal(back.positions[k], to_units(f.pos))
    lines = path.read_text().splitlines()
    assert len(lines) == 22 + len(frames) - 1 + 1 and lines[-1] == "-1"
    assert [p.name for p in tmp_path.iterdir()] == ["break.cp"]  # no temporary left behind
    # 16 bits suffice for on-table positions (the thesis packs x,y in one 32-bit word)
    assert back.positions.max() < 65536


def test_subset_starts_from_that_frame() -> None:
    frames, _ = simulate_to_rest(T, break_off(T, 5.0))
    cp = Checkpoint.from_metres([f.pos for f in frames]).subset(10, 20)
    back = parse(cp.to_text())
    assert back.n_frames == 11 and np.array_equal(back.positions[0], to_units(frames[10].pos))
    with pytest.raises(ValueError):
        Checkpoint.from_metres([f.pos for f in frames]).subset(5, 1000)


@settings(max_examples=40, deadline=None)
@given(st.lists(st.lists(st.tuples(st.integers(0, 65535), st.integers(0, 65535)),
                         min_size=22, max_size=22), min_size=1, max_size=6))
def test_any_integer_positions_round_trip(frames) -> None:
    cp = Checkpoint(np.array(frames, dtype=np.int64))
    assert np.array_equal(parse(cp.to_text()).positions, cp.positions)


GOOD = (DATA / "thesis_example.cp").read_text().splitlines()


@pytest.mark.parametrize(
    "lines,line,message",
    [
        (GOOD[:10], 11, "expected 22 initial position lines"),
        (GOOD[:3] + ["12 34"] + GOOD[4:], 4, "expected 'x,y'"),
        (GOOD[:5] + ["1.5,2"] + GOOD[6:], 6, "not an integer"),
        (GOOD[:22] + ["1 2"] + GOOD[23:], 23, "expected 'ball dx dy'"),
        (GOOD[:22] + ["23 1 1"] + GOOD[23:], 23, "not in 1..22"),
        (GOOD[:22] + ["1 1 1, 1 2 2"] + GOOD[23:], 23, "appears twice"),
        (GOOD[:22] + ["1 1 1,, 2 1 1"] + GOOD[23:], 23, "empty entry"),
        (GOOD[:-1], 25, "missing the negative ball number"),
        (GOOD + ["1 1 1"], 26, "after the end"),
        (GOOD[:22] + ["1 x 1"] + GOOD[23:], 23, "dx 'x' is not an integer"),
    ],
)
def test_malformed_files_name_the_line(tmp_path, lines, line, message) -> None:
    path = tmp_path / "bad.cp"
    path.write_text("\n".join(lines) + "\n")
    with pytest.raises(CheckpointError) as exc:
        checkpoint.read(path)
    assert exc.value.line == line and message in str(exc.value) and str(path) in str(exc.value)


def test_binary_garbage_names_line_and_offset(tmp_path) -> None:
    path = tmp_path / "bin.cp"
    path.write_bytes(b"1,2\n3,4\n\xff\xfe")
    with pytest.raises(CheckpointError, match=r"bin.cp:3: non-ASCII byte at offset 8"):
        checkpoint.read(path)


def test_end_marker_may_follow_entries_on_a_line() -> None:
    text = "\n".join(GOOD[:22]) + "\n1 5 5, -1\n"
    cp = parse(text)
    assert cp.n_frames == 2 and tuple(cp.positions[1, 0]) == (5005, 6008)


@settings(max_examples=150, deadline=None)
@given(st.text(alphabet="0123456789-, \n", max_size=400))
def test_fuzz_never_crashes(text) -> None:
    try:
        parse("\n".join(GOOD[:22]) + "\n" + text)
    except CheckpointError:
        pass


def test_positions_stay_in_the_16_bit_packing(tmp_path) -> None:
    """§6.2.2 packs x and y in 16 bits each: a file taking a ball outside 0..65535 is refused
    at that line; a potted ball dropped behind a baulk pocket (y < 0) is parked in range."""
    path = tmp_path / "off.cp"
    x, y = (int(v) for v in GOOD[0].split(","))
    path.write_text("\n".join(GOOD[:22] + [f"1 0 {65536 - y}", "-1"]) + "\n")
    with pytest.raises(CheckpointError, match="outside the 16-bit packing") as exc:
        checkpoint.read(path)
    assert exc.value.line == 23
    path.write_text("\n".join(GOOD[:22] + [f"1 0 {65535 - y}", "-1"]) + "\n")
    assert tuple(checkpoint.read(path).positions[1, 0]) == (x, 65535)  # the edge is allowed
    pos = np.array(break_off(T, 0.0).pos)
    pos[0] = T.pockets[0].drop  # behind the baulk-right pocket: x and y below 0
    cp = Checkpoint.from_metres([pos])
    assert tuple(cp.positions[0, 0]) == (0, 65535)
    with pytest.raises(ValueError, match="does not fit"):
        Checkpoint.from_metres([pos], (T.length_m * 3, T.width_m))
