"""The main menu's commands as dialogues (section 7.3.2).

Each command is a generator that yields ``Ask`` requests (a point, a rubber-band rectangle,
typed text, a menu choice) and receives the answer, or ``None`` if the animator cancelled
(middle button or Escape). The program poses the questions and feeds the answers back, so
a command reads as the thesis describes it, step by step.
"""

from __future__ import annotations

import os
from collections.abc import Generator
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from camlab88.apps.ca import library
from camlab88.apps.ca.engine import SIDE, Rect
from camlab88.apps.ca.patterns import (
    ORIENTATIONS,
    Pattern,
    PatternError,
    read_pattern,
    write_pattern,
)
from camlab88.apps.ca.program.viewport import subpixel_side
from camlab88.apps.ca.rules import RuleError

if TYPE_CHECKING:
    from camlab88.apps.ca.program.program import CAProgram


@dataclass(frozen=True)
class Ask:
    kind: str  # "point", "rect", "text", "menu"
    prompt: str
    items: tuple[str, ...] = ()
    default: str = ""


Dialogue = Generator[Ask, Any, None]
ERROR = "#ff9c9c"


def _path(name: str, suffix: str) -> str:
    return name if os.path.splitext(name)[1] else name + suffix


def advance_area(p: CAProgram) -> Dialogue:
    choice = yield Ask("menu", "Advance area", ("Advance a rectangle", "Advance everywhere",
                                                 "Do nothing"))
    if choice == "Advance everywhere":
        p.session.advance_area(None)
        p.changed()
    elif choice == "Advance a rectangle":
        rect = yield Ask("rect", "Advance area: right button at two opposite corners")
        if rect is not None:
            try:
                p.session.advance_area(rect)
            except ValueError as exc:
                p.say(str(exc), ERROR)
                return
            p.changed()
            p.say(f"Rules apply only inside {rect.x0},{rect.y0} .. {rect.x1},{rect.y1}")


def alter_display(p: CAProgram) -> Dialogue:
    choice = yield Ask("menu", "Alter display", ("Colour", "Monochrome", "Display frequency",
                                                  "Grid on", "Grid off", "Do nothing"))
    if choice in ("Colour", "Monochrome"):
        p.display.mode = "mono" if choice == "Monochrome" else "colour"
        p.display.apply_page()
    elif choice in ("Grid on", "Grid off"):
        p.view.grid = choice == "Grid on"
        p.display.load_luts()
        if p.view.zoom not in (16, 8):
            p.say("The grid is shown at zoom 16 and zoom 8")
    elif choice == "Display frequency":
        text = yield Ask("text", "Show every Nth generation, N =", default=str(p.frequency))
        if text is not None:
            try:
                n = int(text)
                if not 1 <= n <= 10000:
                    raise ValueError
            except ValueError:
                p.say(f"Display frequency must be a whole number 1..10000, not {text!r}",
                      ERROR)
                return
            p.frequency = n
            p.fast_forward = False
            p.pending = None
            p.say(f"Display every {n} generation{'s' if n > 1 else ''}")


def change_rules(p: CAProgram) -> Dialogue:
    name = yield Ask("text", "Rule file (path or library name):")
    if not name:
        return
    try:
        path = library.rules_path(name)
        with open(path, encoding="utf-8") as f:
            text = f.read()
        rules = p.session.change_rules(text, os.path.basename(path))
    except (OSError, RuleError) as exc:
        p.say(f"{exc}\nThe old rules are still in force.", ERROR)
        return
    p.display.set_rules(rules)
    p.changed()
    p.say(f"New rules from {path}")


def clear_area(p: CAProgram) -> Dialogue:
    choice = yield Ask("menu", "Clear the entire grid?", ("Clear the entire grid",
                                                          "Clear a rectangle", "Do nothing"))
    if choice == "Clear the entire grid":
        p.session.clear(None)
        p.changed()
    elif choice == "Clear a rectangle":
        rect = yield Ask("rect", "Clear: right button at two opposite corners")
        if rect is not None:
            p.session.clear(rect)
            p.changed()


def save_pattern(p: CAProgram) -> Dialogue:
    rect = yield Ask("rect", "Save pattern: right button at two opposite corners")
    if rect is None:
        return
    name = yield Ask("text", "Save as file:")
    if not name:
        return
    ref = yield Ask("point", "Right button on the reference point")
    if ref is None:
        return
    xs, ys, ts = p.session.engine.cells_in_rect(rect)
    # offsets from the corner round the wrapping plane (the rectangle may cross the seam)
    cells = [((int(x) - rect.x0) % SIDE, (int(y) - rect.y0) % SIDE, int(t))
             for x, y, t in zip(xs, ys, ts)]
    if not cells:
        p.say("Nothing to save: the rectangle has no living cells", ERROR)
        return
    pat = Pattern.from_cells(cells, ref=(_offset(ref[0], rect.x0), _offset(ref[1], rect.y0)),
                             name=os.path.basename(name))
    path = _path(name, ".pat")
    try:
        write_pattern(path, pat)
    except (OSError, PatternError, ValueError) as exc:
        p.say(f"Cannot save {path}: {exc}", ERROR)
        return
    p.say(f"Saved {len(cells)} cells to {path}")


