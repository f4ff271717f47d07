"""'A line taking a walk' as a Sigma session: the editor screen, then the line test.

``demo_session()`` returns the bytes a host would send and when: first the keyframe editor
(walk_a loaded, walk_b as the guide of the editor §2.3 wished for) with a short scripted
stroke drawn by the stylus, then, after a pause, the in-betweened and superimposed demo
sequence played by the viewer at 9600 baud: first in real time (frames dropped as the line
forces), then every frame (the thesis used both, §3.1.4).  ``camlab88 demo`` can write the
chunks to a ``SerialLine`` host at their times and feed the terminal.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass
from fractions import Fraction

from camlab88.apps.kas import demo as kas_demo
from camlab88.apps.kas import files
from camlab88.apps.kas.editor import Editor
from camlab88.apps.kas.library import LIBRARY
from camlab88.apps.kas.program.editor_front import EditorFront
from camlab88.apps.kas.program.script import Session, parse_timed_script
from camlab88.apps.kas.program.viewer import LineTest, ViewerReport
from camlab88.protocols.link import LineSettings
from camlab88.protocols.link.host_only import HostOnlyLine

PAUSE = Fraction(2)  # seconds of line time between the editor and the viewer
TICK = Fraction(1, 100)  # the editor session's polling period

DEMO_SCRIPT = """
# the animator adds a small wandering line in yellow, then looks at edit mode's cursors
0.5 menu pen5
move -4 -2.5
down -4 -2.5
+0.05 down -3.6 -2.2
+0.05 down -3.2 -2.5
+0.05 down -2.8 -2.1
+0.05 down -2.4 -2.4
up -2.4 -2.4
key space
menu edit
key g
"""


@dataclass
class DemoSession:
    chunks: list[tuple[Fraction, bytes]]   # (line time to write, bytes), in order
    editor_end: Fraction                   # line time the editor part has been drawn
    viewer: ViewerReport                   # the real-time run
    every: ViewerReport                    # the every-frame run after it
    duration: Fraction

    @property
    def stream(self) -> bytes:
        return b"".join(d for _, d in self.chunks)

    def arrivals(self, period: Fraction = Fraction(1, 25)) -> Iterator[tuple[int, bytes]]:
        """``(k, bytes)``: what reaches the terminal in each period of line time when the
        chunks are written to a 9600-baud line at their times (feed them, show a frame)."""
        line = HostOnlyLine(LineSettings(baud=9600))
        i, k = 0, 0
        while True:
            end = (k + 1) * period
            while i < len(self.chunks) and self.chunks[i][0] <= end:
                line.run_to(self.chunks[i][0])
                line.port.write(self.chunks[i][1])
                i += 1
            line.run_to(end)
            yield k, line.take()
            k += 1
            if i == len(self.chunks) and line.in_flight() == 0:
                return


def _editor_part(session: Session, line: HostOnlyLine) -> None:
    """The editor session's host bytes on a line with no terminal at its end (so no key
    ever comes back up: the demo's key lines do nothing, as they always have)."""
    session.begin()
    events = parse_timed_script(DEMO_SCRIPT, "demo script")
    i = 0
    while i < len(events) or session.busy():
        mouse, _keys, i = session.due(events, i)
        session.step(mouse)
        line.take()  # nobody there: what arrives is only counted as arrived
        line.run_to(line.now + TICK)


def demo_session() -> DemoSession:
    """The demo's host bytes with their line times (9600 baud)."""
    ed = Editor(files.load_keyframe(LIBRARY / "walk_a.kas"),
                guide=files.load_keyframe(LIBRARY / "walk_b.kas"))
    line = HostOnlyLine(LineSettings(baud=9600))
    session = Session(EditorFront(ed), line.port)
    _editor_part(session, line)
    editor_end = line.port.drain_exact()
    test = LineTest(kas_demo.build())
    rep = test.run("realtime", 9600)
    every = test.run("every", 9600)
    start = editor_end + PAUSE
    chunks = list(session.sent) + [(start + t, d) for t, d in rep.sent]
    start2 = start + rep.end_exact + PAUSE
    chunks += [(start2 + t, d) for t, d in every.sent]
    return DemoSession(chunks, editor_end, rep, every, start2 + every.end_exact)
