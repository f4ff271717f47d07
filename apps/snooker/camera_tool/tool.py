"""The interactive camera tool (thesis §6.5's "better approach"): the script beside the live
view; every edit -- typed here, or saved to the file from any text editor -- is
re-interpreted at once and the view follows; errors are marked at their lines while the
preview goes on with the rest of the script; the time line shows the shot's events and the
commands' periods; scrub to any frame and read its observer, viewpoint and focal length.

Keys: typing edits the script (arrows, home/end, backspace/delete, return); ctrl-s saves it,
ctrl-r reloads it from disk; tab plays/pauses; page up/page down step one frame; escape
quits.  The left button on the time line scrubs; on the script it places the cursor.
"""

from __future__ import annotations

import os
import textwrap
from pathlib import Path

from camlab88.apps.snooker.camera import ccl
from camlab88.apps.snooker.camera.interpreter import Interpretation
from camlab88.apps.snooker.camera.motion import Motion, timeline_events
from camlab88.apps.snooker.camera.projection import Camera, CameraError
from camlab88.apps.snooker.camera.space import table_to_ccl
from camlab88.apps.snooker.camera_tool import layout
from camlab88.apps.snooker.camera_tool.editor import TextBuffer
from camlab88.apps.snooker.camera_tool.panes import InfoPane, ScriptPane, Timeline
from camlab88.apps.snooker.camera_tool.watch import FileWatch
from camlab88.apps.snooker.table import BALL_NAMES
from camlab88.apps.snooker.visualiser.display import ViewDisplay
from camlab88.base.atomicfile import write_atomic
from camlab88.protocols.rainbow.client import SCREEN, RainbowClient
from camlab88.protocols.rainbow.events import LEFT, KeyEvent, MouseEvent

VIEW_PAGE = 1
DEVICE_FRAMES_PER_FRAME = 2  # 25 frames/s


