"""KAS file formats: round trips, and bad or truncated files named by file and line."""

from __future__ import annotations

import os

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from camlab88.apps.kas import files
from camlab88.apps.kas.files import KasFileError, SamplePath, Timing
from camlab88.apps.kas.model import AnimSequence, Chain, Drawing
from tests.support.refusals import refusal_of

coord = st.floats(-1e4, 1e4, allow_nan=False, allow_infinity=False)
chain_st = st.builds(
    lambda pts, col, sec: Chain(np.array(pts).reshape(-1, 2), np.full(len(pts), col), sec),
    st.lists(st.tuples(coord, coord), min_size=1, max_size=12),
    st.integers(1, 8), st.integers(0, 5))
drawing_st = st.builds(Drawing, st.lists(chain_st, max_size=5))


@settings(max_examples=60, deadline=None)
@given(drawing_st)
def test_keyframe_round_trip(d):
    back = files.parse_keyframe(files.keyframe_text(d))
    assert back.equals(d)


@settings(max_examples=30, deadline=None)
@given(st.lists(drawing_st, max_size=4), st.sampled_from([24.0, 25.0, 12.5]))
def test_sequence_round_trip(frames, fps):
    back = files.parse_sequence(files.sequence_text(AnimSequence(frames, fps)))
    assert back.fps == fps and len(back) == len(frames)
    assert all(a.equals(b) for a, b in zip(back.frames, frames))


@settings(max_examples=40, deadline=None)
@given(st.lists(st.tuples(coord, coord), min_size=2, max_size=20),
       st.lists(st.floats(0, 1), max_size=20).map(sorted))
def test_path_and_timing_round_trip(path, ticks):
    p = files.parse_path(files.path_text(SamplePath(path)))
    assert np.array_equal(p.points, np.array(path))
    t = files.parse_timing(files.timing_text(Timing("ticks", ticks, "hand")))
    assert t.kind == "ticks" and t.name == "hand" and np.array_equal(t.values, ticks)
    c = Timing("curve", [(0, 0), (0.3, 0.1), (1, 1)], "")
    assert np.array_equal(files.parse_timing(files.timing_text(c)).values, c.values)


@settings(max_examples=80, deadline=None)
@given(drawing_st.filter(lambda d: d.n_points > 0), st.data())
def test_any_truncation_is_an_error_naming_a_line(d, data):
    text = files.keyframe_text(d)
    lines = text.splitlines()
    cut = data.draw(st.integers(0, len(lines) - 1))
    with pytest.raises(KasFileError) as err:
        files.parse_keyframe("\n".join(lines[:cut]), "k.kas")
    assert str(err.value).startswith("k.kas:")


@settings(max_examples=80, deadline=None)
@given(st.binary(max_size=200))
def test_garbage_never_crashes(blob):
    text = blob.decode("latin-1")
    for parse in (files.parse_keyframe, files.parse_sequence, files.parse_path,
                  files.parse_timing):
        refusal_of(parse, text, "g.kas", KasFileError)


def test_bad_number_named_by_line(tmp_path):
    f = tmp_path / "k.kas"
    f.write_text("KAS keyframe 1\n# a comment\nchains 1\nchain section=0 points=2\n"
                 "0 0 1\n1 zero 1\nend\n")
    with pytest.raises(KasFileError, match=r"k\.kas:6: expected 3 finite numbers"):
        files.load_keyframe(f)


@pytest.mark.parametrize("text,line,msg", [
    ("", 1, "empty file"),
    ("KAS keyframe 2\nchains 0\nend\n", 1, "unsupported keyframe file version"),
    ("KAS sequence 1\nfps 25\nframes 0\nend\n", 1, "KAS sequence file, not a keyframe"),
    ("hello\n", 1, "not a KAS file"),
    ("KAS keyframe 1\nchains 1\nchain section=0 points=1\n0 0 0\nend\n", 4, "colour"),
    ("KAS keyframe 1\nchains 1\nchain section=0 points=1\n0 inf 1\nend\n", 4, "finite"),
    ("KAS keyframe 1\nchains 1\nchain sect=0 points=1\n0 0 1\nend\n", 3, "chain section"),
    ("KAS keyframe 1\nchains 0\nend\nmore\n", 4, "after 'end'"),
    ("KAS keyframe 1\nchains 1\nchain section=0 points=3\n0 0 1\n", 4, "ends early"),
])
def test_bad_keyframes(text, line, msg):
    with pytest.raises(KasFileError, match=msg) as err:
        files.parse_keyframe(text, "k.kas")
    assert err.value.line == line


@pytest.mark.parametrize("ticks, msg", [
    ("0.75\n0.25\n0.5\n", "tick 2 \\(0.25\\) comes before tick 1"),   # the reviewer's file
    ("0.2\n1.5\n", "tick 2 \\(1.5\\) is not a fraction"),
    ("-0.1\n0.5\n", "tick 1 \\(-0.1\\) is not a fraction"),
])
def test_bad_ticks_refused(ticks, msg):
    text = f"KAS timing 1\nkind ticks\nname hand ticks\nsamples 3\n{ticks}end\n"
    text = text.replace("samples 3", f"samples {ticks.count(chr(10))}")
    with pytest.raises(KasFileError, match=msg) as err:
        files.parse_timing(text, "t.kas")
    assert "t.kas" in str(err.value)
    with pytest.raises(ValueError, match="tick"):
        from camlab88.apps.kas.timing import fractions
        fractions(Timing("ticks", [float(x) for x in ticks.split()]), None)


def test_equal_ticks_hold_a_frame():
    t = files.parse_timing("KAS timing 1\nkind ticks\nsamples 2\n0.5\n0.5\nend\n")
    assert t.values.tolist() == [0.5, 0.5]


def test_bad_timing_curve():
    text = "KAS timing 1\nkind curve\nsamples 2\n0.5 0\n1 1\nend\n"
    with pytest.raises(KasFileError, match="from 0 to 1"):
        files.parse_timing(text, "t.kas")


def test_atomic_save_keeps_old_file_on_failure(tmp_path, monkeypatch):
    f = tmp_path / "k.kas"
    good = Drawing([Chain.from_points([(0, 0), (1, 1)], 2)])
    files.save_keyframe(f, good)
    before = f.read_text()

    def boom(*a, **k):
        raise OSError("disk full")

    monkeypatch.setattr(os, "replace", boom)
    with pytest.raises(OSError):
        files.save_keyframe(f, Drawing([Chain.from_points([(5, 5)], 3)]))
    assert f.read_text() == before
    assert [p.name for p in tmp_path.iterdir()] == ["k.kas"]  # no temp files left


def test_sequence_last_frame_continues(tmp_path):
    f = tmp_path / "s.kas"
    frames = [Drawing([Chain.from_points([(i, 0)], 1)]) for i in range(3)]
    files.save_sequence(f, AnimSequence(frames))
    assert files.load_drawing_or_frame(f).chains[0].points.tolist() == [[2.0, 0.0]]


def test_hand_edited_spacing_accepted():
    text = "KAS keyframe 1\n\nchains 1\nchain section=2 points=2\n  0.5\t-1   3\n2 2e-1 4\nend"
    d = files.parse_keyframe(text)
    assert d.chains[0].points.tolist() == [[0.5, -1], [2, 0.2]]
    assert d.chains[0].section == 2 and d.chains[0].colours.tolist() == [3, 4]
