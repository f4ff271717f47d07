"""What a replay's web page needs (``camlab88 replay FILE --html OUT``), gathered while the
replay runs: the frames shown as a browser video at the program's frame rate (a frame that
stood for several frame periods is written that many times, as ``--video`` does), which
video frame each shown frame starts at and its virtual time, every input event the program
was given (the window's or a recording's, and a script's, through the target's
``on_input`` hook), for a Sigma every order the terminal decoded (byte offset, virtual
time, text), and for a Rainbow the inspector's panel beside the screen in the video.

Bounded: at most ``MAX_ROWS`` events and orders are kept (the rest are counted), so a long
session cannot grow the page without limit; the video streams to ffmpeg (flat memory)."""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from camlab88.emulator.harness.loop import Plugin
from camlab88.emulator.harness.video import VideoWriter, video_params

if TYPE_CHECKING:
    from camlab88.emulator.harness.loop import Harness
    from camlab88.emulator.protocol_trace import TraceEvent

MAX_ROWS = 100_000
# Screen content: large flat areas and sharp edges. CRF 23 keeps thin lines legible; a long
# GOP keeps static screens nearly free (a seek decodes from the previous key frame: <= 10 s).
H264 = ["-preset", "veryfast", "-tune", "animation", "-crf", "23", "-g", "250"]


@dataclass
class Capture:
    """What was gathered; ``frames`` rows are (first video frame, virtual time)."""

    fps: float = 25.0
    size: tuple[int, int] = (0, 0)          # the video's (w, h)
    screen: tuple[int, int] = (0, 0)        # the device screen's part of it (w, h)
    device: str = ""
    frames: list[tuple[int, float]] = field(default_factory=list)
    video_frames: int = 0
    events: list[tuple[float, str]] = field(default_factory=list)
    orders: list[tuple[int, float, str, bool]] = field(default_factory=list)
    dropped_events: int = 0
    dropped_orders: int = 0
    panel: bool = False
    last: np.ndarray | None = None          # the last screen shown (a gallery's thumbnail)


def web_params(path: Path) -> dict[str, Any]:
    """write_frames arguments for a page's video: ``.mp4`` H.264, ``.webm`` VP9."""
    params = video_params(path)
    if path.suffix.lower() == ".mp4":
        params = {**params, "quality": None,
                  "output_params": [*H264, *params["output_params"]]}
    return params


class WebCapture(Plugin):
    """Gathers a :class:`Capture` while the replay runs; the video goes to ``video``."""

    def __init__(self, video: Path) -> None:
        self.video = Path(video)
        self.data = Capture()
        self._writer: VideoWriter | None = None
        self._panel: Any = None
        # a command running more than one harness: the first one's run is the page's
        self._harness: Harness | None = None

    # ------------------------------------------------------------------ set-up
    def start(self, harness: Harness) -> None:
        if self._harness is not None:
            return
        self._harness = harness
        target = harness.target
        self.data.fps = float(target.fps)
        self.data.device = _device_name(target)
        self._writer = VideoWriter(self.video, web_params(self.video), quiet=True)
        if hasattr(target, "on_input"):
            target.on_input = lambda ev: self._event(harness, ev)
        machine = _sigma_machine(target)
        if machine is not None:
            old = machine.tracer
            def sink(ev: TraceEvent) -> None:
                self._order(ev)
                if old is not None:
                    old.sink(ev)
            machine.trace(sink, old.strict if old is not None else False)
        elif self.data.device.startswith("Rainbow"):
            from camlab88.emulator.inspect import panel_for

            self._panel = panel_for(target)
            self.data.panel = self._panel is not None

    # ------------------------------------------------------------------ input and orders
    def handle_events(self, harness: Harness, events: list[Any]) -> list[Any]:
        """The window's or the recording's events (a script's come through ``on_input``)."""
        if self._writer is not None and harness is self._harness:
            for ev in events:
                if type(ev).__name__ != "Quit":
                    self._event(harness, ev)
        return events

    def _event(self, harness: Harness, ev: Any) -> None:
        if len(self.data.events) >= MAX_ROWS:
            self.data.dropped_events += 1
            return
        self.data.events.append((float(harness.target.time()), describe_event(ev)))

    def _order(self, ev: TraceEvent) -> None:
        if len(self.data.orders) >= MAX_ROWS:
            self.data.dropped_orders += 1
            return
        from camlab88.emulator.inspect.sigma import order_text

        self.data.orders.append((ev.offset, ev.time, order_text(ev)[:200],
                                 ev.warning is not None))

    # ------------------------------------------------------------------ frames
    def on_frame(self, harness: Harness, frame: np.ndarray) -> None:
        if self._writer is None or harness is not self._harness:
            return
        h, w = frame.shape[:2]
        self.data.screen = (w - w % 2, h - h % 2)
        self.data.last = frame.copy()  # the device may draw the next one into the same array
        if self._panel is not None:
            frame = np.concatenate([frame, self._panel(frame)], axis=1)
        first = self._writer.count
        self._writer.on_frame(harness, frame)
        self.data.frames.append((first, float(harness.target.time())))
        self.data.size = self._writer.size
        self.data.video_frames = self._writer.count

    def finish(self, harness: Harness) -> None:
        if self._writer is not None and harness is self._harness:
            writer, self._writer = self._writer, None
            writer.finish(harness)
            self.data.video_frames = writer.count


