"""The README's screenshot of HashLife in the ca program (run by hand:
PYTHONPATH=. python benchmarks/screenshot_hashlife.py docs/images/ca_hashlife_jump.png).

The Gosper gun after "Go to generation 100000", headless on the in-process Rainbow, the main
menu open with its jump column (built here as the program will once it is wired).
"""

from __future__ import annotations

import sys

from camlab88.apps.ca.program import stepping
from camlab88.apps.ca.program.menus import MainMenu, main_item_point
from camlab88.apps.ca.program.program import Options
from camlab88.base.png import write_png
from tests.ca_program.driver import Driver


def main(path: str) -> None:
    d = Driver(Options(pattern="gosper_gun"))
    d.leave_editing()
    d.program.main_menu = MainMenu(d.machine.client, jumps=True)  # the wiring asked for
    d.program.main_menu.mark("Step mode")
    d.program._start(stepping.go_to_generation(d.program))
    d.type("100000")
    d.program.set_zoom(4)
    d.frames(2)
    ix, iy = main_item_point("Go to generation", 600, 330, jumps=True)
    d.run(f"press middle 600 330\nmove {ix} {iy}\nframes 2")
    write_png(d.frame, path)
    print(d.program.session.generation, d.program.said[-1])


if __name__ == "__main__":
    main(sys.argv[1])
