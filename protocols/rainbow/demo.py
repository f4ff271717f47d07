"""The ``camlab88 rainbow run`` demo program (client side only).

On a virtual background pad: the Appendix I transparency example in its own cluster (the
polygon and the splodges drift independently), a double-buffered pad of bouncing balls
redrawn every frame and itself moving, and a message area. The middle mouse button pops
up a menu ('Do nothing' first); the choice appears as a coloured message.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

from camlab88.base.plainstate import Bool, Float, Int, ListOf, Record, Tuple
from camlab88.protocols.rainbow import transparency
from camlab88.protocols.rainbow.client import SCREEN, SCREEN_H, SCREEN_W, RainbowClient
from camlab88.protocols.rainbow.events import MouseEvent
from camlab88.protocols.rainbow.ui import DoubleBuffer, MessageArea, PopupMenu

BG_PAGE, BALL_PAGE, MSG_PAGE = 4, 5, 6
BALLS_W, BALLS_H = 300, 220
BALL_COLOURS = ["#101018", "#ff5050", "#50ff50", "#5080ff", "#ffff60", "#ff60ff", "#60ffff",
                "#ffffff"]
MENU_ITEMS = ["Freeze polygon", "Freeze splodges", "Faster", "Slower", "Do nothing"]


# Pad sizes for the strict (relic-sized, 512 x 256 x 8 planes) video memory, where the full
# sizes cannot all be placed: (polygon, splodges, balls); messages and menu use upper planes.
COMPACT_POLY, COMPACT_SPLODGE, COMPACT_BALLS = (176, 144), (256, 184), (200, 120)
COMPACT_MEMORY = 512 * 256


class Demo:
    def __init__(self, client: RainbowClient) -> None:
        c = self.client = client
        info = c.hello()
        self.compact = info["memory_w"] * info["memory_h"] <= COMPACT_MEMORY
        if self.compact:
            poly, splodge, (self.balls_w, self.balls_h) = (COMPACT_POLY, COMPACT_SPLODGE,
                                                           COMPACT_BALLS)
            msg_plane, menu_plane = 6, 3
        else:
            poly, splodge = (transparency.POLY_W, transparency.POLY_H), (
                transparency.SPLODGE_W, transparency.SPLODGE_H)
            self.balls_w, self.balls_h = BALLS_W, BALLS_H
            msg_plane = menu_plane = 0
        c.set_lut(BG_PAGE * 256, ["#23304a"])
        bg = c.create_pad(SCREEN_W, SCREEN_H, 0, lut_page=BG_PAGE)
        c.map(SCREEN, bg, 0, 0, priority=0)
        self.tx_cluster = c.create_cluster(470, SCREEN_H - 60)
        c.map(SCREEN, self.tx_cluster, 10, 50, priority=1)
        self.tx = transparency.build(c, self.tx_cluster, poly_at=(110, 100), splodge_at=(40, 40),
                                     poly_size=poly, splodge_size=splodge)
        c.set_lut(BALL_PAGE * 256, BALL_COLOURS)
        self.db = DoubleBuffer(c, SCREEN, self.balls_w, self.balls_h, 3, lut_page=BALL_PAGE,
                               x=460, y=300, priority=2)
        self.msg = MessageArea(c, 10, 8, 470, 34, MSG_PAGE, plane=msg_plane, priority=3)
        self.msg.show("Appendix I transparency  +  double-buffered pads\n"
                      "middle button: menu", "#c8e8ff")
        self.menu = PopupMenu(c, MENU_ITEMS, lut_page=7, plane=menu_plane, priority=50)
        self.balls = [[40.0 + 37 * i, 30.0 + 23 * i, 2.0 + 0.7 * i, 1.3 + 0.4 * i]
                      for i in range(6)]
        self.t = 0
        self.speed = 1.0
        self.frozen = {"poly": False, "splodge": False}
        self.poly_phase = self.spl_phase = 0.0

    # its declared state (emulator.harness.program_state); the pads are the Rainbow's
    STATE_VERSION = 1
    STATE_SCHEMA = Record(
        t=Int(0), speed=Float(), frozen=Record(poly=Bool(), splodge=Bool()),
        poly_phase=Float(), spl_phase=Float(),
        balls=ListOf(Tuple((Float(), Float(), Float(), Float())), 6),
        db=DoubleBuffer.STATE_SCHEMA, msg=MessageArea.STATE_SCHEMA, menu=PopupMenu.STATE_SCHEMA)

    def state_values(self) -> dict[str, Any]:
        return {"t": self.t, "speed": self.speed, "frozen": dict(self.frozen),
                "poly_phase": self.poly_phase, "spl_phase": self.spl_phase,
                "balls": [tuple(b) for b in self.balls], "db": self.db.state_values(),
                "msg": self.msg.state_values(), "menu": self.menu.state_values()}

    def check_state_values(self, values: dict[str, Any]) -> Callable[[], None]:
        if len(values["balls"]) != len(self.balls):
            raise ValueError(f"{len(values['balls'])} balls, this demo has {len(self.balls)}")
        parts = [self.db.check_state_values(values["db"]),
                 self.msg.check_state_values(values["msg"]),
                 self.menu.check_state_values(values["menu"])]

        def put() -> None:
            self.t, self.speed = values["t"], values["speed"]
            self.frozen = dict(values["frozen"])
            self.poly_phase, self.spl_phase = values["poly_phase"], values["spl_phase"]
            self.balls = [list(b) for b in values["balls"]]
            for part in parts:
                part()
        return put

    def _handle(self, e: object) -> None:
        if not isinstance(e, MouseEvent):
            return
        if e.button == 2 and e.pressed:
            self.menu.open(e.x, e.y)
        elif self.menu.open_ and e.button == 0:
            self.menu.track(e.x, e.y)
        elif self.menu.open_ and e.button == 2 and not e.pressed:
            choice = self.menu.close()
            if choice == "Freeze polygon":
                self.frozen["poly"] = not self.frozen["poly"]
            elif choice == "Freeze splodges":
                self.frozen["splodge"] = not self.frozen["splodge"]
            elif choice == "Faster":
                self.speed *= 1.5
            elif choice == "Slower":
                self.speed /= 1.5
            if choice is not None:
                i = MENU_ITEMS.index(choice)
                self.msg.show(f"Selected: {choice}", self.menu.highlights[i])

    def step(self) -> tuple[int, int]:
        """One frame: read input, move pads, redraw the back buffer, swap, show."""
        c = self.client
        for e in c.poll_events():
            self._handle(e)
        self.t += 1
        if not self.frozen["poly"]:
            self.poly_phase += 0.03 * self.speed
        if not self.frozen["splodge"]:
            self.spl_phase += 0.017 * self.speed
        a, b = self.poly_phase, self.spl_phase
        c.move(self.tx.poly_arc, int(115 + 95 * math.sin(a)), int(160 + 110 * math.sin(1.7 * a)))
        c.move(self.tx.splodge_arc, int(60 + 50 * math.cos(b)), int(120 + 100 * math.sin(b)))
        back = self.db.back
        c.clear(back, 0)
        c.rect(back, 0, 0, self.balls_w, self.balls_h, 7, filled=False)
        for i, ball in enumerate(self.balls):
            x, y, vx, vy = ball
            x, y = x + vx * self.speed, y + vy * self.speed
            if not 14 <= x <= self.balls_w - 14:
                vx = -vx
                x = min(max(x, 14), self.balls_w - 14)
            if not 14 <= y <= self.balls_h - 14:
                vy = -vy
                y = min(max(y, 14), self.balls_h - 14)
            ball[:] = [x, y, vx, vy]
            c.circle(back, int(x), int(y), 12, 1 + i % 6)
        c.text(back, 6, self.balls_h - 14, f"frame {self.t}", 7)
        self.db.swap()
        self.db.move(460 + int(20 * math.sin(self.t / 40)), 300 + int(30 * math.cos(self.t / 50)))
        return c.wait_frame()
