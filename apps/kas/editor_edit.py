"""Edit-mode commands of the keyframe editor (§3.1.1), bound to keys for ``Editor``.

Most commands act on the points between the cyan square and magenta triangle cursors in
drawing order.  The five simple transformations are remembered one per kind (§3.1.1 "each
transform remembered independently"): at a later command of the same kind Return takes the
remembered value at every prompt - origin, angle, factor, mirror line, and for a move the
same vector from wherever the first point is touched - so a composite ("enlarge, again,
rotate, again") can be replayed exactly on other points.  'Move again' repeats the most
recent transformation on whatever the cursors select now.  'Move back' inverts the
transformations in the reverse order they were actually applied (repeats included), each on
whatever the cursors select now: a stack, popped by each move back.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

import numpy as np

from camlab88.apps.kas import editor_commands as ops
from camlab88.apps.kas.editor_commands import Transform

if TYPE_CHECKING:
    from camlab88.apps.kas.editor import Editor


def bindings(ed: Editor) -> dict[str, Callable[[], None]]:
    def ask(name, steps, done, defaults=None):
        return lambda: ed._ask(name, steps, done, defaults)

    def last(kind: str) -> dict[int, object]:
        """Return's defaults at each prompt of a command of this kind: as last time."""
        t = ed.transforms.get(kind)
        if t is None:
            return {}
        if kind == "move":
            (x0, y0), (x1, y1) = t.touched
            return {0: (x0, y0), 1: lambda got: (got[0][0] + x1 - x0, got[0][1] + y1 - y0)}
        out: dict[int, object] = dict(enumerate(t.touched))
        out.update({len(t.touched) + k: v for k, v in enumerate(t.params)})
        return out

    return {
        "tab": lambda: _switch(ed),
        ",": lambda: _step(ed, -1), ".": lambda: _step(ed, 1),
        "[": lambda: _chain_step(ed, -1), "]": lambda: _chain_step(ed, 1),
        "m": ask("move points", [("point", "touch from"), ("point", "touch to")],
                 lambda g: _move(ed, g, "points"), last("move")),
        "l": ask("move line-chain", [("point", "touch from"), ("point", "touch to")],
                 lambda g: _move(ed, g, "chain"), last("move")),
        "s": ask("move section", [("point", "touch from"), ("point", "touch to")],
                 lambda g: _move(ed, g, "section"), last("move")),
        "t": ask("rotate", [("point", "touch the origin"), ("number", "angle (degrees)")],
                 lambda g: _new(ed, Transform("rotate", ops.rotation(g[1], g[0]),
                                              (g[1],), touched=(g[0],))), last("rotate")),
        "f": ask("reflect", [("point", "touch the mirror line"),
                             ("point", "touch the mirror line again")],
                 lambda g: _new(ed, Transform("reflect", ops.reflection(g[0], g[1]), (),
                                              touched=(g[0], g[1]))), last("reflect")),
        "z": ask("enlarge", [("point", "touch the origin"), ("number", "factor")],
                 lambda g: _new(ed, Transform("enlarge", ops.scaling(g[1], g[1], g[0]),
                                              (g[1],), touched=(g[0],))), last("enlarge")),
        "y": ask("stretch", [("point", "touch the origin"), ("number", "x factor"),
                             ("number", "y factor")],
                 lambda g: _new(ed, Transform("stretch", ops.scaling(g[1], g[2], g[0]),
                                              (g[1], g[2]), touched=(g[0],))),
                 last("stretch")),
        "p": ask("collapse onto point", [("point", "touch the point")],
                 lambda g: _reshape(ed, lambda p: ops.collapse_to_point(p, g[0]))),
        "j": ask("collapse onto line", [("point", "touch the line"),
                                        ("point", "touch the line again")],
                 lambda g: _reshape(ed, lambda p: ops.collapse_to_line(p, g[0], g[1]))),
        "d": lambda: _delete(ed),
        "i": lambda: _insert(ed),
        "k": lambda: _colour(ed, chain=False),
        "h": lambda: _colour(ed, chain=True),
        "x": ask("de-regularise", [("number", "maximum perturbation (inches)")],
                 lambda g: _deregularise(ed, g[0]), {0: ed.last_perturbation}
                 if ed.last_perturbation is not None else None),
        "b": lambda: _back(ed),
        "a": lambda: _again(ed),
        "g": lambda: setattr(ed, "background", not ed.background),
        "u": lambda: setattr(ed, "message", "edit mode has no undo: use move back (b)"),
    }


def _switch(ed: Editor) -> None:
    ed.active = "triangle" if ed.active == "square" else "square"


def _step(ed: Editor, d: int) -> None:
    ed.set_cursor(ed.active, ed.cursor_index(ed.active) + d)


def _chain_step(ed: Editor, d: int) -> None:
    if not ed.drawing.chains:
        return
    ci, _ = ed.square if ed.active == "square" else ed.triangle
    ci = min(max(ci + d, 0), len(ed.drawing.chains) - 1)
    if ed.active == "square":
        ed.square = (ci, 0)
    else:
        ed.triangle = (ci, 0)


def _targets(ed: Editor, scope: str) -> list[tuple[int, int, int]]:
    chains = ed.drawing.chains
    if not chains:
        return []
    if scope == "points":
        return ed.selection()
    ci = ed.square[0]
    if scope == "chain":
        return [(ci, 0, len(chains[ci]) - 1)]
    sec = chains[ci].section
    return [(j, 0, len(c) - 1) for j, c in enumerate(chains) if c.section == sec]


