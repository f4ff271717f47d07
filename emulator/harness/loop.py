"""One run loop for every interactive program: a *target* (a program wired to a device) is
ticked on the virtual clock, shown in a window or run headless, with plugin hooks around each
tick (the PyBoy model: ``handle_events``, ``post_tick``, a frame limiter).

One tick::

    events = window.poll()                  (headless: [])
    for plugin: events = plugin.handle_events(harness, events)   (record / replay input)
    Quit in events and target.may_close()  -> stop
    target.handle_events(events)            (host input -> the device's input)
    alive = target.tick()                   (one step of virtual time)
    if target.time() reached the next frame: window.show(frame); plugin.on_frame(harness, frame)
    for plugin: plugin.post_tick(harness)
    stop if not alive, after ``stop_after`` frames, or when a plugin called harness.stop()
    pace: sleep until the wall clock reaches target.time() (``paced`` only)

At the end ``plugin.finish(harness)`` runs for every plugin, then the window closes.
"""

from __future__ import annotations

import sys
from dataclasses import dataclass, field
from fractions import Fraction
from pathlib import Path
from typing import TYPE_CHECKING, Any, Protocol

from camlab88.emulator.harness.control_options import Controls
from camlab88.emulator.host_input import HostEvent, Quit

if TYPE_CHECKING:
    import numpy as np


class Target(Protocol):
    """What the harness runs: a program wired to a device.

    ``title``, ``size`` (device pixels w, h), ``fps`` (frames shown per virtual second) and
    ``keys`` (the one-line key hint printed when a window opens) are attributes.  Optional
    methods the harness uses when present: ``may_close() -> bool`` (a window close is
    refused while e.g. unsaved work is asked about), ``wire() -> list[tuple[str, bytes]]``
    (the wire traffic since the last call, for recordings), ``put_wire(data)`` (replayed
    outside input on the wire), ``finish()`` and ``status() -> str`` (the keys, frame and
    time, shown after ``title`` in the window's title bar), and its declared state:
    ``STATE_VERSION``, ``STATE_SCHEMA``, ``state_values()`` and ``load_state_values(values)``
    (plain values checked against the schema, loaded into a freshly built target of the
    same program all or nothing: emulator.harness.program_state; a target without them
    saves no state file, and F4 keeps its object graph in memory).
    """

    title: str
    size: tuple[int, int]
    fps: float
    keys: str

    def handle_events(self, events: list[HostEvent]) -> None: ...
    def tick(self) -> bool: ...
    def frame(self) -> np.ndarray: ...
    def time(self) -> Fraction: ...


class Plugin:
    """A hook around each tick; subclasses override what they need.

    A plugin that answers keys in the window lists them in a ``keys`` attribute, a list of
    ``(key, what)`` pairs such as ``[("F5", "pause / resume")]``, with an optional
    ``keys_title`` heading; the F1 help overlay (emulator.harness.help) shows every
    plugin's keys with the program's own.  A plugin that acts on a key should take it out
    of the events it returns, so the program (and a recording) never sees it.
    """

    def start(self, harness: Harness) -> None:
        """Called once before the first tick."""

    def handle_events(self, harness: Harness, events: list[HostEvent]) -> list[HostEvent]:
        return events

    def wants_frame(self, harness: Harness) -> bool:
        """Whether ``on_frame`` will look at the frame being shown (``harness.frames_shown``
        counts it already): the harness composes a frame only when a window or a plugin
        wants it, so a headless run nobody watches draws no pictures.  By default: if the
        plugin has an ``on_frame`` of its own."""
        return type(self).on_frame is not Plugin.on_frame

    def on_frame(self, harness: Harness, frame: np.ndarray | None) -> None:
        """Called with every frame shown (window or not); None when nothing wanted it."""

    def post_tick(self, harness: Harness) -> None:
        """Called after every tick."""

    def finish(self, harness: Harness) -> None:
        """Called once at the end (also after an error)."""


@dataclass
class RunOptions:
    """How to run: the flags that mean one thing in every command."""

    headless: bool = True
    paced: bool = True                  # wall clock follows virtual time (window only)
    realtime: bool = False              # ... headless too (replay --period)
    live: bool = False                  # outside bytes come on the wall clock: always paced
    scale: int = 1
    screenshot: Path | None = None      # save the last screen here at the end
    frames: Path | None = None          # DIR: every frame shown as DIR/frame_NNNNN.png
    record: Path | None = None          # a session recording (protocols.session)
    stop_after: int | None = None       # stop after this many frames
    command: str = "camlab88"           # for messages: "camlab88 kas edit"
    argv: list[str] = field(default_factory=list)   # for recordings
    run_only: dict[str, int] = field(default_factory=dict)  # argv's run-only flags: values
    inputs: list[Path] = field(default_factory=list)  # extra input files to record
    controls: Controls = field(default_factory=Controls)  # --speed, --video, --inspect...
    state: Any = None  # emulator.harness.program_state.StateOptions: save states, seeking


