"""A short scripted session for ``camlab88 demo``: the Gosper glider gun in Life.

Leave edit mode, choose Auto mode, let the gun fire for a while, pan after the gliders
with the left button, switch to zoom 8 and back to single steps. Expressed as scripted
input (``script_events``) so it runs through exactly the code a person's mouse drives.
"""

from __future__ import annotations

from camlab88.apps.ca.program.menus import CrossMenu, main_item_point


def choose(item: str, x: int = 300, y: int = 300) -> str:
    """Script lines choosing ``item`` from the main menu opened at (x, y)."""
    ix, iy = main_item_point(item, x, y, jumps=True)  # the program's menu has 3 columns
    return f"press middle {x} {y}\nmove {ix} {iy}\nrelease middle {ix} {iy}\nframes 1\n"


def leave_editing(x: int = 300, y: int = 300) -> str:
    return f"press middle {x} {y}\nrelease middle {x} {y}\nframes 1\n"


def edit_choice(direction: str, x: int = 300, y: int = 300) -> str:
    d = 2 * CrossMenu.DEAD
    dx, dy = {"up": (0, -d), "down": (0, d), "left": (-d, 0), "right": (d, 0)}[direction]
    return (f"press middle {x} {y}\nmove {x + dx} {y + dy}\nrelease middle {x + dx} {y + dy}\n"
            "frames 1\n")


def pan(x0: int, y0: int, x1: int, y1: int, steps: int) -> str:
    """A left-button drag, one mouse report per frame (the grid follows smoothly)."""
    out = [f"press left {x0} {y0}"]
    for i in range(1, steps + 1):
        out.append(f"move {x0 + (x1 - x0) * i // steps} {y0 + (y1 - y0) * i // steps}")
        out.append("frames 1")
    out.append(f"release left {x1} {y1}")
    return "\n".join(out) + "\n"


def demo_events(generations: int = 60) -> str:
    """The demo's input: ``generations`` generations in auto mode (one per frame)."""
    steps = 12
    before = max(1, (generations - steps) // 2)
    after = max(1, generations - steps - before)
    return ("frames 10\n" + leave_editing() + choose("Auto mode")  # 1 generation
            + f"frames {before - 1}\n"
            + pan(500, 300, 260, 180, steps)  # a generation a frame while panning
            + choose("Zoom 8", 200, 200)  # 1 generation
            + f"frames {after - 1}\n"
            + choose("Step mode") + "frames 20\n")
