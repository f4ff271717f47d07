"""The camera tool's panes, drawn through the pad library: the script (errors marked at
their lines, the cursor), the frame's values and messages, and the time line with the
shot's events and the commands' periods."""

from __future__ import annotations

from collections.abc import Sequence

from camlab88.apps.snooker.camera.errors import CclError
from camlab88.apps.snooker.camera_tool import fit, layout
from camlab88.apps.snooker.camera_tool.editor import TextBuffer
from camlab88.protocols.rainbow.client import SCREEN, RainbowClient

SCRIPT_PAGE, INFO_PAGE, TIMELINE_PAGE, MARKER_PAGE = 2, 3, 4, 5
SCRIPT_COLOURS = ["#101418", "#d8d8d0", "#601818", "#f0c000"]  # bg, text, error line, cursor
INFO_COLOURS = ["#101418", "#d8d8d0", "#ff7060", "#80c0ff"]  # bg, text, error, status
TIMELINE_COLOURS = ["#101418", "#505860", "#ff4040", "#40d060", "#f0d040", "#2a3038",
                    "#384048", "#d8d8d0"]  # bg, axis, strike, start, stop, periods a/b, text
EVENT_VALUE = {"strike": 2, "start": 3, "stop": 4}
EVENT_ROWS = {"strike": (6, 42), "start": (14, 26), "stop": (26, 38)}


def _pad(client: RainbowClient, box: tuple[int, int, int, int], depth: int, page: int,
         colours: Sequence[str]) -> int:
    x, y, w, h = box
    client.set_lut(page * 256, list(colours) + ["#000000"] * (256 - len(colours)))
    pad = client.create_pad(w, h, depth, plane=0, lut_page=page)
    client.map(SCREEN, pad, x, y, 1)
    return pad


class ScriptPane:
    def __init__(self, client: RainbowClient) -> None:
        self.client = client
        self.pad = _pad(client, layout.SCRIPT, 2, SCRIPT_PAGE, SCRIPT_COLOURS)
        self.top = self.left = 0  # the first line and column shown

    def draw(self, buf: TextBuffer, errors: Sequence[CclError], status: str) -> None:
        c, rows = self.client, layout.SCRIPT_ROWS
        self.top = min(max(self.top, buf.line - rows + 1), buf.line)
        self.left = fit.scroll_left(self.left, buf.col, layout.SCRIPT_COLS)
        c.clear(self.pad, 0)
        bad = {e.line - 1 for e in errors}
        cw, ch = layout.CHAR_W, layout.CHAR_H
        for row in range(rows):
            n = self.top + row
            if n >= len(buf.lines):
                break
            if n in bad:
                c.rect(self.pad, 0, row * ch, layout.SCRIPT[2], ch, 2)
            text = fit.window(buf.lines[n].expandtabs(1), self.left, layout.SCRIPT_COLS)
            if text.strip():
                c.text(self.pad, 3, row * ch, text, 1)
        cy = (buf.line - self.top) * ch
        c.rect(self.pad, 2 + (buf.col - self.left) * cw, cy, 1, ch, 3)
        c.text(self.pad, 3, rows * ch, fit.elide(status, layout.SCRIPT_COLS), 3)

    def cell_at(self, x: int, y: int) -> tuple[int, int]:
        """Screen point -> (line, column) of the script."""
        sx, sy = x - layout.SCRIPT[0], y - layout.SCRIPT[1]
        return self.top + sy // layout.CHAR_H, self.left + max(
            0, (sx - 3 + layout.CHAR_W // 2) // layout.CHAR_W)


class InfoPane:
    def __init__(self, client: RainbowClient) -> None:
        self.client = client
        self.pad = _pad(client, layout.INFO, 2, INFO_PAGE, INFO_COLOURS)
        self.shown: tuple[object, ...] | None = None

    def draw(self, lines: Sequence[tuple[str, int]]) -> None:
        """(text, value) rows; redrawn only when they change."""
        key = tuple(lines)
        if key == self.shown:
            return
        self.shown = key
        c = self.client
        c.clear(self.pad, 0)
        rows = fit.wrap_rows(lines, layout.INFO_COLS - 1, layout.INFO[3] // layout.CHAR_H)
        for row, (text, value) in enumerate(rows):
            if text:
                c.text(self.pad, 2, row * layout.CHAR_H, text, value)


class Timeline:
    def __init__(self, client: RainbowClient) -> None:
        self.client = client
        self.pad = _pad(client, layout.TIMELINE, 3, TIMELINE_PAGE, TIMELINE_COLOURS)
        client.set_lut(MARKER_PAGE * 256, ["#000000", "#40e0ff"])
        self.marker = client.create_pad(2, layout.TIMELINE[3], 1, plane=0, lut_page=MARKER_PAGE)
        client.clear(self.marker, 1)
        x, y = layout.TIMELINE[0], layout.TIMELINE[1]
        self.marker_arc = client.map(SCREEN, self.marker, x, y, 2)
        self.at: int | None = None

    def draw(self, n_frames: int, events: Sequence[tuple[int, str, int]],
             periods: Sequence[tuple[int, int, int]]) -> None:
        c, pad = self.client, self.pad
        c.clear(pad, 0)
        for k, (_, first, last) in enumerate(periods):
            x0, x1 = layout.timeline_x(first, n_frames), layout.timeline_x(last, n_frames)
            c.rect(pad, x0, 4, max(1, x1 - x0 + 1), 40, 5 + k % 2)
        c.line(pad, layout.TIMELINE_X0, 26, layout.TIMELINE_X1, 26, 1)
        for frame, kind, _ in events:
            x = layout.timeline_x(frame, n_frames)
            y0, y1 = EVENT_ROWS[kind]
            c.line(pad, x, y0, x, y1, EVENT_VALUE[kind])
        c.text(pad, 2, 0, "strike", 2)
        c.text(pad, 44, 0, "start", 3)
        c.text(pad, 80, 0, "stop", 4)

    def mark(self, frame: int, n_frames: int) -> None:
        x = layout.TIMELINE[0] + layout.timeline_x(frame, n_frames)
        if x != self.at:
            self.client.move(self.marker_arc, x, layout.TIMELINE[1])
            self.at = x
