"""The ``ca`` program's model of a session (sections 7.3.1, 7.3.2), free of any device.

It ties the engine to the animator's interventions and to the Log / Checkpoint files: the
four editing methods, loading and erasing patterns, clearing, random population, advance
areas, changing rules (a bad file leaves the old rules running), stepping with checkpoints,
and the viewport/zoom record.  The Rainbow program drives it from menus and the mouse.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from camlab88.apps.ca import log
from camlab88.apps.ca.engine import CENTRE, Engine, Rect
from camlab88.apps.ca.patterns import Pattern
from camlab88.apps.ca.rules import RuleSet, parse_rules

EDIT_MODES = ("step_up", "step_down", "set_value", "pick_up")
ZOOMS = ("16", "8", "4", "2", "1", "subpixel")
MAX_CELLS_PER_PIXEL = 1024


def subpixel_side(cells_per_pixel: int) -> int:
    """The subpixel zoom's cells per pixel is an area (section 7.3.2: "1024 cells per pixel"),
    so it is a square number 4, 9, 16 ... 1024; returns the side (2..32). On the 65536-cell
    plane the 752 x 576 view then shows 752*32 x 576*32 cells = 10.3 % of it (the thesis's
    "approximately 40 %" and zoom 1's "0.04 %" fit a 32768-cell-square surface)."""
    side = math.isqrt(cells_per_pixel) if cells_per_pixel >= 0 else 0
    if not 2 <= side <= 32 or side * side != cells_per_pixel:
        raise ValueError(f"cells per pixel must be a square number from 4 to "
                         f"{MAX_CELLS_PER_PIXEL} (4, 9, 16, ... 1024), not {cells_per_pixel}")
    return side


@dataclass
class Viewport:
    x: int = CENTRE  # cell at the top-left of the view
    y: int = CENTRE
    zoom: str = "16"
    cells_per_pixel: int = 1  # for the subpixel zoom


@dataclass
class Session:
    engine: Engine
    writer: log.LogWriter | None = None
    checkpoint_every: int = 0
    edit_mode: str = "step_up"
    current: int = 1  # the set-value / picked-up colour
    view: Viewport = field(default_factory=Viewport)
    _loaded: dict[tuple[str, int, int], str] = field(default_factory=dict)

    # -- logging --------------------------------------------------------------------
    def _log(self, ev: log.Event) -> None:
        if self.writer is not None:
            self.writer.add(ev)

    @property
    def generation(self) -> int:
        return self.engine.generation

    # -- rules ------------------------------------------------------------------------
    def change_rules(self, text: str, name: str = "rules") -> RuleSet:
        """Parse and install new rules; on a RuleError the old rules keep running."""
        rules = parse_rules(text, source=name)
        self.engine.set_rules(rules)
        self._log(log.ev_rules(self.generation, name, text))
        return rules

    def forms_with_rules(self) -> list[int]:
        rules = self.engine.rules
        return sorted(rules.forms) if rules is not None else []

    # -- editing (section 7.3.1) -------------------------------------------------------
    def set_edit_mode(self, mode: str, value: int | None = None) -> None:
        if mode not in EDIT_MODES:
            raise ValueError(f"edit mode must be one of {EDIT_MODES}")
        self.edit_mode = mode
        if value is not None:
            self.current = value

    def click(self, x: int, y: int) -> int:
        """The right button over cell (x, y) in the current editing method; returns the
        cell's new value (the value to paint while dragging)."""
        old = self.engine.get(x, y)
        forms = self.forms_with_rules() or [1]
        cycle = [0, *forms]  # only life-forms with rules, wrapping round to dead
        if self.edit_mode in ("step_up", "step_down"):
            i = cycle.index(old) if old in cycle else 0
            step = 1 if self.edit_mode == "step_up" else -1
            new = cycle[(i + step) % len(cycle)]
        elif self.edit_mode == "set_value":
            new = 0 if old == self.current else self.current
        else:  # pick up colour
            if old != 0 and old != self.current:
                self.current = old
                return old  # the cell is unaltered
            new = 0 if old == self.current else self.current
        self.paint(x, y, new)
        return new

    def paint(self, x: int, y: int, value: int) -> None:
        """Set one cell (dragging with the right button sets each cell passed over)."""
        if self.engine.get(x, y) != value:
            self.engine.set(x, y, value)
            self._log(log.ev_edit(self.generation, x, y, value))

    # -- patterns, areas -------------------------------------------------------------------
    def load_pattern(self, name: str, pattern: Pattern, x: int, y: int,
                     orientation: str = "identity") -> bool:
        """Place a pattern's reference point on (x, y); the same point again erases it.
        Returns True if loaded, False if erased."""
        key = (name, x, y)
        erase = key in self._loaded
        if erase:
            orientation = self._loaded[key]  # erase the copy placed there, as placed
        xs, ys, ts = pattern.placed(x, y, orientation)
        self.engine.set_cells(xs, ys, 0 if erase else ts)
        if erase:
            del self._loaded[key]
        else:
            self._loaded[key] = orientation
        self._log(log.ev_load(self.generation, name, x, y, orientation, pattern, erase=erase))
        return not erase

    def clear(self, rect: Rect | None = None) -> None:
        self.engine.clear(rect)
        self._log(log.ev_clear(self.generation, rect))

    def populate(self, rect: Rect, density: float, weights: dict[int, float],
                 seed: int) -> None:
        log.populate(self.engine, rect, density, weights, seed)
        self._log(log.ev_populate(self.generation, rect, density, weights, seed))

    def advance_area(self, rect: Rect | None) -> None:
        self.engine.set_advance_area(rect)
        self._log(log.ev_advance(self.generation, rect))

    # -- time ------------------------------------------------------------------------------
    def step(self) -> None:
        self.engine.step()
        if (self.writer is not None and self.checkpoint_every
                and self.generation % self.checkpoint_every == 0):
            log.write_checkpoint(self.writer.path, self.engine)

    # -- viewing ----------------------------------------------------------------------------
    def pan_to(self, x: int, y: int) -> None:
        self.view.x, self.view.y = x % 65536, y % 65536
        self._log(log.ev_view(self.generation, self.view.x, self.view.y))

    def set_zoom(self, zoom: str, cells_per_pixel: int = 1) -> None:
        if zoom not in ZOOMS:
            raise ValueError(f"zoom must be one of {ZOOMS}")
        if zoom == "subpixel":
            subpixel_side(cells_per_pixel)  # the same square areas the program accepts
        self.view.zoom = zoom
        self.view.cells_per_pixel = cells_per_pixel if zoom == "subpixel" else 1
        self._log(log.ev_zoom(self.generation, zoom if zoom != "subpixel"
                              else f"subpixel:{cells_per_pixel}"))

    def apply_view_event(self, ev: log.Event) -> None:
        """ReplayPansAndZooms: repeat a recorded viewing event."""
        if ev.kind == "view":
            self.view.x, self.view.y = int(ev.args[0]), int(ev.args[1])
        elif ev.kind == "zoom":
            zoom, _, cpp = str(ev.args[0]).partition(":")
            self.view.zoom = zoom
            self.view.cells_per_pixel = int(cpp) if cpp else 1

    def centralise(self, width_cells: int, height_cells: int) -> None:
        """Move the viewport to the centre of the population (its bounding box)."""
        box = self.engine.bbox()
        if box is None:
            return
        cx = box.x0 + (box.width - 1) // 2  # the box may cross the seam: pan_to wraps
        cy = box.y0 + (box.height - 1) // 2
        self.pan_to(cx - width_cells // 2, cy - height_cells // 2)

    def statistics(self) -> dict:
        stats = self.engine.stats()
        stats["viewport"] = [self.view.x, self.view.y, self.view.zoom]
        return stats
