"""The LUT pages of the grid pads (pure): colour, monochrome, editing and density.

Switching between them is one ``set_page`` per pad, so changing the display mode (section
7.3.2 "Alter display") or entering edit mode recolours the screen without redrawing.
"""

from __future__ import annotations

from camlab88.apps.ca.program.raster import FORMS
from camlab88.apps.ca.render import default_colour
from camlab88.apps.ca.rules import RuleSet

PAGE_COLOUR, PAGE_MONO, PAGE_EDIT, PAGE_DENSITY = 1, 2, 3, 4
GRID_WHITE = (255, 255, 255)
DEAD_GREY = (150, 150, 150)  # the "grey and white grid" of section 7.3.1


def _hex(c: tuple[int, int, int]) -> str:
    return f"#{c[0]:02x}{c[1]:02x}{c[2]:02x}"


def page(kind: str, rules: RuleSet | None, grid: bool) -> list[str]:
    """256 colours for one LUT page. ``grid``: gap pixels show as grid lines."""
    cols: list[tuple[int, int, int]] = []
    if kind == "density":
        cols = [(0, 0, 0), (0, 0, 0)]
        for i in range(254):  # dark blue through yellow to white as density rises
            f = (i + 1) / 254
            cols.append((min(255, int(510 * f)), min(255, int(400 * f)),
                         min(255, int(120 + 135 * f))))
        return [_hex(c) for c in cols]
    if kind == "mono":
        dead, gap = (0, 0, 0), ((90, 90, 90) if grid else (0, 0, 0))
    else:
        dead, gap = DEAD_GREY, (GRID_WHITE if grid else DEAD_GREY)
    forms: list[tuple[int, int, int]] = []
    for t in range(1, FORMS + 1):
        form = rules.forms.get(t) if rules is not None else None
        if form is not None and form.invisible and kind in ("colour", "mono"):
            forms.append(dead)  # section 7.4.2's invisible cells: only editing shows them
        elif kind == "mono":
            forms.append((255, 255, 255))
        elif kind == "colour" and form is not None and form.colour is not None:
            forms.append(tuple(form.colour))
        else:  # editing: the unique colour of each life-form, whatever COLOUR says
            forms.append(default_colour(t))
    if kind == "edit":  # shading pixels darker, so the style shows
        shades = [(r // 2, g // 2, b // 2) for r, g, b in forms]
    else:
        shades = forms
    cols = [gap, dead, *forms, *shades]
    cols += [dead] * (256 - len(cols))
    return [_hex(c) for c in cols]