def _sigma_machine(target: Any) -> Any:
    """The SigmaMachine behind a Sigma target (its ``trace`` reports every order)."""
    for m in (getattr(target, "machine", None),
              getattr(getattr(target, "run", None), "machine", None)):
        if m is not None and hasattr(m, "trace") and hasattr(m, "terminal"):
            return m
    return None


def _device_name(target: Any) -> str:
    machine = _sigma_machine(target)
    if machine is not None:
        return f"Sigma {machine.terminal.model.name.upper()}"
    term = getattr(target, "term", None)
    if term is not None and hasattr(term, "model"):
        return f"Sigma {term.model.name.upper()}"
    from camlab88.emulator.machine import RainbowMachine  # a Sigma run never gets here

    if isinstance(getattr(target, "machine", None), RainbowMachine):
        return "Rainbow workstation"
    return type(target).__name__


BUTTONS = {1: "left", 2: "middle", 3: "right"}


def describe_event(ev: Any) -> str:
    """One input event as a short line: ``press middle 300,300``, ``key space``,
    ``stylus down -4,-2``.  Host events (emulator.host_input), Rainbow device events and
    the Sigma programs' timed script events are told apart by their fields."""
    kind = type(ev).__name__
    if kind == "KeyDown":
        return f"key {ev.key}"
    if kind == "KeyUp":
        return f"key {ev.key} up"
    if kind == "PointerMove":
        return f"pointer {ev.x},{ev.y}" + (" held" if ev.buttons else "")
    if kind == "PointerButton":
        return f"{'press' if ev.pressed else 'release'} {BUTTONS.get(ev.button, ev.button)} " \
               f"{ev.x},{ev.y}"
    if kind == "MouseEvent":
        if ev.button == 0:
            return f"mouse {ev.x},{ev.y}"
        name = BUTTONS.get(ev.button, str(ev.button))
        return f"{'press' if ev.pressed else 'release'} {name} {ev.x},{ev.y}"
    if kind == "KeyEvent":
        return f"key {ev.key}" + ("" if ev.pressed else " up")
    if kind == "TabletEvent":
        return f"stylus {ev.x},{ev.y} pressure {ev.pressure}"
    if kind == "TimedEvent":  # a Sigma program's script: stylus in field inches, or a key
        if ev.kind == "key":
            return f"key {ev.key}"
        if ev.kind == "pointer":
            return f"stylus {'down' if ev.down else 'up'} {ev.x:g},{ev.y:g}"
        return ev.kind
    if kind == "Command":  # the painting program's script: a command and its words
        return " ".join([ev.name, *map(str, ev.args)])
    return kind
