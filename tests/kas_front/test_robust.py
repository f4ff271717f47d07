"""Parsers and drawing never crash on odd input; the guide keyframe shows on the Sigma."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from camlab88.apps.kas import files
from camlab88.apps.kas.editor import Editor
from camlab88.apps.kas.files import KasFileError
from camlab88.apps.kas.library import LIBRARY
from camlab88.apps.kas.program import EditorFront, parse_timed_script
from camlab88.apps.kas.program import layout as L
from camlab88.apps.kas.program.draw import Painter, chain_prims, clip_polyline, encode
from camlab88.emulator.sigma import Terminal
from camlab88.protocols.sigma import Decoder, Encoder
from camlab88.protocols.sigma.keyboard import bytes_to_keys
from tests.kas_front.helpers import drive

WORDS = st.sampled_from(["move", "down", "up", "key", "menu", "type", "wait", "fly", "+0.1",
                         "1.5", "-2", "nan", "pen2", "f2", "space", "x", "", "#c", "1e400"])


@settings(max_examples=150, deadline=None)
@given(st.lists(st.lists(WORDS, max_size=5).map(" ".join), max_size=8).map("\n".join))
def test_script_parser_accepts_or_names_the_line(text: str) -> None:
    try:
        events = parse_timed_script(text, "h.txt")
    except KasFileError as exc:
        assert str(exc).startswith("h.txt:")
        return
    times = [e.t for e in events]
    assert times == sorted(times)


@settings(max_examples=100, deadline=None)
@given(st.binary(max_size=64))
def test_keyboard_bytes_never_fail(data: bytes) -> None:
    for k in bytes_to_keys(data):
        assert isinstance(k, str) and k


@settings(max_examples=100, deadline=None)
@given(st.lists(st.tuples(st.floats(-1e7, 1e7), st.floats(-1e7, 1e7)), min_size=1,
                max_size=12), st.lists(st.integers(0, 300), min_size=12, max_size=12))
def test_any_chain_clips_to_valid_orders(pts, cols) -> None:
    prims = chain_prims(np.array(pts), cols[:len(pts)], (8, 8, 584, 428),
                        lambda c: c if 1 <= c <= 8 else 1)
    enc = Encoder()
    data = b"".join(encode(enc, p) for p in prims)
    for p in prims:
        xs, ys = p.data[0::2], p.data[1::2]
        assert min(xs) >= 8 and max(xs) <= 584 and min(ys) >= 8 and max(ys) <= 428
    dec = Decoder()
    dec.feed(b"+-*/" + data)
    assert dec.stats.unknown == dec.stats.malformed == 0


def test_clip_keeps_inside_and_cuts_crossings() -> None:
    inside = np.array([[10.0, 10.0], [20.0, 20.0]])
    assert np.array_equal(clip_polyline(inside, 0, 0, 100, 100)[0], inside)
    pieces = clip_polyline(np.array([[-50.0, 50.0], [150.0, 50.0]]), 0, 0, 100, 100)
    assert len(pieces) == 1 and np.allclose(pieces[0], [[0, 50], [100, 50]])
    pieces = clip_polyline(np.array([[50.0, 50.0], [50.0, 150.0], [60.0, 150.0],
                                     [60.0, 50.0]]), 0, 0, 100, 100)
    assert len(pieces) == 2
    assert clip_polyline(np.array([[200.0, 200.0]]), 0, 0, 100, 100) == []


def test_painter_no_change_sends_nothing() -> None:
    p = Painter()
    front = EditorFront(Editor())
    p.full(front.prims())
    assert p.update(front.prims()) == b""


def test_guide_keyframe_highlighted_on_screen() -> None:
    guide = files.load_keyframe(LIBRARY / "walk_a.kas")
    front = EditorFront(Editor(guide=guide))
    run = drive(front)
    term = run.terminal
    run.run_script(parse_timed_script("move 0 0\n5 wait"))
    idx = term.indices()
    # the first chain of walk_a is the one to draw next; the other is the plain guide
    assert (idx == L.GUIDE_NEXT).sum() > 50 and (idx == L.GUIDE).sum() > 50
    # drawing a chain moves the highlight to the guide's next chain
    front.on_pointer(0, 0, False)
    front.on_pointer(0, 0, True)
    front.on_pointer(1, 1, True)
    front.on_key("space")
    t2 = Terminal("t5684")
    t2.feed(front.start())
    assert front.editor.next_guide_chain() == 1
    assert (t2.indices() == L.GUIDE_NEXT).sum() > 20


def test_a_script_file_with_a_bad_byte_a_directory_or_no_file_is_named(tmp_path) -> None:
    """A non-UTF-8 KAS script is named by file, line and column, not by Python's codec."""
    import pytest

    from camlab88.apps.kas.files import KasFileError
    from camlab88.apps.kas.program.script import load_timed_script

    bad = tmp_path / "bad.script"
    bad.write_bytes(b"wait 1\nkey a\n\xff\xfe bad\n")
    with pytest.raises(KasFileError, match=r"bad\.script:3:1: byte 0xff is not UTF-8"):
        load_timed_script(bad)
    with pytest.raises(KasFileError, match=r": is a directory"):
        load_timed_script(tmp_path)
    with pytest.raises(KasFileError, match=r"missing\.script: cannot read"):
        load_timed_script(tmp_path / "missing.script")
