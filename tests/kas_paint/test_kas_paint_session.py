"""The painting program driven by a script: what the animator does on one frame is recorded
in the operations file, painted through the terminal, and repeated by auto-paint."""

from __future__ import annotations

import numpy as np
import pytest

from camlab88.apps.kas.paint import areas, opsfile, script
from camlab88.apps.kas.paint.ops import OpsFile
from camlab88.apps.kas.paint.session import PaintSession
from tests.kas_paint.helpers import t5688_line, walk

SCRIPT = """colour 3
select {cx} {cy}
fill
colour 5
select {wx} {wy}
fill
rgb blue +40
show preview
"""


def test_scripted_session_records_and_paints() -> None:
    seq = walk(8)
    ring, wander = seq.frames[3].chains[1], seq.frames[3].chains[0]
    text = SCRIPT.format(cx=ring.points[0][0], cy=ring.points[0][1],
                         wx=wander.points[5][0], wy=wander.points[5][1])
    s = PaintSession(seq, OpsFile(painted=4))
    line, term = t5688_line()
    line.send(s.start())
    for cmd in script.parse(text, "s.paint"):
        line.send(script.run(s, cmd))
    assert [(o.kind, o.chains, o.colour) for o in s.ops.ops] == [("fill", (2,), 3),
                                                                  ("fill", (1,), 5)]
    assert s.ops.ops[0].seeds and s.ops.palette[5][2] == min(40 + 40, 255)
    x0, y0, x1, y1 = areas.PAINTING.box()
    fill = term.planes[y0:y1 + 1, x0:x1 + 1] & 0x1F
    assert np.sum(fill == 3) > 100 and np.sum(fill == 5) > 100
    assert not np.any(term.planes & 0x80)  # fills clear the highlights
    assert term.reg.view == 4
    # the recorded file paints the same frame the same way from scratch
    again = opsfile.parse(opsfile.ops_text(s.ops))
    line2, t2 = t5688_line()
    line2.send(PaintSession(seq, again).start())
    assert np.array_equal(t2.planes[y0:y1 + 1, x0:x1 + 1] & 0x1F, fill)
    assert s.autopaint() == []


def test_script_errors_name_line_and_column() -> None:
    with pytest.raises(script.ScriptError, match=r"^s:2:8: expected a number"):
        script.parse("fill\nselect x 1.0\n", "s")
    with pytest.raises(script.ScriptError, match=r"^s:1:1: unknown command 'paint'"):
        script.parse("paint\n", "s")
    with pytest.raises(script.ScriptError, match=r"^s:1:5: expected red, green, blue"):
        script.parse("rgb pink 3\n", "s")
