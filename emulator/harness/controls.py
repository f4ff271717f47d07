"""The emulator controls every window has, whatever the device or program (docs/harness.md,
"Controls"): F1 help, F5 pause/resume, F6 one frame, F7/F8 half/double speed, F11 the
inspector, F12 a screenshot, Esc quit (as closing the window: ``target.may_close()`` asks
first; a target whose program reads Esc itself sets ``escape_is_a_key``); and the title
bar's frame, virtual time and speed.

:class:`ControlKeys` runs first among the plugins and takes its keys out of the events, so
a program never sees them, a recording never holds them and a replay can be paused.  While
paused it keeps the window answering (it polls, redraws, sleeps a 50th of a second) inside
``handle_events``; the tick after a pause is re-anchored on the wall clock."""

from __future__ import annotations

import sys
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from camlab88.base.png import write_png
from camlab88.emulator.harness.control_options import SPEED_MAX, SPEED_MIN, Controls, clamp_speed
from camlab88.emulator.harness.loop import Plugin, RunOptions
from camlab88.emulator.harness.written import tell_written
from camlab88.emulator.host_input import HostEvent, KeyDown, KeyUp, Quit

if TYPE_CHECKING:
    from camlab88.emulator.harness.loop import Harness

KEYS = [("F1", "show / hide these keys"), ("F5", "pause / resume"),
        ("F6", "advance one frame (and pause)"), ("F7", "slower (half speed)"),
        ("F8", "faster (double speed)"), ("F11", "inspector beside the screen on / off"),
        ("F12", "screenshot: a PNG of the screen, its name printed"),
        ("Esc, close", "quit (asks first where there is unsaved work)")]
CONTROL_KEYS = frozenset({"f1", "f5", "f6", "f7", "f8", "f11", "f12"})
IDLE = 1 / 50  # wall seconds between polls while paused


