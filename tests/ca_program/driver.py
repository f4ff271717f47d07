"""Drive the ca program headless on an in-process Rainbow with scripted input."""

from __future__ import annotations

from pathlib import Path

from camlab88.apps.ca.program import script_events
from camlab88.apps.ca.program.demo import choose, edit_choice, leave_editing
from camlab88.apps.ca.program.program import CAProgram, Options
from camlab88.emulator.machine import RainbowMachine
from camlab88.protocols.rainbow.stream import Decoder
from camlab88.protocols.rainbow.ui.menu import ROW_H

DATA = Path(__file__).resolve().parents[1] / "data" / "ca_program"


class Driver:
    def __init__(self, options: Options | None = None, record: bool = False) -> None:
        self.machine = RainbowMachine(record=record)
        self.program = CAProgram(self.machine.client, options or Options())
        self.mark = 0
        self.mouse = script_events.MouseState()

    # -- input ---------------------------------------------------------------------------
    def run(self, text: str) -> int:
        steps = script_events.parse(text, "<test>", self.mouse)
        return script_events.play(steps, self.machine.post, self.program.frame,
                                  lambda: self.program.finished)

    def frames(self, n: int = 1) -> None:
        self.run(f"frames {n}")

    def main(self, item: str, x: int = 300, y: int = 300) -> None:
        self.run(choose(item, x, y))

    def leave_editing(self) -> None:
        self.run(leave_editing())

    def edit_menu(self, direction: str) -> None:
        self.run(edit_choice(direction))

    def pick(self, item: str) -> None:
        """Choose ``item`` from the dialogue's pop-up menu (move to it, right button)."""
        menu = self.program.choice
        assert menu is not None, "no choice menu is open"
        i = menu.items.index(item)
        x, y = menu.x + 10, menu.y + menu.scroll + i * ROW_H + ROW_H // 2
        self.run(f"move {x} {y}\nclick right {x} {y}\nframes 1")

    def type(self, text: str) -> None:
        self.run(f"type {text}\nkey return\nframes 1")

    def step(self, n: int = 1) -> None:
        """Right-click the view ``n`` times: in step mode each click is one generation."""
        self.run("click right 600 500\nframes 1\n" * n)

    def place_pattern(self, name: str, cx: int, cy: int, orientation: str) -> None:
        """Load pattern ``name`` and place it at cell (cx, cy) in ``orientation``."""
        self.main("Load pattern")
        self.type(name)
        self.click_cell(cx, cy)
        self.pick(orientation)

    def screen_of(self, cx: int, cy: int) -> tuple[int, int]:
        v = self.program.view
        sx, sy = v.screen_of_cell(cx, cy)
        z = v.zoom or 1
        return sx + z // 2, sy + z // 2

    def click_cell(self, cx: int, cy: int) -> None:
        x, y = self.screen_of(cx, cy)
        self.run(f"move {x} {y}\nclick right {x} {y}\nframes 1")

    # -- what the device saw --------------------------------------------------------------
    @property
    def frame(self):
        return self.machine.executor.last_frame.copy()

    def commands_since_mark(self) -> list:
        """Decoded command frames sent since the last call (needs record=True)."""
        rec = self.machine.recording.entries
        frames = [b for d, b in rec[self.mark:] if d == ">"]
        self.mark = len(rec)
        d = Decoder()
        return d.feed(b"".join(frames))
