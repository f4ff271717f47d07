"""The keyframe editor's model (§3.1.1, and the §2.3 "draw over the previous keyframe").

A state machine fed by abstract events (``camlab88.apps.kas.events``): a device front
(Sigma screen +
tablet) or a test script drives it; it owns the drawing, the modes, the editing cursors, the
remembered transformations and the view, and says what should be displayed
(``display_list``).  No device code here.  Key bindings are in ``KEYS`` and docs/kas.md.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from camlab88.apps.kas import editor_commands as ops
from camlab88.apps.kas.events import Event, Key, MenuPick, Pointer
from camlab88.apps.kas.model import FIELD_H, FIELD_W, PENS, WORK_X, WORK_Y, Chain, Drawing

# Menu row above the twelve-field (§3.1.1: "a row of coloured boxes above the drawing area").
MENU_ITEMS: tuple[str, ...] = (
    *(f"pen{p}" for p in PENS), "undo", "undo-chain", "undo-section", "edit", "draw",
    "back", "again", "background", "enlarge", "reverse",
)
MENU_Y0 = FIELD_H / 2 + 0.15
MENU_Y1 = FIELD_H / 2 + 0.75
FREEHAND_STEP = 0.03  # inches on the screen between freehand points (tablet jitter filter)

KEYS: dict[str, str] = {
    # both modes
    "1..8": "pen colour (paint pots)", "e": "edit mode / drawing mode", "v": "enlarge view at "
    "stylus", "o": "reverse enlargement", "arrows": "pan the working area", "g": "background "
    "(edit) / previous keyframe guide (draw)", "escape": "cancel command", "f2": "save",
    # drawing mode
    "space": "break the line-chain", "u": "undo point", "k": "undo line-chain (draw) / colour "
    "segment (edit)", "x": "undo section (draw) / de-regularise (edit)", "n": "new section",
    "r": "rectangle", "c": "circle",
    # edit mode
    "tab": "switch editing cursor", ", .": "cursor back / on one point", "[ ]": "cursor to "
    "previous / next chain", "m": "move points", "l": "move line-chain", "s": "move section",
    "t": "rotate", "f": "reflect", "p": "collapse onto point", "j": "collapse onto line",
    "d": "delete points", "i": "insert points", "z": "enlarge", "y": "stretch",
    "h": "colour line-chain", "b": "move back", "a": "move again",
}


def menu_layout() -> list[tuple[str, float, float, float, float]]:
    """(item, x0, y0, x1, y1) boxes of the menu row, in screen field inches."""
    w = FIELD_W / len(MENU_ITEMS)
    x0 = -FIELD_W / 2
    return [(it, x0 + i * w, MENU_Y0, x0 + (i + 1) * w, MENU_Y1)
            for i, it in enumerate(MENU_ITEMS)]


def menu_hit(x: float, y: float) -> str | None:
    for item, x0, y0, x1, y1 in menu_layout():
        if x0 <= x < x1 and y0 <= y <= y1:
            return item
    return None


@dataclass
class View:
    """Which part of the working area the screen's twelve-field shows."""

    cx: float = 0.0
    cy: float = 0.0
    zoom: float = 1.0

    def to_world(self, x: float, y: float) -> tuple[float, float]:
        return self.cx + x / self.zoom, self.cy + y / self.zoom

    def to_screen(self, pts: np.ndarray) -> np.ndarray:
        return (np.asarray(pts, dtype=np.float64) - (self.cx, self.cy)) * self.zoom


@dataclass
class DisplayItem:
    """A polyline to show: world inches, per-point colours, and how to show it:
    normal | dim (unmoved, background on) | bright (moved) | old (faint purple former
    position) | guide (previous keyframe) | guide-next (its chain to draw next)."""

    points: np.ndarray
    colours: np.ndarray
    style: str