def _transform(ed: Editor, matrix: np.ndarray, scope: str) -> bool:
    targets = _targets(ed, scope)
    if not targets:
        ed.message = "no points to act on"
        return False
    return _rewrite(ed, targets, lambda p: ops.apply(matrix, p))


def _rewrite(ed: Editor, spans: list[tuple[int, int, int]],
             fn: Callable[[np.ndarray], np.ndarray]) -> bool:
    """Each span's points (chain, first, last) through ``fn``, written back only if every
    result stays inside the drawing area; True if written."""
    new = [(ci, lo, hi, fn(ed.drawing.chains[ci].points[lo:hi + 1])) for ci, lo, hi in spans]
    if not all(ed._inside(p) for *_, p in new):
        return False
    for ci, lo, hi, p in new:
        c = ed.drawing.chains[ci]
        pts = c.points.copy()
        pts[lo:hi + 1] = p
        c.points = pts
    ed.dirty = True
    return True


def _new(ed: Editor, t: Transform) -> None:
    if _transform(ed, t.matrix, t.scope):
        ed.transforms[t.kind] = t
        ed.last = t
        ed.applied.append(t)


def _move(ed: Editor, got: list, scope: str) -> None:
    (x0, y0), (x1, y1) = got
    _new(ed, Transform("move", ops.translation(x1 - x0, y1 - y0), (x1 - x0, y1 - y0), scope,
                       touched=((x0, y0), (x1, y1))))


def _back(ed: Editor) -> None:
    if not ed.applied:
        ed.message = "no transformation to move back" if ed.last is None else \
            "every transformation applied has been moved back"
        return
    t = ed.applied[-1]
    if _transform(ed, t.inverse(), t.scope):
        ed.applied.pop()
        ed.message = f"moved back: {t.kind}"


def _again(ed: Editor) -> None:
    t = ed.last
    if t is None:
        ed.message = "no transformation to repeat"
        return
    if _transform(ed, t.matrix, t.scope):
        ed.applied.append(t)
        ed.message = f"again: {t.kind}"


def _reshape(ed: Editor, fn: Callable[[np.ndarray], np.ndarray]) -> None:
    """A non-invertible edit of the selected points (collapse)."""
    sel = ed.selection()
    if not sel:
        ed.message = "no points to act on"
        return
    _rewrite(ed, sel, fn)


def _delete(ed: Editor) -> None:
    sel = ed.selection()
    if not sel:
        ed.message = "no points to delete"
        return
    first = min(ed.cursor_index("square"), ed.cursor_index("triangle"))
    for ci, lo, hi in reversed(sel):
        c = ed.drawing.chains[ci]
        keep = np.ones(len(c), dtype=bool)
        keep[lo:hi + 1] = False
        if not keep.any():
            del ed.drawing.chains[ci]
        else:
            c.points, c.colours = c.points[keep], c.colours[keep]
    ed.set_cursor("square", first)
    ed.set_cursor("triangle", first)
    ed.dirty = True


def _insert(ed: Editor) -> None:
    """Touches add points after the square cursor (and move it on) until space/return/i."""
    if not ed.drawing.chains:
        ed.message = "no line-chain to insert into (draw one)"
        return

    def add(got: list) -> None:
        p = got[-1]
        if not ed._inside(np.array(p)):
            return
        ci, pi = ed.square
        c = ed.drawing.chains[ci]
        c.points = np.insert(c.points, pi + 1, p, axis=0)
        c.colours = np.insert(c.colours, pi + 1, ed.pen)
        ed.square = (ci, pi + 1)
        if ed.triangle[0] == ci and ed.triangle[1] > pi:
            ed.triangle = (ci, ed.triangle[1] + 1)
        ed.dirty = True
        ed._ask("insert", [("point", "touch points to insert; space ends")], add)

    ed._ask("insert", [("point", "touch points to insert; space ends")], add)


def _colour(ed: Editor, chain: bool) -> None:
    if not ed.drawing.chains:
        return
    ci, pi = ed.square
    c = ed.drawing.chains[ci]
    cols = c.colours.copy()
    if chain:
        cols[:] = ed.pen
    elif len(c) == 1:
        cols[0] = ed.pen
    else:
        # The segment from the square cursor's point to the next (or the last segment).
        cols[min(pi + 1, len(c) - 1)] = ed.pen
        if pi == 0:
            cols[0] = ed.pen  # first segment: the chain's pen for its first point too
    c.colours = cols
    ed.dirty = True


def _deregularise(ed: Editor, magnitude: float) -> None:
    if magnitude < 0:
        raise ValueError("the perturbation must not be negative")
    ed.last_perturbation = magnitude
    sel = ed.selection()
    if not sel:
        ed.message = "no points to act on"
        return
    remap: dict[int, np.ndarray] = {}
    for ci, lo, hi in sel:
        new, index = ops.deregularise(ed.drawing.chains[ci], lo, hi, magnitude, ed.rng)
        new.uid = ed.drawing.chains[ci].uid
        ed.drawing.chains[ci] = new
        remap[ci] = index
    for which in ("square", "triangle"):
        ci, pi = getattr(ed, which)
        if ci in remap:
            setattr(ed, which, (ci, int(remap[ci][pi])))
    ed.dirty = True
