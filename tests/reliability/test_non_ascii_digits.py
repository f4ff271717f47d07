"""Characters that str.isdigit() accepts but int() refuses ('²', '³', ...) are bad input like
any other: every text format reports them with its own error, naming where."""

from __future__ import annotations

import re

import pytest

from camlab88.apps.ca.library import rules_path
from camlab88.apps.ca.log import latest_checkpoint
from camlab88.apps.ca.patterns import PatternError, parse_rle
from camlab88.apps.ca.rules import RuleError, parse_rules
from camlab88.apps.kas import files
from camlab88.apps.kas.files import KasFileError
from camlab88.apps.kas.model import Chain, Drawing
from camlab88.apps.snooker.table import ball_index
from camlab88.protocols.link.recording import RecordingError, parse_recording


def test_link_recording_end_count() -> None:
    text = "camlab88-link-recording 1\nline 9600 8N1\nend ²\n"
    with pytest.raises(RecordingError, match=r"^r.rec:3: expected 'end <number of chunks>'"):
        parse_recording(text, "r.rec")


def test_kas_keyframe_count() -> None:
    good = files.keyframe_text(Drawing([Chain.from_points([(0, 0), (1, 1)], 2)]))
    bad, n = re.subn(r"^chains \d+", "chains ²", good, count=1, flags=re.M)
    assert n == 1
    with pytest.raises(KasFileError, match="'chains' needs one non-negative integer"):
        files.parse_keyframe(bad, "k.kas")


def test_ca_rle_repeat_count() -> None:
    with pytest.raises(PatternError, match=r"g.rle:2:1"):
        parse_rle("x = 3, y = 1\n²o!\n", "g.rle")


def test_ca_rules_interpretation_line() -> None:
    with open(rules_path("life"), encoding="utf-8") as fh:
        text = fh.read()
    bad = text.replace("#B?0011 1", "²3 1", 1)
    assert bad != text
    with pytest.raises(RuleError, match="expected an interpretation line"):
        parse_rules(bad, "life.rules")


def test_ca_checkpoint_names(tmp_path) -> None:
    log = tmp_path / "run.log"
    log.write_text("")
    (tmp_path / "run.log²").write_text("not a checkpoint")
    (tmp_path / "run.log12").write_text("")
    assert latest_checkpoint(str(log), 100) == str(tmp_path / "run.log12")


def test_snooker_ball_number() -> None:
    assert ball_index("3") == 2
    with pytest.raises(ValueError, match="unknown ball"):
        ball_index("²")