class CameraTool:
    def __init__(self, client: RainbowClient, motion: Motion,
                 script: str | os.PathLike[str]) -> None:
        self.client, self.motion, self.path = client, motion, Path(script)
        self.buf = TextBuffer(self._read())
        self.watch = FileWatch(self.path)
        # Texts read from disk after the start, for session recordings (the harness's
        # "outside" wire); a replay feeds them back instead of reading the disk.
        self.outside: list[str] = []
        self.fed: list[str] | None = None
        self.writes = True  # False while a save state's load runs the session again
        x, y, w, h = layout.VIEW
        self.view = ViewDisplay(client, SCREEN, x, y, w, h, VIEW_PAGE)
        self.script_pane, self.info, self.timeline = (ScriptPane(client), InfoPane(client),
                                                      Timeline(client))
        self.events = timeline_events(motion)
        self.frame, self.playing, self.done = 1, True, False
        self.modified, self.ctrl, self.scrubbing = False, False, False
        self.status = f"{self.path.name}"
        self.result: Interpretation | None = None
        self.dirty = True  # the script must be interpreted (and its panes drawn)
        self.interpretations = 0

    def _read(self) -> str:
        try:
            return ccl.read_script(self.path)
        except FileNotFoundError:
            return ":\n"
        except ccl.CclErrors as exc:  # not UTF-8: show what we can, the error in the status
            self.status = str(exc)
            return self.path.read_bytes().decode("utf-8", errors="replace")

    # -- one frame of the program ------------------------------------------------------------
    def step(self) -> bool:
        for e in self.client.poll_events():
            self.handle(e)
        self.poll_file()
        if self.dirty:
            self.reinterpret()
        self.show()
        for _ in range(DEVICE_FRAMES_PER_FRAME):
            self.client.wait_frame()
        if self.playing:
            self.frame = self.frame % self.motion.n_frames + 1
        return not self.done

    def read_outside(self) -> str:
        """The script as it is on disk now (recorded), or as it was when recorded (replay)."""
        if self.fed is not None:
            return self.fed.pop(0) if self.fed else self.buf.text
        text = self._read()
        self.outside.append(text)
        return text

    def feed(self, text: str) -> None:
        """A replay: the text the recorded run read from disk at this point."""
        self.fed = (self.fed or []) + [text]

    def _disk_changed(self) -> bool:
        return bool(self.fed) if self.fed is not None else self.watch.changed()

    def poll_file(self) -> None:
        if not self._disk_changed():
            return
        text = self.read_outside()
        if text == self.buf.text:
            return
        if self.modified:
            self.status = f"{self.path.name} changed on disk: ctrl-r reloads it"
            self.dirty = True
            return
        self.buf.replace(text)
        self.status = f"reloaded {self.path.name}"
        self.dirty = True

    def reinterpret(self) -> None:
        self.result = ccl.run(self.buf.text, self.motion)
        self.interpretations += 1
        self.dirty = False
        mark = " (modified: ctrl-s saves)" if self.modified else ""
        self.script_pane.draw(self.buf, self.result.errors, self.status + mark)
        self.timeline.draw(self.motion.n_frames, self.events, self.result.periods)
        self.view.force_redraw()

    def show(self) -> None:
        r, f, m = self.result, self.frame, self.motion
        assert r is not None
        lines = self._values(r, f)
        try:
            cam = Camera(r.observer[f - 1], r.viewpoint[f - 1], float(r.focal[f - 1]))
            self.view.show(cam, m.table, m.centres[f - 1], m.on_table[f - 1])
        except CameraError as exc:
            lines.append((f"cannot draw frame {f}: {exc}", 2))
        self.info.draw(lines)
        self.timeline.mark(f, m.n_frames)

    def _values(self, r: Interpretation, f: int) -> list[tuple[str, int]]:
        # shown in CCL's space, the one the script is written in
        o, v = table_to_ccl(r.observer[f - 1]), table_to_ccl(r.viewpoint[f - 1])
        line = int(r.command_line[f - 1])
        here = [e for e in self.events if e[0] == f]
        lines = [
            (f"frame {f} of {self.motion.n_frames}   {'playing' if self.playing else 'paused'}"
             f"   {'set by the command at line ' + str(line) if line else 'start-of-day values'}",
             1),
            (f"observer  ({o[0]:8.3f}, {o[1]:8.3f}, {o[2]:8.3f}) m", 1),
            (f"viewpoint ({v[0]:8.3f}, {v[1]:8.3f}, {v[2]:8.3f}) m", 1),
            (f"focal length {r.focal[f - 1]:.1f} mm", 1),
            ("events: " + (", ".join(_event_text(k, b) for _, k, b in here)
                           or "none this frame"), 3),
        ]
        n = len(r.errors)
        lines.append((f"{n} error{'' if n == 1 else 's'}" if n else "no errors", 2 if n else 1))
        for e in r.errors[:10]:  # wrapped to the pane, continuation rows indented
            rows = textwrap.wrap(f"{e.line}:{e.col}: {e.message}", layout.INFO_COLS - 2,
                                 subsequent_indent="    ")
            lines += [(row, 2) for row in rows]
        return lines

    # -- input ---------------------------------------------------------------------------
    def handle(self, e: object) -> None:
        if isinstance(e, KeyEvent):
            if e.key == "ctrl":
                self.ctrl = e.pressed
            elif e.pressed:
                self.key(e.key, e.char)
        elif isinstance(e, MouseEvent):
            self.mouse(e)

    def key(self, key: str, char: str) -> None:
        if self.ctrl:
            {"s": self.save, "r": self.reload}.get(key, lambda: None)()
            return
        b = self.buf
        frame_keys = {"page_up": -1, "page_down": 1}
        edits = {"return": b.newline, "kp_enter": b.newline, "backspace": b.backspace,
                 "delete": b.delete, "home": b.home, "end": b.end}
        moves = {"up": (-1, 0), "down": (1, 0), "left": (0, -1), "right": (0, 1)}
        if key == "escape":
            self.done = True
        elif key == "tab":
            self.playing = not self.playing
        elif key in frame_keys:
            self.playing = False
            self.frame = max(1, min(self.motion.n_frames, self.frame + frame_keys[key]))
        elif key in moves:
            b.move(*moves[key])
            self.dirty = True
        elif key in edits:
            edits[key]()
            self.edited(key not in ("home", "end"))
        elif char and char.isprintable():
            b.insert(char)
            self.edited(True)

    def edited(self, changed: bool) -> None:
        self.modified = self.modified or changed
        self.dirty = True

    def mouse(self, e: MouseEvent) -> None:
        if e.button == 1:
            self.scrubbing = e.pressed and e.y >= layout.TIMELINE[1] and e.x < layout.VIEW[2]
            if e.pressed and e.x >= layout.SCRIPT[0]:
                self.buf.place(*self.script_pane.cell_at(e.x, e.y))
                self.dirty = True
        if self.scrubbing and (e.buttons & LEFT):
            self.playing = False
            self.frame = layout.timeline_frame(e.x - layout.TIMELINE[0], self.motion.n_frames)

    def save(self) -> None:
        if self.writes:
            write_atomic(self.path, self.buf.text)
            self.watch.seen()
        self.modified = False
        self.status = f"saved {self.path.name}"
        self.dirty = True

    def reload(self) -> None:
        self.buf.replace(self.read_outside())
        self.watch.seen()
        self.modified = False
        self.status = f"reloaded {self.path.name}"
        self.dirty = True


def _event_text(kind: str, ball: int) -> str:
    if kind == "strike":
        return f"the cue ball strikes the {BALL_NAMES[ball]}"
    return f"{BALL_NAMES[ball]} {kind}s"
