"""Log -> Script replay reproduces the session exactly, from scratch and from checkpoints."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from camlab88.apps.ca import log
from camlab88.apps.ca.engine import Engine, Rect
from camlab88.apps.ca.library import pattern_path, rules_path
from camlab88.apps.ca.patterns import read_pattern

GUN = read_pattern(pattern_path("gosper_gun"))
LIFE_TEXT = Path(rules_path("life")).read_text()
GRAZE_TEXT = Path(rules_path("overgrazing")).read_text()


def _session(tmp_path: Path, checkpoint_every: int = 0) -> tuple[str, Engine, list]:
    """A scripted session: every kind of intervention, logged as the program would."""
    path = str(tmp_path / "session.log")
    writer = log.LogWriter(path, record_views=True)
    engine = Engine()
    plan = {
        0: [log.ev_rules(0, "life", LIFE_TEXT), log.ev_load(0, "gosper_gun", 500, 500,
                                                            "identity", GUN),
            log.ev_view(0, 480, 490), log.ev_zoom(0, "8")],
        3: [log.ev_edit(3, 400, 400, 1), log.ev_edit(3, 401, 400, 1),
            log.ev_edit(3, 402, 400, 1)],
        10: [log.ev_load(10, "gosper_gun", 600, 520, "rot90", GUN),
             log.ev_populate(10, Rect(300, 300, 340, 330), 0.3, {1: 1.0}, seed=42)],
        17: [log.ev_advance(17, Rect(590, 500, 700, 600)), log.ev_view(17, 600, 600)],
        21: [log.ev_advance(21, None),
             log.ev_load(21, "gosper_gun", 600, 520, "rot90", GUN, erase=True)],
        30: [log.ev_clear(30, Rect(290, 290, 350, 340)),
             log.ev_rules(30, "overgrazing", GRAZE_TEXT)],
        38: [log.ev_clear(38, None), log.ev_load(38, "gosper_gun", 100, 100, "flip_x", GUN),
             log.ev_rules(38, "life", LIFE_TEXT)],
    }
    views = []
    for gen in range(0, 61):
        assert engine.generation == gen
        if checkpoint_every and gen % checkpoint_every == 0 and gen > 0:
            log.write_checkpoint(path, engine)
        for ev in plan.get(gen, []):
            writer.add(ev)
            if ev.kind in log.VIEW_EVENTS:
                views.append(ev)
            else:
                log.apply_event(engine, ev)
        if gen < 60:
            engine.step()
    return path, engine, views


def test_script_replay_reproduces_the_session_exactly(tmp_path: Path) -> None:
    path, live, views = _session(tmp_path)
    seen: list = []
    replayed = log.start_from_script(path, 60, Engine, on_view=seen.append)
    assert replayed.same_state(live)
    assert seen == views  # ReplayPansAndZooms
    # Any intermediate generation too (the user chooses where to begin).
    mid = log.start_from_script(path, 25, Engine)
    assert mid.generation == 25 and mid.population > 0


def test_replay_from_latest_checkpoint(tmp_path: Path) -> None:
    path, live, _ = _session(tmp_path, checkpoint_every=20)
    names = sorted(n for n in os.listdir(tmp_path) if n.startswith("session.log"))
    assert names == ["session.log", "session.log20", "session.log40", "session.log60"]
    assert log.latest_checkpoint(path, 59) == path + "40"
    assert log.latest_checkpoint(path, 19) is None
    from_cp = log.start_from_script(path, 60, Engine)
    assert from_cp.same_state(live)
    # The checkpoint really is used: without the log's early events it still arrives.
    cp = log.read_checkpoint(path + "40")
    assert cp.generation == 40
    events = [e for e in log.read_log(path) if e.generation >= 40]
    assert log.replay(cp, events, 60).same_state(live)


def test_script_user_can_still_intervene(tmp_path: Path) -> None:
    path, live, _ = _session(tmp_path)
    e = log.start_from_script(path, 45, Engine)
    e.set_cells([20, 21, 20, 21], [20, 20, 21, 21], 1)  # the new session adds a block
    e.step(15)
    assert not e.same_state(live)


def test_log_and_checkpoint_round_trip_text(tmp_path: Path) -> None:
    path, live, _ = _session(tmp_path)
    events = log.read_log(path)
    assert log.parse_log(log.format_log(events)) == events
    text = log.format_checkpoint(live)
    back = log.parse_checkpoint(text)
    assert back.same_state(live) and back.rules.forms == live.rules.forms


def test_views_not_recorded_without_record_pans_and_zooms(tmp_path: Path) -> None:
    w = log.LogWriter(tmp_path / "a.log", record_views=False)
    w.add(log.ev_view(0, 1, 2))
    w.add(log.ev_edit(0, 1, 2, 1))
    assert [e.kind for e in log.read_log(tmp_path / "a.log")] == ["edit"]


@pytest.mark.parametrize(("text", "words"), [
    ("", "expected 'CAMLAB88-CA-LOG 1'"),
    ("CAMLAB88-CA-LOG 1\nx edit 1 2 3\n", ":2: expected 'generation kind"),
    ("CAMLAB88-CA-LOG 1\n3 dance 1\n", "unknown event 'dance'"),
    ("CAMLAB88-CA-LOG 1\n3 edit 1 2\n", "edit takes 3 fields"),
    ("CAMLAB88-CA-LOG 1\n3 edit 1 2 x\n", "bad number"),
    ("CAMLAB88-CA-LOG 1\n0 rules life 2\n|1 0 0 0 0 |1\n", "expected 2 rule lines"),
    ("CAMLAB88-CA-LOG 1\nedges round\n", ":2: edges must be wrap or bounded"),
    ("CAMLAB88-CA-LOG 1\nedges wrap\nseed x\n", ":3: expected 'seed <integer>'"),
])
def test_log_errors_name_line(text: str, words: str) -> None:
    with pytest.raises(log.LogError, match=words):
        log.parse_log(text, "bad.log")


@pytest.mark.parametrize(("text", "words"), [
    ("nope", "expected 'CAMLAB88-CA-CHECKPOINT 1'"),
    ("CAMLAB88-CA-CHECKPOINT 1\ngeneration x\n", "bad generation .x."),
    ("CAMLAB88-CA-CHECKPOINT 1\ngeneration 1\nedges round\n", "wrap or bounded"),
    ("CAMLAB88-CA-CHECKPOINT 1\ngeneration 1\nedges wrap\nseed 0\nadvance all\nrules 0\n"
     "cells 2\n1 1 1\nend\n", "expected 2 cell lines"),
])
def test_checkpoint_errors(text: str, words: str) -> None:
    with pytest.raises(log.LogError, match=words):
        log.parse_checkpoint(text, "bad.cp")


def test_replay_cannot_go_backwards() -> None:
    e = Engine()
    e.generation = 5
    with pytest.raises(ValueError, match="backwards"):
        log.replay(e, [], 3)


def test_load_event_with_lifeforms_beyond_rle_states(tmp_path: Path) -> None:
    from camlab88.apps.ca.patterns import Pattern

    p = Pattern.from_cells([(0, 0, 300), (2, 1, 7)], ref=(1, 1))
    ev = log.ev_load(4, "big", 50, 60, "rot180", p)
    back = log.parse_log(log.format_log([ev]))[0]
    e = Engine()
    log.apply_event(e, back)
    assert {(int(x), int(y), int(t)) for x, y, t in zip(e.xs, e.ys, e.ts)} == {
        (51, 61, 300), (49, 60, 7)}


def test_log_header_records_edges_and_seed(tmp_path: Path) -> None:
    path = tmp_path / "s.log"
    w = log.LogWriter(path, settings=log.LogSettings("bounded", 7))
    w.add(log.ev_edit(0, 1, 2, 1))
    text = path.read_text()
    assert text.splitlines()[:3] == [log.LOG_MAGIC, "edges bounded", "seed 7"]
    assert log.read_log_settings(path) == log.LogSettings("bounded", 7)
    assert log.parse_log(text) == [log.ev_edit(0, 1, 2, 1)]
    old = log.LOG_MAGIC + "\n0 edit 1 2 1\n"  # a log from before the header: still reads
    assert log.parse_log_settings(old) == log.LogSettings()
    assert log.resolve_settings(log.LogSettings(), None, None) == ("wrap", 0, [])
    assert log.resolve_settings(log.LogSettings(), "bounded", 3) == ("bounded", 3, [])
    edges, seed, warn = log.resolve_settings(log.LogSettings("bounded", 7), "wrap", 7)
    assert (edges, seed) == ("bounded", 7) and len(warn) == 1 and "edges bounded" in warn[0]
    assert log.resolve_settings(log.LogSettings("bounded", 7), None, 8)[2] == [
        "the script was recorded with seed 7; replaying with it, not the command line's 8"]


def test_populate_keeps_the_overall_and_the_relative_densities() -> None:
    # section 7.3.2: a rectangle, an overall density and relative densities of life-forms
    e = Engine()
    log.populate(e, Rect(10, 10, 209, 209), 0.5, {1: 3.0, 2: 1.0}, seed=1)
    counts = e.by_type()
    assert abs(e.population - 20000) < 600
    assert abs(counts[1] - 15000) < 600 and abs(counts[2] - 5000) < 400
    assert e.bbox() == Rect(10, 10, 209, 209)
