"""The pygame front-end: shows a device frame scaled, turns host input into host_input events.

This is the only module that imports pygame, and only when a Window is made, so importing
the emulator package (or running headless) never loads pygame.
"""

from __future__ import annotations

import os
import sys
import time
from pathlib import Path
from typing import Any

import numpy as np

from camlab88.emulator.host_input import HostEvent, KeyDown, KeyUp, PointerButton, PointerMove, Quit

_SPECIAL_KEYS = {
    "return": "return",
    "enter": "kp_enter",
    "space": "space",
    "backspace": "backspace",
    "escape": "escape",
    "tab": "tab",
    "delete": "delete",
    "up": "up",
    "down": "down",
    "left": "left",
    "right": "right",
    "home": "home",
    "end": "end",
    "page up": "page_up",
    "page down": "page_down",
    "insert": "insert",
    "left shift": "shift",
    "right shift": "shift",
    "left ctrl": "ctrl",
    "right ctrl": "ctrl",
    "left alt": "alt",
    "right alt": "alt",
    "left meta": "meta",
    "right meta": "meta",
}


def key_name(raw: str) -> str:
    """pygame's key name -> the pygame-independent name used by host_input."""
    raw = raw.lower()
    if raw in _SPECIAL_KEYS:
        return _SPECIAL_KEYS[raw]
    if raw.startswith("[") and raw.endswith("]"):  # keypad keys: "[1]" -> "kp_1"
        return "kp_" + raw[1:-1]
    return raw.replace(" ", "_")


