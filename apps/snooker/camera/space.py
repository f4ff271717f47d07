"""The table frame, in which the pictures are made and view files are written: metres from
the centre of the playing surface, +x towards the top cushion, +y towards the left cushion
as seen from the baulk end, +z up (right-handed); z = 0 on the cloth, a ball's centre at
z = its radius.  Spots lie on the cloth; a corner pocket is the corner of the playing
surface where its two cushion faces meet, a centre pocket the middle of its long side (both
z = 0).

The camera control language's own default space (thesis §6.3.1, "measured in metres from
the centre of the table") has the same origin, y and z but +x towards the BAULK cushion:
the thesis's example decides it.  Its last command puts the observer at the pink ball +
(0.1, -0.1, 0.05), "a few centimetres behind the pink ball looking towards the pocket" as
the pink runs to the top left pocket, and its second moves "in the y direction (parallel to
the short side of the table)".  Of the four ways to lay x along the long side and y along
the short, only top cushion at -x, left cushion at +y puts that offset behind a ball running
to the top left pocket.  With z up that frame is left-handed (as several viewing systems of
the period were), so CCL coordinates are mirrored into the table frame (x -> -x) where they
are read (``ccl_to_table``); pictures are made in the right-handed table frame and so are
never mirrored.  Names (balls, spots, pockets) mean the same point in either frame.

The motion program's own coordinates (table.py, checkpoint.py) have the same axes but their
origin at the baulk cushion face on the right-hand cushion (y = 0), so converting is a shift
by half the table's length and width.  A ball outside the playing area is potted (the
checkpoint parks potted balls behind their pocket) and is not drawn.
"""

from __future__ import annotations

import numpy as np

from camlab88.apps.snooker.checkpoint import Checkpoint, to_metres
from camlab88.apps.snooker.table import BLACK, BLUE, BROWN, GREEN, PINK, YELLOW, Table

# CCL's colour names -> ball index (table.py order); CUEBALL is ball 0.
COLOUR_BALLS: dict[str, int] = {
    "yellow": YELLOW, "green": GREEN, "brown": BROWN, "blue": BLUE, "pink": PINK, "black": BLACK,
}
# CCL's pocket names (§6.3.1) -> table.py's pocket names.  "Bottom" is the baulk end.
POCKET_NAMES: dict[str, str] = {
    "bottom left": "baulk-left", "bottom right": "baulk-right",
    "left centre": "middle-left", "right centre": "middle-right",
    "top left": "top-left", "top right": "top-right",
}


# CCL's default space -> the table frame: x is mirrored, y and z are shared.
CCL_MIRROR = np.array([-1.0, 1.0, 1.0])


def ccl_to_table(v: np.ndarray) -> np.ndarray:
    """A position or displacement in CCL's default space -> the table frame (and back: the
    mirror is its own inverse)."""
    return np.asarray(v, dtype=np.float64) * CCL_MIRROR


table_to_ccl = ccl_to_table


def origin_shift(table: Table) -> np.ndarray:
    """Table-coordinate position (metres) of the table frame's origin (the table's centre)."""
    return np.array([table.length_m / 2.0, table.width_m / 2.0])


def on_table(table: Table, xy_m: np.ndarray) -> np.ndarray:
    """(..., 2) table-coordinate metres -> bool: on the playing area (not potted)."""
    x, y = xy_m[..., 0], xy_m[..., 1]
    return (x >= 0.0) & (x <= table.length_m) & (y >= 0.0) & (y <= table.width_m)


def ball_centres_m(table: Table, xy_m: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(..., 22, 2) table-coordinate metres -> ((..., 22, 3) table-frame centres, (..., 22)
    on-table mask).  Potted balls get centres too (outside the table) but mask False."""
    xy = np.asarray(xy_m, dtype=np.float64)
    out = np.empty((*xy.shape[:-1], 3), dtype=np.float64)
    out[..., :2] = xy - origin_shift(table)
    out[..., 2] = table.radius
    return out, on_table(table, xy)


def checkpoint_centres(checkpoint: Checkpoint,
                       table: Table | None = None) -> tuple[np.ndarray, np.ndarray]:
    """Every frame of a checkpoint -> ((frames, 22, 3) table-frame ball centres, (frames,
    22) on-table mask).  Index 0 is the checkpoint's frame 1 (its initial positions)."""
    return ball_centres_m(table or Table(), to_metres(checkpoint.positions))


def spots(table: Table) -> dict[str, np.ndarray]:
    """Colour name -> its spot in the table frame (on the cloth, z = 0)."""
    shift = origin_shift(table)
    out = {}
    for name, ball in COLOUR_BALLS.items():
        x, y = np.asarray(table.spots[ball]) - shift
        out[name] = np.array([x, y, 0.0])
    return out


def pockets(table: Table) -> dict[str, np.ndarray]:
    """CCL pocket name ('top left', ...) -> its point in the table frame (z = 0)."""
    hx, hy = table.length_m / 2.0, table.width_m / 2.0
    return {
        "bottom left": np.array([-hx, hy, 0.0]), "bottom right": np.array([-hx, -hy, 0.0]),
        "left centre": np.array([0.0, hy, 0.0]), "right centre": np.array([0.0, -hy, 0.0]),
        "top left": np.array([hx, hy, 0.0]), "top right": np.array([hx, -hy, 0.0]),
    }
