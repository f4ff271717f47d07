"""Inputs the fuzzers found (fuzz/, docs/reliability.md), kept as regressions: each raised
something other than its format's error before its fix."""

from __future__ import annotations

import pytest

from camlab88.apps.ca.log import LogError, parse_checkpoint
from camlab88.apps.ca.patterns import PatternError, parse_native
from camlab88.apps.snooker.session import Session, SessionError
from fuzz.targets import TARGETS

CHECKPOINT = ("CAMLAB88-CA-CHECKPOINT 1\ngeneration 1\nedges wrap\nseed 0\nadvance {}\nrules 0\n"
              "cells 0\nend\n")


def test_a_negative_native_cell_count() -> None:
    with pytest.raises(PatternError, match=r"p.pat:2:1: a cell count cannot be negative"):
        parse_native("CAMLAB88-CA-PATTERN 1\ncells -5\n0 0 1\nend\n", "p.pat")


@pytest.mark.parametrize("advance", ["", "1 2", "1 2 3"])
def test_a_checkpoint_rectangle_with_too_few_corners(advance: str) -> None:
    with pytest.raises(LogError, match="four corners"):
        parse_checkpoint(CHECKPOINT.format(advance), "c.cp")


@pytest.mark.parametrize("doc", ['{"format": "camlab88-snooker-session", "version": 1}',
                                 '{"format": "camlab88-snooker-session", "version": null}',
                                 '{"format": "camlab88-snooker-session", "version": 1, '
                                 '"table": 5}'])
def test_session_documents_with_odd_values(doc: str) -> None:
    with pytest.raises(SessionError):
        TARGETS["snooker-session"].run(doc.encode())
    with pytest.raises(SessionError):
        Session.from_json(__import__("json").loads(doc))

