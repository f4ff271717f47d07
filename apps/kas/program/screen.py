"""The keyframe editor's screen (§3.1.1, figure 3.1) as display primitives.

Twelve-field rectangle, nine-field corners and centre cross; the menu row of coloured boxes
above the field (paint pots in their colours, commands in grey with a short label); the
list of keyboard commands on the right; prompt and status lines at the top; the drawing as
the editor's display list (normal, dim, bright, faint purple, guide); the cyan square and
magenta triangle editing cursors.  The stylus cursor is the Sigma's own graphics cursor,
attached to the pen (``CE``) and parked at the stylus after every update, so it never
touches the picture in the planes.
"""

from __future__ import annotations

import numpy as np

from camlab88.apps.kas.editor import KEYS, Editor, menu_layout
from camlab88.apps.kas.model import FIELD_H, FIELD_W, NINE_H, NINE_W, PENS
from camlab88.apps.kas.program import layout as L
from camlab88.apps.kas.program.draw import Prim, chain_prims, poly, rect, text

FIELD_CLIP = (L.FIELD_X0, L.FIELD_Y0, L.FIELD_X1, L.FIELD_Y1)
MENU_LABELS = {"undo": "UND", "undo-chain": "UCH", "undo-section": "USC", "edit": "EDT",
               "draw": "DRW", "back": "BCK", "again": "AGN", "background": "BGD",
               "enlarge": "ENL", "reverse": "REV"}
# short forms of apps.kas.editor.KEYS that fit the panel (21 characters a line)
SHORT = {
    "1..8": "paint pots", "e": "edit / draw mode", "v": "enlarge view", "o": "reverse view",
    "arrows": "pan", "escape": "cancel command", "f2": "save", "space": "break line",
    "u": "undo point", "n": "new section", "r": "rectangle", "c": "circle",
    "tab": "other cursor", ", .": "cursor -/+ point", "[ ]": "cursor -/+ chain",
    "m": "move points", "l": "move line-chain", "s": "move section", "t": "rotate",
    "f": "reflect", "z": "enlarge", "y": "stretch", "p": "collapse to pt",
    "j": "collapse to line", "d": "delete points", "i": "insert points",
    "h": "colour chain", "b": "move back", "a": "move again",
}
STYLE_COLOUR = {"old": L.OLD, "guide": L.GUIDE, "guide-next": L.GUIDE_NEXT}
PANEL_CHARS = (L.SCREEN_W - L.PANEL_X) // L.CHAR_W


def px(x: float, y: float) -> tuple[int, int]:
    a, b = L.field_to_px(x, y)
    return round(a), round(b)


def field_marks() -> list[Prim]:
    """Twelve-field rectangle, nine-field corners, centre cross (§3.1.1)."""
    hw, hh = FIELD_W / 2, FIELD_H / 2
    out = [poly(L.MARKS, [px(-hw, -hh), px(hw, -hh), px(hw, hh), px(-hw, hh), px(-hw, -hh)])]
    nw, nh, arm = NINE_W / 2, NINE_H / 2, 0.4
    for sx in (-1, 1):
        for sy in (-1, 1):
            cx, cy = sx * nw, sy * nh
            out.append(poly(L.MARKS, [px(cx - sx * arm, cy), px(cx, cy), px(cx, cy - sy * arm)]))
    out.append(poly(L.MARKS, [px(-0.25, 0), px(0.25, 0)]))
    out.append(poly(L.MARKS, [px(0, -0.25), px(0, 0.25)]))
    return out


def menu_boxes() -> list[tuple[str, tuple[int, int, int, int]]]:
    out = []
    for item, x0, y0, x1, y1 in menu_layout():
        a, b = px(x0, y0)
        c, d = px(x1, y1)
        out.append((item, (a + 1, b, c - 1, d)))
    return out