@dataclass
class _Pending:
    name: str
    steps: list[tuple[str, str]]          # ("point" | "number", prompt)
    done: Callable[[list], None]
    # Return at a prompt takes these: numbers, points, or f(got so far) -> point
    defaults: dict[int, object] = field(default_factory=dict)
    got: list = field(default_factory=list)
    text: str = ""


class Editor:
    def __init__(self, drawing: Drawing | None = None, guide: Drawing | None = None,
                 seed: int = 0) -> None:
        self.drawing = drawing if drawing is not None else Drawing()
        self.mode = "draw"
        self.pen = 1
        self.section = max(self.drawing.sections(), default=-1) + 1
        self.open_chain = False
        self.stylus = (0.0, 0.0)
        self.stylus_down = False
        self._drag_in_menu = False
        self.view = View()
        self._views: list[View] = []
        self.pending: _Pending | None = None
        self.square = (0, 0)      # (chain, point): the cyan square cursor
        self.triangle = (0, 0)    # the magenta triangle cursor
        self.active = "square"
        self.original: Drawing | None = None
        self.background = False
        self.guide = guide
        self.show_guide = guide is not None
        self.transforms: dict[str, ops.Transform] = {}  # the last of each kind
        self.last: ops.Transform | None = None           # what 'move again' repeats
        self.applied: list[ops.Transform] = []           # what 'move back' unwinds
        self.rng = np.random.default_rng(seed)  # de-regularise: repeatable for a seed
        self.last_perturbation: float | None = None
        self.message = ""
        self.dirty = False
        self.quit_warned = False
        self.on_save: Callable[[Drawing], None] | None = None

    # ------------------------------------------------------------------ events
    def feed(self, event: Event) -> None:
        self.quit_warned = False  # "close again" means again straight away
        if isinstance(event, Pointer):
            self._pointer(event)
        elif isinstance(event, Key):
            self._key(event.key)
        elif isinstance(event, MenuPick):
            self.menu(event.item)
        else:
            raise TypeError(f"not an editor event: {event!r}")

    def run(self, events: list[Event]) -> None:
        for ev in events:
            self.feed(ev)

    def _pointer(self, ev: Pointer) -> None:
        touch = ev.down and not self.stylus_down
        drag = ev.down and self.stylus_down
        self.stylus_down = ev.down
        world = self.view.to_world(ev.x, ev.y)
        self.stylus = world
        if touch and ev.y >= MENU_Y0:
            self._drag_in_menu = True
            item = menu_hit(ev.x, ev.y)
            if item:
                self.menu(item)
            return
        if not ev.down:
            self._drag_in_menu = False
        if self._drag_in_menu:
            return
        if self.pending is not None:
            if touch:
                self._pending_point(world)
            return
        if self.mode == "draw":
            if touch:
                self._add_point(world)
            elif drag:
                last = self.drawing.chains[-1].points[-1] if self.open_chain else None
                if last is not None and math.dist(last, world) * self.view.zoom >= FREEHAND_STEP:
                    self._add_point(world)
        elif touch:
            self._snap_cursor(world)

    def menu(self, item: str) -> None:
        if item not in MENU_ITEMS:
            self.message = f"no menu item {item!r}"
            return
        if item.startswith("pen"):
            self._key(item[3:])
        elif item == "edit":
            if self.mode == "draw":
                self.enter_edit()
        elif item == "draw":
            self._leave_edit()
        elif item in ("undo-chain", "undo-section"):
            if self.mode != "draw":
                self.message = "undo works in drawing mode; use move back"
            elif item == "undo-chain":
                self.undo_chain()
            else:
                self.undo_section()
        else:
            self._key({"undo": "u", "back": "b", "again": "a", "background": "g",
                       "enlarge": "v", "reverse": "o"}[item])

    def save(self) -> bool:
        """F2: save through ``on_save``.  A failed save (disk full, no permission, ...) is
        shown on the message line and the drawing stays in the editor, still unsaved."""
        if self.on_save is None:
            self.message = "no file to save to"
            return False
        try:
            self.on_save(self.drawing)
        except OSError as exc:
            self.message = f"NOT saved: {exc.strerror or exc}"
            self.quit_warned = False
            return False
        self.dirty = False
        return True

    def request_quit(self) -> bool:
        """May the editor close now?  With unsaved edits the first request only warns
        (message line); a second one in a row discards them."""
        if not self.dirty or self.quit_warned:
            return True
        self.quit_warned = True
        self.message = "unsaved edits: F2 saves; close again to discard them"
        return False

    def _key(self, key: str) -> None:
        if self.pending is not None and self._pending_key(key):
            return
        k = key.lower()
        if k == "f2":
            self.save()
            return
        if k in ("1", "2", "3", "4", "5", "6", "7", "8"):
            self.pen = int(k)
            return
        if k == "escape":
            self.pending = None
            self.message = ""
            return
        view_keys = {"v": self.enlarge_view, "o": self.reverse_view}
        if k in view_keys:
            view_keys[k]()
            return
        if k in ("up", "down", "left", "right"):
            step = FIELD_W / 4 / self.view.zoom
            dx, dy = {"up": (0, 1), "down": (0, -1), "left": (-1, 0), "right": (1, 0)}[k]
            self.view = View(self.view.cx + dx * step, self.view.cy + dy * step, self.view.zoom)
            return
        if k == "e":
            if self.mode == "draw":
                self.enter_edit()
            else:
                self._leave_edit()
            return
        table = self._draw_keys() if self.mode == "draw" else self._edit_keys()
        action = table.get(k)
        if action is None:
            self.message = f"no command {key!r} in {self.mode} mode"
            return
        self.message = ""
        action()

    # ------------------------------------------------------------------ drawing mode
    def _draw_keys(self) -> dict[str, Callable[[], None]]:
        return {
            "space": self.break_chain, " ": self.break_chain, "u": self.undo_point,
            "k": self.undo_chain, "x": self.undo_section, "n": self.new_section,
            "r": lambda: self._ask("rectangle", [("point", "touch one corner"),
                                                  ("point", "touch the opposite corner")],
                                   self._rectangle),
            "c": lambda: self._ask("circle", [("point", "touch the centre"),
                                               ("point", "touch the rim")], self._circle),
            "g": self._toggle_guide,
        }

    def _inside(self, pts: np.ndarray) -> bool:
        pts = np.asarray(pts).reshape(-1, 2)
        ok = bool(np.all(np.abs(pts[:, 0]) <= WORK_X) and np.all(np.abs(pts[:, 1]) <= WORK_Y))
        if not ok:
            self.message = "outside the working area"
        return ok

    def _add_point(self, p: tuple[float, float]) -> None:
        if not self._inside(np.array(p)):
            return
        if self.open_chain and self.drawing.chains:
            c = self.drawing.chains[-1]
            c.points = np.vstack([c.points, p])
            c.colours = np.append(c.colours, np.int16(self.pen))
        else:
            self.drawing.chains.append(Chain.from_points([p], self.pen, self.section))
            self.open_chain = True
        self.dirty = True

    def _add_chain(self, pts: np.ndarray) -> None:
        if self._inside(pts):
            self.drawing.chains.append(Chain.from_points(pts, self.pen, self.section))
            self.open_chain = False
            self.dirty = True

    def _rectangle(self, got: list) -> None:
        self._add_chain(ops.rectangle(got[0], got[1]))

    def _circle(self, got: list) -> None:
        self._add_chain(ops.circle(got[0], got[1]))

    def break_chain(self) -> None:
        self.open_chain = False

    def new_section(self) -> None:
        self.section = max([self.section, *self.drawing.sections()]) + 1
        self.open_chain = False

    def undo_point(self) -> None:
        if not self.drawing.chains:
            self.message = "nothing to undo"
            return
        c = self.drawing.chains[-1]
        c.points, c.colours = c.points[:-1], c.colours[:-1]
        if len(c) == 0:
            self.drawing.chains.pop()
            self.open_chain = False
        else:
            self.open_chain = True  # carry on drawing the chain the point came from
        self.dirty = True

    def undo_chain(self) -> None:
        if not self.drawing.chains:
            self.message = "nothing to undo"
            return
        self.drawing.chains.pop()
        self.open_chain = False
        self.dirty = True

    def undo_section(self) -> None:
        if not self.drawing.chains:
            self.message = "nothing to undo"
            return
        last = self.drawing.chains[-1].section
        while self.drawing.chains and self.drawing.chains[-1].section == last:
            self.drawing.chains.pop()
        self.open_chain = False
        self.dirty = True

    def _toggle_guide(self) -> None:
        if self.guide is None:
            self.message = "no previous keyframe to draw over"
        else:
            self.show_guide = not self.show_guide

    def next_guide_chain(self) -> int | None:
        """Index of the previous keyframe's chain that corresponds to the one being drawn
        (or about to be drawn) - highlighted so the drawing order matches (§2.3)."""
        if self.guide is None:
            return None
        n = len(self.drawing.chains) - (1 if self.open_chain else 0)
        return n if n < len(self.guide.chains) else None

    # ------------------------------------------------------------------ view
    def enlarge_view(self) -> None:
        self._views.append(self.view)
        self.view = View(self.stylus[0], self.stylus[1], self.view.zoom * 2)

    def reverse_view(self) -> None:
        if self._views:
            self.view = self._views.pop()
        else:
            self.message = "the view is not enlarged"

    # ------------------------------------------------------------------ prompts
    def _ask(self, name: str, steps: list[tuple[str, str]], done: Callable[[list], None],
             defaults: dict[int, object] | None = None) -> None:
        self.pending = _Pending(name, steps, done, defaults or {})
        self._prompt()

    def _prompt(self) -> None:
        p = self.pending
        if p is None:
            return
        kind, text = p.steps[len(p.got)]
        if kind == "number":
            d = p.defaults.get(len(p.got))
            text += f" [{d:g}]" if d is not None else ""
            text += f": {p.text}"
        elif len(p.got) in p.defaults:
            text += " (Return: as last time)"
        self.message = f"{p.name}: {text}"

    def _pending_point(self, world: tuple[float, float]) -> None:
        p = self.pending
        assert p is not None
        if p.steps[len(p.got)][0] != "point":
            self.message = f"{p.name}: type a number"
            return
        p.got.append(world)
        self._advance()

    def _pending_key(self, key: str) -> bool:
        """Keys while a command waits for input; True if consumed."""
        p = self.pending
        assert p is not None
        if p.name == "insert" and key in ("space", " ", "i", "return"):
            self.pending = None
            self.message = ""
            return True
        if p.steps[len(p.got)][0] != "number":
            if key != "return":
                return False
            if len(p.got) not in p.defaults:
                self.message = f"{p.name}: touch a point (nothing remembered yet)"
                return True
            d = p.defaults[len(p.got)]
            p.got.append(tuple(d(p.got) if callable(d) else d))
            self._advance()
            return True
        if key in "0123456789.-" and len(key) == 1:
            p.text += key
        elif key == "backspace":
            p.text = p.text[:-1]
        elif key == "return":
            if p.text == "" and len(p.got) in p.defaults:
                p.got.append(p.defaults[len(p.got)])
            else:
                try:
                    value = float(p.text)
                    if not math.isfinite(value):
                        raise ValueError
                except ValueError:
                    self.message = f"{p.name}: {p.text!r} is not a number"
                    p.text = ""
                    return True
                p.got.append(value)
            p.text = ""
            self._advance()
            return True
        else:
            return key != "escape"
        self._prompt()
        return True

    def _advance(self) -> None:
        p = self.pending
        assert p is not None
        if len(p.got) < len(p.steps):
            self._prompt()
            return
        self.pending = None
        self.message = ""
        try:
            p.done(p.got)
        except ValueError as exc:
            self.message = f"{p.name}: {exc}"

    # ------------------------------------------------------------------ edit mode
    def enter_edit(self) -> None:
        self.mode = "edit"
        self.open_chain = False
        self.original = self.drawing.copy()
        self.square = (0, 0)
        last = len(self.drawing.chains) - 1
        self.triangle = (last, len(self.drawing.chains[last]) - 1) if last >= 0 else (0, 0)
        self.active = "square"

    def _leave_edit(self) -> None:
        self.mode = "draw"
        self.pending = None

    def _edit_keys(self) -> dict[str, Callable[[], None]]:
        from camlab88.apps.kas import editor_edit as ed

        return ed.bindings(self)

    def _flat(self) -> np.ndarray:
        return np.concatenate([[0], np.cumsum([len(c) for c in self.drawing.chains])])

    def cursor_index(self, which: str) -> int:
        ci, pi = self.square if which == "square" else self.triangle
        return int(self._flat()[ci]) + pi if self.drawing.chains else 0

    def set_cursor(self, which: str, g: int) -> None:
        flat = self._flat()
        total = int(flat[-1])
        if total == 0:
            pos = (0, 0)
        else:
            g = min(max(g, 0), total - 1)
            ci = int(np.searchsorted(flat, g, side="right") - 1)
            pos = (ci, g - int(flat[ci]))
        if which == "square":
            self.square = pos
        else:
            self.triangle = pos

    def cursor_point(self, which: str) -> np.ndarray | None:
        if not self.drawing.chains:
            return None
        ci, pi = self.square if which == "square" else self.triangle
        return self.drawing.chains[ci].points[pi]

    def selection(self) -> list[tuple[int, int, int]]:
        """(chain, first, last) point ranges between the cursors, in drawing order."""
        if not self.drawing.chains:
            return []
        a, b = sorted((self.cursor_index("square"), self.cursor_index("triangle")))
        flat = self._flat()
        out = []
        for ci in range(len(self.drawing.chains)):
            lo = max(a, int(flat[ci]))
            hi = min(b, int(flat[ci + 1]) - 1)
            if lo <= hi:
                out.append((ci, lo - int(flat[ci]), hi - int(flat[ci])))
        return out

    def _snap_cursor(self, world: tuple[float, float]) -> None:
        pts = self.drawing.all_points()
        if len(pts) == 0:
            return
        g = int(np.argmin(np.hypot(*(pts - world).T)))
        self.set_cursor(self.active, g)

    # ------------------------------------------------------------------ display
    def cursors(self) -> list[tuple[str, np.ndarray]]:
        """World positions of the stylus cursor and, in edit mode, the cyan square and the
        magenta triangle (which is active is ``self.active``)."""
        out = [("stylus", np.array(self.stylus))]
        if self.mode == "edit" and self.drawing.chains:
            for which in ("square", "triangle"):
                p = self.cursor_point(which)
                if p is not None:
                    out.append((which, p.copy()))
        return out

    def display_list(self) -> list[DisplayItem]:
        items: list[DisplayItem] = []
        if self.mode == "draw" and self.guide is not None and self.show_guide:
            nxt = self.next_guide_chain()
            for j, c in enumerate(self.guide.chains):
                items.append(DisplayItem(c.points, c.colours,
                                         "guide-next" if j == nxt else "guide"))
        if self.mode == "edit" and self.background and self.original is not None:
            now = {c.uid: c for c in self.drawing.chains}
            moved = set()
            for c in self.original.chains:
                cur = now.get(c.uid)
                if cur is None or not (cur.same_shape(c)):
                    items.append(DisplayItem(c.points, c.colours, "old"))
                    moved.add(c.uid)
            for c in self.drawing.chains:
                unmoved = c.uid not in moved and any(o.uid == c.uid for o in self.original.chains)
                items.append(DisplayItem(c.points, c.colours, "dim" if unmoved else "bright"))
        else:
            items.extend(DisplayItem(c.points, c.colours, "normal") for c in self.drawing.chains)
        return items