def load_pattern(p: CAProgram) -> Dialogue:
    name = yield Ask("text", "Load pattern (path or library name):")
    if not name:
        return
    try:
        pat = read_pattern(library.pattern_path(name))
    except (OSError, PatternError, ValueError) as exc:
        p.say(str(exc), ERROR)
        return
    orientation = None
    while True:  # several copies; the same point again erases; middle button/Escape ends
        point = yield Ask("point", f"{name}: right button where the reference point goes "
                          "(again to erase; middle button ends)")
        if point is None:
            return
        erase = (name, point[0], point[1]) in p.session._loaded
        if orientation is None and not erase:
            orientation = yield Ask("menu", "Orientation", (*ORIENTATIONS, "Do nothing"))
            if orientation is None or orientation == "Do nothing":
                return
        p.session.load_pattern(name, pat, point[0], point[1], orientation or "identity")
        p.changed()


def randomly_populate(p: CAProgram) -> Dialogue:
    rect = yield Ask("rect", "Randomly populate: right button at two opposite corners")
    if rect is None:
        return
    text = yield Ask("text", "Overall density (0..1 or a percentage):", default="0.3")
    if text is None:
        return
    try:
        density = float(text[:-1]) / 100 if text.endswith("%") else float(text)
        if not 0 <= density <= 1:
            raise ValueError
    except ValueError:
        p.say(f"Density must be between 0 and 1 (or 0% and 100%), not {text!r}", ERROR)
        return
    forms = p.session.forms_with_rules() or [1]
    text = yield Ask("text", "Relative densities (life-form:weight ...):",
                     default=" ".join(f"{f}:1" for f in forms))
    if text is None:
        return
    try:
        weights = {int(k): float(v) for k, v in (w.split(":") for w in text.split())}
        if not weights or min(weights.values()) < 0 or min(weights) < 1:
            raise ValueError
    except ValueError:
        p.say(f"Relative densities are life-form:weight pairs, e.g. 1:2 3:1, not {text!r}",
              ERROR)
        return
    p.populations += 1  # a fresh, logged seed each time: replays are exact
    seed = (p.session.engine.seed * 1_000_003 + p.session.generation * 7919
            + p.populations) & 0x7FFFFFFF
    try:
        p.session.populate(rect, density, weights, seed)
    except ValueError as exc:
        p.say(str(exc), ERROR)
        return
    p.changed()


def statistics(p: CAProgram) -> Dialogue:
    s = p.session.statistics()
    lines = [f"Generation   {s['generation']}", f"Population   {s['population']}"]
    kinds = list(s["by_type"].items())
    for k, v in kinds[:8]:
        lines.append(f"  life-form {k}: {v}")
    if len(kinds) > 8:
        lines.append(f"  ... {len(kinds) - 8} more life-forms")
    vx, vy = p.view.top_left_cell()
    w, h = p.view.cells_across()
    lines.append(f"Viewport     {vx},{vy} ({w}x{h} cells, zoom {p.view.name})")
    box = s["bbox"]
    lines.append("Population box  none" if box is None else
                 f"Population box  {box[0]},{box[1]} .. {box[2]},{box[3]}")
    p.show_statistics("\n".join(lines))
    return
    yield  # a generator with no questions


def zoom_subpixel(p: CAProgram) -> Dialogue:
    text = yield Ask("text", "Cells per pixel (4, 16, 64, 256 or 1024; any square up to 1024):",
                     default="64")
    if text is None:
        return
    try:
        n = int(text)
        subpixel_side(n)
    except ValueError as exc:
        p.say(str(exc) if "square" in str(exc) else f"not a number: {text!r}", ERROR)
        return
    p.set_zoom(0, n)


def set_value(p: CAProgram) -> Dialogue:
    forms = p.session.forms_with_rules() or [1]
    if len(forms) <= 28:
        choice = yield Ask("menu", "Value", (*(f"Life-form {f}" for f in forms), "Do nothing"))
        if choice is None or choice == "Do nothing":
            return
        value = int(choice.split()[-1])
    else:
        text = yield Ask("text", f"Life-form to set ({forms[0]}..{forms[-1]}):")
        if text is None:  # cancelled: the editing method stays as it was
            return
        try:
            value = int(text)
        except ValueError:
            p.say(f"not a life-form number: {text!r}", ERROR)
            return
        if value not in forms:  # the menu offers only life-forms with rules; so does this
            p.say(f"life-form {value} has no rules in the current rule set "
                  f"(forms {forms[0]}..{forms[-1]}, {len(forms)} of them)", ERROR)
            return
    p.session.set_edit_mode("set_value", value)
    p.display.set_marker(value)


def start_generation(p: CAProgram, last: int) -> Dialogue:
    text = yield Ask("text", f"Script: begin at which generation (0..{last})?", default=str(last))
    try:
        target = int(text if text is not None else last)
        if target < 0:
            raise ValueError
    except ValueError:
        p.say(f"not a generation number: {text!r}; beginning at {last}", ERROR)
        target = last
    p.begin_script(target)


MAIN = {"Advance area": advance_area, "Alter display": alter_display,
        "Change rules": change_rules, "Clear area": clear_area, "Save pattern": save_pattern,
        "Load pattern": load_pattern, "Randomly populate": randomly_populate,
        "Statistics": statistics, "Zoom subpixel": zoom_subpixel}


def rect_from(a: tuple[int, int], b: tuple[int, int]) -> Rect:
    """The rectangle dragged between corners a and b (it may cross the plane's seam)."""
    return Rect.dragged(a[0], a[1], b[0], b[1])


def _offset(v: int, origin: int) -> int:
    """Signed distance from ``origin`` to ``v`` the short way round the plane."""
    return (v - origin + SIDE // 2) % SIDE - SIDE // 2