def menu_prims() -> list[Prim]:
    out = []
    for item, (x0, y0, x1, y1) in menu_boxes():
        if item.startswith("pen"):
            out.append(rect(int(item[3:]), x0, y0, x1, y1, solid=True))
        else:
            out.append(rect(L.MARKS, x0, y0, x1, y1, solid=True))
            label = MENU_LABELS[item]
            tx = (x0 + x1) // 2 - len(label) * L.CHAR_W // 2
            out.append(text(L.BG, tx, (y0 + y1) // 2 - 5, label))
    return out


def key_lines(mode: str) -> list[str]:
    """The keyboard-command list for the right of the screen: common keys, then this mode's."""
    common = ["1..8", "e", "v", "o", "arrows", "g", "escape", "f2"]
    draw = ["space", "u", "k", "x", "n", "r", "c"]
    edit = ["tab", ", .", "[ ]", "m", "l", "s", "t", "f", "z", "y", "p", "j", "d", "i", "k",
            "h", "x", "b", "a"]
    edit_text = {"k": "colour segment", "x": "de-regularise", "g": "background"}
    draw_text = {"k": "undo line-chain", "x": "undo section", "g": "guide keyframe"}
    lines = ["DRAWING MODE" if mode == "draw" else "EDIT MODE"]
    for k in (draw if mode == "draw" else edit) + common:
        desc = (draw_text if mode == "draw" else edit_text).get(k, SHORT.get(k, KEYS.get(k, "")))
        name = {"escape": "esc", "arrows": "arr", "space": "spc"}.get(k, k)
        lines.append(f"{name:<4} {desc}"[:PANEL_CHARS])
    return lines


def static_prims() -> list[Prim]:
    return field_marks() + menu_prims()


def dim_pens(ed: Editor) -> dict[int, int]:
    """Pen -> the LUT entry its unmoved chains are drawn in (§3.1.1's "dim version of the
    line's colour"): the three pens with most unmoved points get L.DIM_ENTRIES in turn; a
    fourth or later pen shares the dim entry of the nearest of those colours."""
    count: dict[int, int] = {}
    for item in ed.display_list():
        if item.style == "dim":
            for c in item.colours:
                pen = int(c) if int(c) in PENS else 1
                count[pen] = count.get(pen, 0) + 1
    order = sorted(count, key=lambda p: (-count[p], p))
    own = dict(zip(order, L.DIM_ENTRIES, strict=False))
    lut = L.lut_plan("black")
    for pen in order[len(own):]:
        near = min(own, key=lambda q: (sum(abs(a - b) for a, b in zip(lut[pen], lut[q],
                                                                        strict=True)), q))
        own[pen] = own[near]
    return own


def editor_prims(ed: Editor, dims: dict[int, int] | None = None) -> list[Prim]:
    """The whole editor screen, bottom to top; ``dims`` as from :func:`dim_pens`."""
    dims = dim_pens(ed) if dims is None else dims
    out = static_prims()
    # selected pen and mode: frames round their menu boxes
    boxes = dict(menu_boxes())
    for item in (f"pen{ed.pen}", "edit" if ed.mode == "edit" else "draw"):
        x0, y0, x1, y1 = boxes[item]
        out.append(rect(L.HILITE, x0 - 1, y0 - 2, x1 + 1, y1 + 2))
    y = L.FIELD_Y1 - 4
    for line in key_lines(ed.mode):
        out.append(text(L.TEXT, L.PANEL_X, y - L.CHAR_H, line))
        y -= L.CHAR_H + 1
    status = (f"{ed.mode.upper()}  pen {ed.pen}  section {ed.section}  "
              f"chains {len(ed.drawing.chains)}  zoom x{ed.view.zoom:g}"
              + ("  background" if ed.mode == "edit" and ed.background else ""))
    out.append(text(L.TEXT, L.FIELD_X0, L.STATUS_Y, status))
    if ed.message:
        out.append(text(L.TEXT, L.FIELD_X0, L.MESSAGE_Y, ed.message[:L.SCREEN_W // 8 - 2]))
    for item in ed.display_list():
        scr = ed.view.to_screen(item.points)
        pts = np.column_stack([L.CENTRE_X + scr[:, 0] * L.SCALE,
                               L.CENTRE_Y + scr[:, 1] * L.SCALE])
        fixed = STYLE_COLOUR.get(item.style)
        if item.style == "dim":
            colour_of = lambda c: dims.get(c if c in PENS else 1, L.DIM)  # noqa: E731
        elif fixed is not None:
            colour_of = lambda c, f=fixed: f  # noqa: E731
        else:
            colour_of = lambda c: c if c in PENS else 1  # noqa: E731
        out += chain_prims(pts, item.colours, FIELD_CLIP, colour_of)
    out += cursor_prims(ed)
    return out


def cursor_prims(ed: Editor) -> list[Prim]:
    """The cyan square and the magenta triangle; the active one gets a second outline."""
    out: list[Prim] = []
    for which, p in ed.cursors():
        if which == "stylus":
            continue
        s = ed.view.to_screen(p[None])[0]
        x, y = round(L.CENTRE_X + s[0] * L.SCALE), round(L.CENTRE_Y + s[1] * L.SCALE)
        if not (L.FIELD_X0 + 7 <= x <= L.FIELD_X1 - 7 and L.FIELD_Y0 + 7 <= y <= L.FIELD_Y1 - 7):
            continue
        sizes = (4, 6) if ed.active == which else (4,)
        for r in sizes:
            if which == "square":
                out.append(rect(L.CYAN_PEN, x - r, y - r, x + r, y + r))
            else:
                out.append(poly(L.MAGENTA_PEN, [(x - r, y - r), (x + r, y - r), (x, y + r),
                                                (x - r, y - r)]))
    return out
