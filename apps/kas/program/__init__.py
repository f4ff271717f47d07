"""The device-facing half of KAS: the programs talking only to a Sigma T5684 over the line.

Every program here produces Sigma bytes with ``camlab88.protocols.sigma.Encoder`` and reads
the stylus through ``camlab88.protocols.tablets.input_layer`` and the keyboard from bytes the
terminal sends up the line.  Nothing here imports the emulator: ``camlab88/commands/kas.py``
wires a program to an emulated terminal, a window and a tablet source (docs/kas.md, "Device front").
"""

from __future__ import annotations

from camlab88.apps.kas.program.demo import DemoSession, demo_session
from camlab88.apps.kas.program.editor_front import EditorFront
from camlab88.apps.kas.program.path_front import PathFront
from camlab88.apps.kas.program.script import Session, TimedEvent, parse_timed_script
from camlab88.apps.kas.program.viewer import LineTest, ViewerReport, run_line_test

__all__ = [
    "DemoSession", "EditorFront", "LineTest", "PathFront", "Session", "TimedEvent",
    "ViewerReport", "demo_session", "parse_timed_script", "run_line_test",
]