class Harness:
    """Runs one target with its options and plugins; see the module docstring."""

    def __init__(self, target: Target, options: RunOptions,
                 plugins: list[Plugin] | None = None) -> None:
        from camlab88.emulator.harness.controls import control_plugins
        from camlab88.emulator.harness.plugins import standard_plugins

        self.target = target
        self.options = options
        standard = standard_plugins(options)  # a replay adjusts the options here
        self.plugins: list[Plugin] = [*control_plugins(options), *standard, *(plugins or [])]
        self.window: Any = None
        self.ticks = 0
        self.frames_shown = 0
        self.last_frame: np.ndarray | None = None
        self.quit = False               # the window was closed / Escape
        self._stop = False
        self._next_show = Fraction(0)
        self._shown_at = Fraction(-1)  # virtual time of the last frame shown

    def stop(self) -> None:
        """End the run after this tick (a plugin's or the program's request)."""
        self._stop = True

    def run(self) -> Harness:
        """Tick until the target finishes, the window closes or a stop; returns self."""
        from camlab88.emulator.harness.pace import Pacer
        from camlab88.emulator.harness.signals import DeferredSignals

        self._open_window()
        c = self.options.controls
        self.pacer = Pacer(self._speed(), c.monotonic, c.sleep)
        with DeferredSignals() as signals:  # Ctrl-C ends the run between ticks
            self.signals = signals  # (a paused run stops waiting when one comes)
            try:
                for p in self.plugins:
                    p.start(self)
                while self._tick_once() and signals.caught is None:
                    if self._running_ahead():
                        self.pacer.release()
                    else:
                        self.pacer.pace(self.target.time())
            finally:
                self._finish()
        signals.deliver()  # after the plugins finished (a recording is written)
        return self

    def _running_ahead(self) -> bool:
        """A live line without ``--speed`` runs as fast as its outside end writes: while bytes
        are on their way (``target.busy()``) no tick waits for the wall clock; once the line
        is idle, line time follows the wall clock again (timeouts, ``--seconds``)."""
        busy = getattr(self.target, "busy", None)
        return (self.options.live and self.options.controls.speed is None
                and callable(busy) and bool(busy()))

    def _speed(self) -> float | None:
        """``--speed`` if given, else period speed when paced (below), else flat out."""
        speed = self.options.controls.speed
        if speed is not None:
            return speed
        return 1.0 if self._paced() else None

    def _paced(self) -> bool:
        o = self.options
        if o.live:  # a live link: line time must follow the wall clock the bytes arrive on
            return True
        return o.screenshot is None and ((self.window is not None and o.paced) or o.realtime)

    def _open_window(self) -> None:
        if self.options.headless:
            return
        from camlab88.emulator.window import Window

        t = self.target
        self.window = Window(t.title, t.size, scale=self.options.scale)
        print(f"{self.options.command}: window open; {t.keys}", file=sys.stderr, flush=True)

    def _tick_once(self) -> bool:
        events = self.window.poll() if self.window is not None else []
        for p in self.plugins:
            events = p.handle_events(self, events)
        if any(isinstance(e, Quit) for e in events) and self._may_close():
            self.quit = True
            return False
        self.target.handle_events([e for e in events if not isinstance(e, Quit)])
        alive = self.target.tick()
        self.ticks += 1
        now = self.target.time()
        if now >= self._next_show or (not alive and now > self._shown_at):
            self._show()  # and the last picture, if time moved on since the last frame
        for p in self.plugins:
            p.post_tick(self)
        limit = self.options.stop_after
        return alive and not self._stop and (limit is None or self.frames_shown < limit)

    def _show(self) -> None:
        self.frames_shown += 1
        wanted = self.window is not None or any(p.wants_frame(self) for p in self.plugins)
        frame = self.target.frame() if wanted else None
        self.last_frame = frame  # None: not composed (harness.screen() composes one)
        self._shown_at = self.target.time()
        self._next_show = self.target.time() + Fraction(1) / Fraction(self.target.fps)
        if self.window is not None:
            self.window.show(frame)
            status = getattr(self.target, "status", None)
            if status is not None:  # the keys, frame and time in the title bar
                self.window.set_caption(f"{self.target.title} | {status()}")
        for p in self.plugins:
            p.on_frame(self, frame)

    def _may_close(self) -> bool:
        may_close = getattr(self.target, "may_close", None)
        return True if may_close is None else bool(may_close())

    def screen(self) -> np.ndarray:
        """The screen now (the last frame shown, or a fresh one)."""
        return self.target.frame()

    def _finish(self) -> None:
        try:
            for p in self.plugins:
                p.finish(self)
            finish = getattr(self.target, "finish", None)
            if finish is not None:
                finish()
        finally:
            if self.window is not None:
                self.window.close()


def run(target: Target, options: RunOptions, plugins: list[Plugin] | None = None) -> Harness:
    """``Harness(target, options, plugins).run()``."""
    return Harness(target, options, plugins).run()
