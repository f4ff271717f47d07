"""The sample-path screen and the demo session."""

from __future__ import annotations

import numpy as np

from camlab88.apps.kas import files
from camlab88.apps.kas.events import Key, Pointer
from camlab88.apps.kas.library import LIBRARY
from camlab88.apps.kas.path_editor import PathEditor
from camlab88.apps.kas.program import PathFront, demo_session
from camlab88.emulator.sigma import Terminal
from camlab88.protocols.sigma import Decoder
from tests.kas_front.helpers import GOLDEN, drive, script
from tests.support.golden import assert_matches_golden


def _model() -> PathEditor:
    return PathEditor(files.load_keyframe(LIBRARY / "walk_a.kas"),
                      files.load_keyframe(LIBRARY / "walk_b.kas"),
                      files.load_path(LIBRARY / "walk_path.kas"))


def test_path_front_draws_path_and_ticks_over_the_line() -> None:
    saved = []
    front = PathFront(_model(), on_save=lambda p, t: saved.append((p, t)))
    s = drive(front)
    term = s.terminal
    events = script("path.txt")
    s.run_script(events)
    want = _model()
    for e in events:
        want.feed(Pointer(e.x, e.y, e.down) if e.kind == "pointer" else Key(e.key))
    np.testing.assert_allclose(np.array(front.model.path), np.array(want.path), atol=1e-9)
    np.testing.assert_allclose(front.model.ticks, want.ticks, atol=1e-9)
    assert len(front.model.ticks) == 4 and front.model.mode == "ticks"
    assert term.stats["unknown"] == term.stats["malformed"] == 0
    assert_matches_golden(term.frame(), GOLDEN / "path.png")
    front.on_key("f2")
    assert len(saved) == 1 and len(saved[0][1].values) == 4


def test_path_front_failed_save_keeps_the_path() -> None:
    def full(_p, _t):
        raise OSError(28, "No space left on device")

    front = PathFront(_model(), on_save=full)
    front.model.run([Pointer(0, 0, True), Pointer(1, 1, True), Pointer(1, 1, False)])
    front.on_key("f2")
    assert "NOT saved" in front.model.message and len(front.model.path) == 2


def test_demo_session_plays_on_a_terminal() -> None:
    demo = demo_session()
    times = [t for t, _ in demo.chunks]
    assert times == sorted(times) and demo.duration > demo.editor_end
    # the editor part on a terminal: the menu row's paint pots are there
    term = Terminal("t5684")
    term.feed(b"".join(d for t, d in demo.chunks if t < demo.editor_end))
    assert term.frame()[50, 20].tolist() == [255, 255, 255]
    # the whole stream is orders the Sigma knows, and the viewer part ends on the last frame
    dec = Decoder()
    dec.feed(demo.stream)
    assert dec.stats.unknown == dec.stats.malformed == 0
    assert len(demo.viewer.shown) < len(demo.viewer.sizes)  # real time drops frames
    assert demo.every.shown_frames == list(range(len(demo.every.sizes)))
    full = Terminal("t5684")
    full.feed(demo.stream)
    assert full.frame().any()


def test_demo_arrivals_replay_the_stream_in_time() -> None:
    demo = demo_session()
    pieces = list(demo.arrivals())
    assert b"".join(d for _, d in pieces) == demo.stream
    assert [k for k, _ in pieces] == list(range(len(pieces)))
    # no byte arrives before it was written: the pieces end at the session's duration
    assert abs(len(pieces) / 25 - float(demo.duration)) < 0.05
