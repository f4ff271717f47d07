"""The editor's demonstration session (examples/ca/actors_edit.events, recorded as
examples/ca/actors_edit.session by examples/make_examples.py): a pawn for the maze's
state 1 and a rook for state 2, drawn, coloured, saved and watched turning."""

from __future__ import annotations

EVENTS = """\
# Scripted input for the actor editor (`camlab88 ca actors`, docs/ca_actors.md "The editor"):
# a pawn for the maze's state 1 and a rook for state 2. The Rainbow script language
# (protocols/rainbow/script.py); the profile pad's axis is screen x 32, its floor y 472,
# 320 pixels a cell.
wait 5
# The left button adds profile points, bottom to top (radius, height).
click left 32 472
wait 2
click left 144 472
wait 2
click left 144 456
wait 2
click left 112 440
wait 2
click left 80 424
wait 2
click left 64 344
wait 2
click left 96 328
wait 2
click left 64 312
wait 2
click left 80 280
wait 2
click left 64 248
wait 2
click left 32 242
wait 4
# Drag the collar out a little; the right button deletes a point, the left adds it back.
drag left 96 328 108 328 4
wait 2
click right 64 312
wait 2
click left 60 312
wait 4
# Colour (red, green, blue) and the specular coefficient on the sliders.
drag left 500 356 640 356 6
drag left 500 376 632 376 6
drag left 500 396 612 396 6
drag left 500 456 575 456 6
wait 20
# The middle button's menu: Cell type, then the right button picks state 2.
press middle 600 200
wait 2
move 600 218
wait 2
release middle 600 218
wait 4
move 600 236
wait 2
click right 600 236
wait 4
click left 32 472
wait 2
click left 128 472
wait 2
click left 128 440
wait 2
click left 100 420
wait 2
click left 100 312
wait 2
click left 128 296
wait 2
click left 128 264
wait 2
click left 32 264
wait 4
# s saves; then watch it turn; q quits (nothing is left unsaved).
key s
wait 60
key q
wait 1
"""


def demo_events() -> str:
    """The session's script, in the Rainbow script language."""
    return EVENTS