class ControlKeys(Plugin):
    """The control keys of a window (headless it only keeps the title-bar text)."""

    keys = KEYS
    keys_title = "Emulator controls"

    def __init__(self, controls: Controls) -> None:
        self.controls = controls
        self.paused = self.stepping = self.help = False
        self.inspect = controls.inspect
        self.shots: list[Path] = []
        self.note = ""  # a message shown in the title bar until the next one
        self._panel: Any = None

    def start(self, harness: Harness) -> None:
        if getattr(harness.target, "escape_is_a_key", False):  # the help says what Esc is
            self.keys = [*KEYS[:-1], ("Esc", "the program's own key"),
                         ("close", "quit (asks first where there is unsaved work)")]
        if harness.window is not None:
            harness.window.decorate = lambda frame: self.decorate(harness, frame)

    # ------------------------------------------------------------------ keys
    def handle_events(self, harness: Harness, events: list[HostEvent]) -> list[HostEvent]:
        events = self._take(harness, events)
        while self.paused and not self.stepping and harness.window is not None:
            if any(isinstance(e, Quit) for e in events) or _signalled(harness):
                break
            self.controls.sleep(IDLE)
            events += self._take(harness, harness.window.poll())
        return events

    def _take(self, harness: Harness, events: list[HostEvent]) -> list[HostEvent]:
        """Act on the control keys in ``events``; the others go on to the program."""
        rest = []
        own_escape = bool(getattr(harness.target, "escape_is_a_key", False))
        for e in events:
            if isinstance(e, KeyDown) and e.key == "escape" and not own_escape:
                rest.append(Quit())  # as closing the window: may_close() asks first
            elif isinstance(e, KeyDown) and e.key in CONTROL_KEYS:
                self._key(harness, e.key)
            elif not (isinstance(e, KeyUp) and (e.key in CONTROL_KEYS or (
                    e.key == "escape" and not own_escape))):
                rest.append(e)
        return rest

    def _key(self, harness: Harness, key: str) -> None:
        if key == "f5":
            self.paused, self.stepping = not self.paused, False
            if not self.paused:
                harness.pacer.rebase(harness.target.time())
        elif key == "f6":
            self.paused = self.stepping = True
        elif key in ("f7", "f8"):
            self._speed(harness, 0.5 if key == "f7" else 2.0)
        elif key == "f12":
            self.screenshot(harness)
        elif key == "f1":
            self.help = not self.help
        elif key == "f11":
            self.inspect = not self.inspect
        self._redraw(harness)

    def _speed(self, harness: Harness, factor: float) -> None:
        """Halve or double the speed; flat out starts from the speed it achieved."""
        pacer, now = harness.pacer, harness.target.time()
        base = pacer.speed if pacer.speed is not None else pacer.achieved(now)
        if base is None:
            base = SPEED_MAX if factor > 1 else 1.0
        new = base * factor
        pacer.set_speed(None if new > SPEED_MAX else clamp_speed(new), now)
        self.note = f"speed {speed_text(pacer.speed)}"

    def screenshot(self, harness: Harness) -> Path:
        """The screen as shown, at device resolution, as a new PNG (never overwrites)."""
        frame = harness.last_frame if harness.last_frame is not None else harness.screen()
        folder = self.controls.shots or Path.cwd()
        k = harness.frames_shown
        path = folder / f"camlab88-{k:05d}.png"
        n = 1
        while path.exists():
            path, n = folder / f"camlab88-{k:05d}-{n}.png", n + 1
        try:
            write_png(frame, path)
        except OSError as exc:
            self.note = f"screenshot failed: {exc.strerror or exc}"
            print(f"{harness.options.command}: cannot write {path}: {exc.strerror or exc}",
                  file=sys.stderr)
            return path
        self.shots.append(path)
        self.note = f"screenshot {path.name}"
        tell_written(harness, f"screenshot {path}")
        return path

    # ------------------------------------------------------------------ window
    def wants_frame(self, harness: Harness) -> bool:
        return False  # only that a frame was shown matters here

    def on_frame(self, harness: Harness, frame: np.ndarray | None) -> None:
        self.stepping = False  # one frame advanced: paused again from the next tick
        if harness.window is not None:
            harness.window.set_caption(caption(harness, self))

    def _redraw(self, harness: Harness) -> None:
        w = harness.window
        if w is not None and not w.closed and harness.last_frame is not None:
            w.show(harness.last_frame)
            w.set_caption(caption(harness, self))

    def decorate(self, harness: Harness, frame: np.ndarray) -> np.ndarray:
        """The window's picture: the frame, the help overlay, the inspector panel."""
        from camlab88.emulator.harness.help import key_lines, overlay

        if self.help:
            frame = overlay(frame, key_lines(harness))
        if not self.inspect:
            return frame
        from camlab88.emulator.inspect.find import nothing

        if self._panel is None:
            from camlab88.emulator.inspect import panel_for

            self._panel = panel_for(harness.target) or False
        panel = self._panel(frame) if self._panel else nothing(frame.shape[0])
        return np.concatenate([frame, panel], axis=1)


def _signalled(harness: Harness) -> bool:
    """Ctrl-C or SIGTERM came (the run ends after the next tick, as unpaused)."""
    return getattr(getattr(harness, "signals", None), "caught", None) is not None


def speed_text(speed: float | None) -> str:
    return "flat out" if speed is None else f"x{speed:g}"


def status_text(harness: Harness) -> str:
    """The program's own status, or frame number, virtual time and key hint."""
    status = getattr(harness.target, "status", None)
    if status is not None:
        return str(status())
    t = float(harness.target.time())
    return f"frame {harness.frames_shown}  t {t:.2f} s  {harness.target.keys}"


def caption(harness: Harness, keys: ControlKeys) -> str:
    pacer = getattr(harness, "pacer", None)
    state = "PAUSED (F5 resumes, F6 one frame)" if keys.paused else \
        speed_text(pacer.speed if pacer is not None else None)
    note = f" | {keys.note}" if keys.note else ""
    return f"{harness.target.title} | {status_text(harness)} | {state}{note} | F1 keys"


def control_plugins(options: RunOptions) -> list[Plugin]:
    """The controls' plugins: the keys always, ``--video`` and ``--inspect-out`` if asked."""
    c = options.controls
    plugins: list[Plugin] = [ControlKeys(c)]
    if c.video is not None:
        from camlab88.emulator.harness.video import VideoWriter

        plugins.append(VideoWriter(c.video))
    if c.inspect_out is not None:
        from camlab88.emulator.harness.inspect_out import InspectOut

        plugins.append(InspectOut(c.inspect_out))
    return plugins


__all__ = ["SPEED_MAX", "SPEED_MIN", "ControlKeys", "caption", "control_plugins"]
