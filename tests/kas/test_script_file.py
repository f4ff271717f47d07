"""A whole editor session from an event-script file, checked against hand-worked numbers."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from camlab88.apps.kas.editor import Editor
from camlab88.apps.kas.events import parse_script

SCRIPT = Path(__file__).resolve().parents[1] / "data" / "kas" / "walk_edit_script.txt"


def test_script_session():
    ed = Editor()
    ed.run(parse_script(SCRIPT.read_text(), str(SCRIPT)))
    zig, head = ed.drawing.chains
    # zig-zag moved right by 2 ('l' moves the square cursor's chain, chain 0)
    assert zig.points.tolist() == [[-2, 0], [-1, 1], [0, 0], [1, 1]]
    assert zig.colours.tolist() == [2] * 4 and zig.section == 0
    # ']' put the square on the head (section 1); 's' moved that section right by 1
    assert head.section == 1 and len(head) == 37
    assert np.allclose(head.points.mean(axis=0)[1], 0.5, atol=0.05)
    assert np.allclose(np.hypot(*(head.points - (1, 0.5)).T), 0.5)
    assert head.colours.tolist() == [5] * 37
    assert ed.mode == "edit" and [t.kind for t in ed.applied] == ["move", "move"]
