"""The visualiser program (thesis §6.3.2): plays a view file over the balls' motion at
25 frames/s on the Rainbow, steps and scrubs.

Keys: space play/pause; right/left one frame; page down/page up 25 frames; home/end the
first/last frame; escape or q quits.  Dragging with the left button scrubs: the pointer's
x across the screen is the frame.  Talks to the device only through the pad library.

The view is the film frame, 768 x 512 (the renderer's picture), centred on the 768 x 576
screen with the bands above and below masked: §6.3.2 wants positions "exactly as it will be
in the finished sequence", so a ball the film would not show is not shown here either.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any

from camlab88.apps.snooker.camera.motion import Motion
from camlab88.apps.snooker.camera.projection import FILM_H, FILM_W
from camlab88.apps.snooker.camera.views import View
from camlab88.apps.snooker.visualiser.display import ViewDisplay
from camlab88.base.plainstate import Bool, Int, Opt, Record
from camlab88.protocols.rainbow.client import SCREEN, SCREEN_H, SCREEN_W, RainbowClient
from camlab88.protocols.rainbow.events import LEFT, KeyEvent, MouseEvent
from camlab88.protocols.rainbow.ui import DoubleBuffer

LUT_PAGE = 1
DEVICE_FRAMES_PER_FRAME = 2  # 25 frames/s on the 50 Hz display
FILM_TOP = (SCREEN_H - FILM_H) // 2  # the film frame's top row on the screen
MASK = "#000000"  # the screen outside the film frame


class ViewsError(ValueError):
    pass


def check_views(views: Sequence[View], motion: Motion) -> None:
    if not views:
        raise ViewsError("the view file has no frames")
    last = views[-1].frame
    if last > motion.n_frames:
        raise ViewsError(f"the view file goes to frame {last} but the motion has only "
                         f"{motion.n_frames} frames")


class Visualiser:
    def __init__(self, client: RainbowClient, motion: Motion, views: Sequence[View]) -> None:
        check_views(views, motion)
        self.client = client
        self.motion = motion
        self.views = list(views)
        self.cameras = [v.camera() for v in self.views]
        client.set_lut(0, [MASK])  # the root's colour: the masked bands
        self.display = ViewDisplay(client, SCREEN, 0, FILM_TOP, FILM_W, FILM_H, LUT_PAGE)
        self.index = 0  # into self.views
        self.drawn: int | None = None
        self.playing = True
        self.done = False
        self.dragging = False

    @property
    def frame(self) -> int:
        return self.views[self.index].frame

    # its declared state (the harness's program_state): where it is in the view file, what
    # is drawn and which view's table is on show (an index into the views: the cameras are
    # the view file's); the pads are the Rainbow's
    STATE_VERSION = 1
    STATE_SCHEMA = Record(index=Int(0), drawn=Opt(Int(0)), playing=Bool(), done=Bool(),
                          dragging=Bool(), table_shown=Opt(Int(0)), table_redraws=Int(0),
                          tables=DoubleBuffer.STATE_SCHEMA, balls=DoubleBuffer.STATE_SCHEMA)

    def state_values(self) -> dict[str, Any]:
        d = self.display
        shown = next((i for i, c in enumerate(self.cameras) if c is d.shown), None)
        if d.shown is not None and shown is None:
            raise ValueError("the view on show is not one of the view file's")
        return {"index": self.index, "drawn": self.drawn, "playing": self.playing,
                "done": self.done, "dragging": self.dragging, "table_shown": shown,
                "table_redraws": d.table_redraws, "tables": d.tables.state_values(),
                "balls": d.balls.state_values()}

    def check_state_values(self, values: dict[str, Any]) -> Callable[[], None]:
        n = len(self.views)
        for name in ("index", "drawn", "table_shown"):
            if values[name] is not None and values[name] >= n:
                raise ValueError(f"{name} {values[name]}: the view file has {n} views")
        d = self.display
        parts = [d.tables.check_state_values(values["tables"]),
                 d.balls.check_state_values(values["balls"])]

        def put() -> None:
            self.index, self.drawn = values["index"], values["drawn"]
            self.playing, self.done = values["playing"], values["done"]
            self.dragging = values["dragging"]
            shown = values["table_shown"]
            d.shown = None if shown is None else self.cameras[shown]
            d.table_redraws = values["table_redraws"]
            for part in parts:
                part()
        return put

    def draw(self) -> bool:
        """Draw the current frame if it is not the one on show; True if drawn."""
        if self.drawn == self.index:
            return False
        f = self.frame
        self.display.show(self.cameras[self.index], self.motion.table,
                          self.motion.centres[f - 1], self.motion.on_table[f - 1])
        self.drawn = self.index
        return True

    def step(self, on_shown: Callable[[int], None] | None = None) -> None:
        """One frame of the program: input, draw, two device frames, advance if playing."""
        for e in self.client.poll_events():
            self.handle(e)
        drawn = self.draw()
        for k in range(DEVICE_FRAMES_PER_FRAME):
            self.client.wait_frame()
            if k == 0 and drawn and on_shown is not None:
                on_shown(self.frame)
        if self.playing and self.index < len(self.views) - 1:
            self.index += 1

    def play_through(self, on_shown: Callable[[int], None] | None = None) -> int:
        """Every frame once, in order (headless, or writing frames); returns the count."""
        self.index, self.playing = 0, True
        shown = 0
        while not self.done:
            last = self.index == len(self.views) - 1
            self.step(on_shown)
            shown += 1
            if last:
                break
        return shown

    # -- input ---------------------------------------------------------------------------
    def handle(self, e: object) -> None:
        if isinstance(e, KeyEvent) and e.pressed:
            self.key(e.key)
        elif isinstance(e, MouseEvent):
            if e.button == 1:
                self.dragging = e.pressed
            if self.dragging or (e.buttons & LEFT):
                self.scrub_to(e.x)

    def key(self, key: str) -> None:
        n = len(self.views)
        moves = {"right": 1, "left": -1, "page_down": 25, "page_up": -25}
        if key == "space":
            self.playing = not self.playing
            if self.playing and self.index == n - 1:
                self.index = 0
        elif key in moves:
            self.playing = False
            self.index = max(0, min(n - 1, self.index + moves[key]))
        elif key in ("home", "end"):
            self.playing = False
            self.index = 0 if key == "home" else n - 1
        elif key in ("escape", "q"):
            self.done = True

    def scrub_to(self, x: int) -> None:
        self.playing = False
        n = len(self.views)
        self.index = max(0, min(n - 1, x * n // SCREEN_W))