class Window:
    """A window showing frames of ``size`` device pixels (w, h), each scaled ``scale`` times."""

    def __init__(self, title: str, size: tuple[int, int], scale: int = 1) -> None:
        os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")
        # pygame's documented hint: centred, and centred again when the window grows (the
        # inspector beside the screen), so it stays on a screen without a window manager
        os.environ.setdefault("SDL_VIDEO_CENTERED", "1")
        import pygame  # the one place pygame is imported

        if int(scale) != scale or scale < 1:
            raise ValueError(f"scale must be a positive integer, not {scale!r}")
        width, height = size
        if width < 1 or height < 1:
            raise ValueError(f"window size must be positive, not {size!r}")
        self._pg: Any = pygame
        self.size = (int(width), int(height))
        self.scale = int(scale)
        pygame.display.init()
        # fitted from the start: a window opened larger than the screen is placed partly
        # off it (SDL centres it at a negative position; there is no window manager to help)
        self.zoom = fit_zoom(self.size, self.scale, self._screen())  # window px / device px
        window_size = (round(self.size[0] * self.zoom), round(self.size[1] * self.zoom))
        self.surface = pygame.display.set_mode(window_size)
        pygame.display.set_caption(title)
        self.caption = title
        self._last_tick: float | None = None
        self.closed = False
        # the harness's controls draw on what is shown (help overlay, inspector panel beside
        # the screen); pointer input stays in device pixels of ``size``
        self.decorate: Any = None

    def show(self, frame: np.ndarray) -> None:
        """Draw an (h, w, 3) uint8 frame (row 0 = top), nearest-neighbour scaled."""
        pg = self._pg
        w, h = self.size
        if frame.shape != (h, w, 3):
            raise ValueError(f"frame shape {frame.shape} does not match window size {(h, w, 3)}")
        if self.decorate is not None:
            frame = self.decorate(frame)
            h, w = frame.shape[:2]
            self._fit((w, h))
        frame = np.ascontiguousarray(frame, dtype=np.uint8)
        image = pg.image.frombuffer(frame.tobytes(), (w, h), "RGB")
        if self.surface.get_size() != (w, h):
            if self.zoom >= 1:
                image = pg.transform.scale(image, self.surface.get_size())  # nearest neighbour
            else:  # shrunk to fit the screen: averaged, so lines stay visible
                image = pg.transform.smoothscale(image, self.surface.get_size())
        self.surface.blit(image, (0, 0))
        pg.display.flip()

    def _fit(self, size: tuple[int, int]) -> None:
        """Resize the window to show ``size`` pixels (w, h) scaled, if it does not already;
        never larger than the screen it is on (then scaled down to fit)."""
        self.zoom = fit_zoom(size, self.scale, self._screen())
        want = (round(size[0] * self.zoom), round(size[1] * self.zoom))
        if self.surface.get_size() != want:
            self.surface = self._pg.display.set_mode(want)

    def _screen(self) -> tuple[int, int] | None:
        """The size of the screen the window is on (pygame's desktop sizes), if known."""
        sizes = self._pg.display.get_desktop_sizes()
        return tuple(sizes[0]) if sizes else None

    def set_caption(self, text: str) -> None:
        """The window's title bar (set only when it changes)."""
        if text != self.caption:
            self._pg.display.set_caption(text)
            self.caption = text

    def pixels(self) -> np.ndarray:
        """What the window shows now, as an (H, W, 3) uint8 array at window resolution."""
        pg = self._pg
        width, height = self.surface.get_size()
        raw = pg.image.tobytes(self.surface, "RGB")
        return np.frombuffer(raw, dtype=np.uint8).reshape(height, width, 3).copy()

    def screenshot(self, path: str | os.PathLike[str]) -> Path:
        """Save the window surface as a PNG, atomically (base.png, the one writer)."""
        from camlab88.base.png import write_png

        return write_png(self.pixels(), path)

    def _device_xy(self, pos: tuple[int, int]) -> tuple[int, int]:
        w, h = self.size
        x = min(max(int(pos[0] / self.zoom), 0), w - 1)
        y = min(max(int(pos[1] / self.zoom), 0), h - 1)
        return x, y

    def _mods(self, mod: int) -> frozenset[str]:
        pg = self._pg
        names = []
        for bit, name in (
            (pg.KMOD_SHIFT, "shift"),
            (pg.KMOD_CTRL, "ctrl"),
            (pg.KMOD_ALT, "alt"),
            (pg.KMOD_META, "meta"),
        ):
            if mod & bit:
                names.append(name)
        return frozenset(names)

    def convert(self, event: Any) -> HostEvent | None:
        """One pygame event -> a host_input event (None for events devices do not see)."""
        pg = self._pg
        if event.type == pg.QUIT:
            return Quit()
        if event.type == pg.KEYDOWN:
            return KeyDown(
                key_name(pg.key.name(event.key)),
                getattr(event, "unicode", "") or "",
                self._mods(getattr(event, "mod", 0)),
            )
        if event.type == pg.KEYUP:
            return KeyUp(key_name(pg.key.name(event.key)))
        if event.type == pg.MOUSEMOTION:
            x, y = self._device_xy(event.pos)
            held = frozenset(i + 1 for i, down in enumerate(event.buttons[:3]) if down)
            return PointerMove(x, y, held)
        if event.type in (pg.MOUSEBUTTONDOWN, pg.MOUSEBUTTONUP) and 1 <= event.button <= 3:
            x, y = self._device_xy(event.pos)
            return PointerButton(x, y, int(event.button), event.type == pg.MOUSEBUTTONDOWN)
        return None

    def poll(self) -> list[HostEvent]:
        """Events since the last poll, as pygame-free host_input events."""
        out: list[HostEvent] = []
        for event in self._pg.event.get():
            converted = self.convert(event)
            if converted is not None:
                out.append(converted)
        return out

    def wait_frame(self, fps: float) -> None:
        """Sleep so that calls come at most ``fps`` times a wall-clock second (interactive
        pacing only: it never changes what a device shows)."""
        if fps <= 0:
            raise ValueError(f"fps must be positive, not {fps!r}")
        now = time.monotonic()
        if self._last_tick is not None:
            wait = self._last_tick + 1.0 / fps - now
            if wait > 0:
                time.sleep(wait)
                now += wait
        self._last_tick = now

    def close(self) -> None:
        if not self.closed:
            self.closed = True
            self._pg.display.quit()

    def __enter__(self) -> Window:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()


