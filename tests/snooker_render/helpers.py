"""Shared fixtures for the renderer tests: the shipped break and its views."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from camlab88.apps.snooker.camera.views import View, read_views
from camlab88.apps.snooker.render.scene import Scene, load_scene

DATA = Path(__file__).resolve().parents[1] / "data" / "snooker_render"
BREAK = DATA / "break.checkpoint"
VIEWS = DATA / "break.views"


def break_scene() -> Scene:
    return load_scene(BREAK)


def break_views() -> list[View]:
    return read_views(VIEWS)


def overhead(frame: int = 1, focal: float = 24.0) -> View:
    """Looking straight down on the middle of the table from 3.2 m."""
    return View(frame, (0.0, 0.0, 3.2), (0.0, 0.0, 0.0), focal)


def one_ball_scene(x: float, y: float, lights: object = None) -> Scene:
    """The break's table with only the cue ball, at (x, y) in the table frame."""
    s = break_scene()
    centres = s.centres[:1].copy()
    on = np.zeros_like(s.on_table[:1])
    centres[0, 0] = (x, y, s.table.radius)
    on[0, 0] = True
    return Scene(s.table, centres, on, lights if lights is not None else s.lights)
