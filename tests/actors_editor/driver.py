"""Drive the actor editor on an in-process Rainbow with the Rainbow script language."""

from __future__ import annotations

from pathlib import Path

from camlab88.apps.actors.editor.cell_types import CellType
from camlab88.apps.actors.editor.program import ActorEditor
from camlab88.emulator.machine import RainbowMachine
from camlab88.protocols.rainbow.script import Player, parse

LIFE = [CellType(1, "form 1", (0, 255, 0))]
MAZE = [CellType(1, "form 1", (200, 200, 200)), CellType(2, "form 2", (255, 0, 0)),
        CellType(3, "form 3", (0, 0, 255))]


def screen(r: float, h: float) -> tuple[int, int]:
    """The screen point of profile point (radius, height) (pad at 16, 40; axis x 16,
    floor y 432; 320 pixels a cell unit)."""
    return 32 + round(r * 320), 472 - round(h * 320)


class Driver:
    def __init__(self, path: Path, types: list[CellType] | None = None,
                 rules: str = "life") -> None:
        self.machine = RainbowMachine()
        self.editor = ActorEditor(self.machine.client, str(path), types or LIFE, rules)
        self.frames = 0

    def run(self, text: str) -> None:
        player = Player(parse(text, "<test>"))
        while not player.finished and not self.editor.finished:
            for e in player.due():
                self.machine.post(e)
            self.editor.frame()
            self.frames += 1

    def click_points(self, points: list[tuple[float, float]]) -> None:
        self.run("".join("click left {} {}\nwait 1\n".format(*screen(*p)) for p in points))

    def key(self, *keys: str) -> None:
        self.run("".join(f"key {k}\nwait 1\n" for k in keys))

    def screen(self):
        return self.machine.device.peek()