def fit_zoom(size: tuple[int, int], scale: int, screen: tuple[int, int] | None) -> float:
    """Window pixels per picture pixel: ``scale``, or less where the picture (the screen and
    the inspector beside it) would not fit on ``screen`` (w, h)."""
    if screen is None or screen[0] < 1 or screen[1] < 1:
        return float(scale)
    return min(float(scale), screen[0] / size[0], screen[1] / size[1])


def test_card(width: int, height: int) -> np.ndarray:
    """A frame for checking a display: colour bars, a 64-pixel grid, a 1-pixel checkerboard
    (it must stay crisp when scaled) and a white border one pixel wide."""
    frame = np.zeros((height, width, 3), np.uint8)
    bars = np.array(
        [[255, 255, 255], [255, 255, 0], [0, 255, 255], [0, 255, 0],
         [255, 0, 255], [255, 0, 0], [0, 0, 255], [0, 0, 0]],
        np.uint8,
    )
    cols = np.arange(width) * len(bars) // width
    frame[: height // 2] = bars[cols][None, :, :]
    ramp = (np.arange(width) * 255 // max(1, width - 1)).astype(np.uint8)
    frame[height // 2 : 3 * height // 4] = ramp[None, :, None]
    yy, xx = np.mgrid[3 * height // 4 : height, 0:width]
    frame[3 * height // 4 :] = (((xx + yy) % 2) * 255).astype(np.uint8)[:, :, None]
    frame[::64, :] = (128, 128, 128)
    frame[:, ::64] = (128, 128, 128)
    frame[0, :] = frame[-1, :] = frame[:, 0] = frame[:, -1] = 255
    return frame


def main(argv: list[str] | None = None) -> int:
    """``python -m camlab88.emulator.window``: show a test card; report input events on stdout."""
    import argparse

    parser = argparse.ArgumentParser(
        prog="python -m camlab88.emulator.window",
        description="Open the camlab88 window with a test card and print the host input "
        "events it produces (device pixel coordinates). Close the window or press Escape.",
    )
    parser.add_argument("--size", default="768x512", help="device pixels WxH (768x512)")
    parser.add_argument("--scale", type=int, default=1, help="integer scale factor (1)")
    parser.add_argument("--screenshot", metavar="PNG", help="save the window after the first "
                        "frames and exit")
    args = parser.parse_args(argv)
    try:
        width, height = (int(v) for v in args.size.lower().split("x"))
    except ValueError:
        parser.error(f"--size must be WxH, not {args.size!r}")
    from camlab88.emulator.harness.display import display_available

    if not display_available():  # the one display rule: never an invisible window
        print("python -m camlab88.emulator.window: no display for a window (set DISPLAY, or run "
              "under xvfb-run)", file=sys.stderr)
        return 2
    frame = test_card(width, height)
    print("window open: input events are printed; Escape or close to quit", flush=True)
    with Window("camlab88 window test card", (width, height), args.scale) as window:
        for n in range(10**9):
            window.show(frame)
            for event in window.poll():
                print(event, flush=True)
                if isinstance(event, Quit) or (
                    isinstance(event, KeyDown) and event.key == "escape"
                ):
                    return 0
            if args.screenshot and n == 2:
                print(f"screenshot written to {window.screenshot(args.screenshot)}")
                return 0
            window.wait_frame(25)
    return 0


def run_module(argv: list[str] | None = None) -> int:
    """``main`` as ``python -m camlab88.emulator.window`` runs it: Ctrl-C quits as Escape does, with
    the shell's status for an interrupt and no traceback."""
    try:
        return main(argv)
    except KeyboardInterrupt:
        print("python -m camlab88.emulator.window: interrupted", file=sys.stderr)
        return 130


if __name__ == "__main__":
    raise SystemExit(run_module())
