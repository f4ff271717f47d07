"""Shared pieces of the film tests: the break, a few small frames, frame bytes."""

from __future__ import annotations

import socket
from pathlib import Path

from camlab88.apps.snooker.camera import ccl, motion
from camlab88.apps.snooker.camera.views import View
from camlab88.apps.snooker.film.schedule import frame_file
from camlab88.apps.snooker.film.task import FrameTask
from camlab88.apps.snooker.render.scene import Scene, load_scene

DATA = Path(__file__).resolve().parents[1] / "data" / "snooker_film"
BREAK = DATA / "break.checkpoint"
SCRIPT = DATA / "break.ccl"
SIZE = (96, 64)


def break_scene() -> Scene:
    return load_scene(BREAK)


def break_views() -> list[View]:
    return list(ccl.compile_script(ccl.read_script(SCRIPT), motion.load(BREAK),
                                   str(SCRIPT)).views())


def small_tasks(frames: range = range(1, 9), blur: int = 1) -> list[FrameTask]:
    views = {v.frame: v for v in break_views()}
    return [FrameTask(f, views[f], SIZE[0], SIZE[1], blur_samples=blur) for f in frames]


def frame_bytes(directory: Path, tasks: list[FrameTask]) -> dict[int, bytes]:
    return {t.frame: frame_file(directory, t.frame).read_bytes() for t in tasks}


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])
