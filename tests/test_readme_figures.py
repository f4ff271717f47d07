"""Figures the README states are the ones the code gives: the KAS line test's real-time mode
shows N of the demo's 28 frames at 9600 baud and M at 38400."""

from __future__ import annotations

import re
from pathlib import Path

from camlab88.apps.kas import demo
from camlab88.apps.kas.program.viewer import LineTest

ROOT = Path(__file__).resolve().parents[1]


def test_the_line_test_figures_in_the_readme_are_measured() -> None:
    text = " ".join((ROOT / "README.md").read_text(encoding="utf-8").split())
    m = re.search(r"at 9600 baud the real-time mode shows (\d+) of the demo's (\d+) frames, "
                  r"at 38400 baud (\d+)", text)
    assert m, "the README no longer states the line test's figures"
    seq = demo.build()
    test = LineTest(seq)
    got = (len(test.run("realtime", 9600).shown), len(seq), len(test.run("realtime", 38400).shown))
    assert tuple(int(g) for g in m.groups()) == (got[0], got[1], got[2])
