"""The chapter-6 pipeline in one call (thesis 6.3-6.4): camera script -> views -> frames
-> film, the intermediate files kept beside the film (``shot.views``, ``shot_frames/``)."""

from __future__ import annotations

import os
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

from camlab88.apps.snooker.camera import ccl, motion
from camlab88.apps.snooker.camera.views import View, write_views
from camlab88.apps.snooker.film.backends import Render, open_backend
from camlab88.apps.snooker.film.schedule import (
    MANIFEST,
    FilmReport,
    Progress,
    frame_file,
    render_film,
)
from camlab88.apps.snooker.film.task import FrameTask, render_png, scene_digest
from camlab88.apps.snooker.render.lights import Lights
from camlab88.apps.snooker.render.scene import Scene


@dataclass(frozen=True)
class FilmPaths:
    movie: Path
    views: Path
    frames: Path

    @classmethod
    def beside(cls, movie: str | os.PathLike[str]) -> FilmPaths:
        m = Path(movie)
        return cls(m, m.with_suffix(".views"), m.with_name(f"{m.stem}_frames"))


@dataclass(frozen=True)
class FilmLook:
    """How each frame is drawn (truecolour): size, specks, shadows, motion blur."""

    width: int = 768
    height: int = 512
    specks: bool = True
    shadows: bool = True
    blur_samples: int = 1
    wood: bool = True

    def task(self, view: View) -> FrameTask:
        return FrameTask(int(view.frame), view, self.width, self.height, self.specks,
                         self.shadows, self.blur_samples, wood=self.wood)


def script_views(motion_path: str | os.PathLike[str], script: str | os.PathLike[str],
                 out: Path) -> list[View]:
    """Interpret the camera script over the shot (§6.3.1) and keep the view file."""
    text = ccl.read_script(script)
    shot = motion.load(motion_path)
    views = ccl.compile_script(text, shot, str(script)).views()
    write_views(out, views, [f"camlab88 snooker film: {script} over {motion_path}"])
    return list(views)


def shoot(scene: Scene, views: Sequence[View], frames_dir: Path, look: FilmLook,
          dask: str | None = None, workers: int | None = None,
          progress: Progress | None = None, manifest: str = MANIFEST,
          render: Render = render_png) -> FilmReport:
    """Render every view's frame (skipping complete ones) on the chosen backend;
    ``manifest``: the resume record's name in ``frames_dir``; ``render``: scene, task ->
    PNG bytes (its repr is part of every frame's resume key)."""
    backend = open_backend(scene, dask, workers, render)
    digest = film_digest(scene, render)
    try:
        return render_film([look.task(v) for v in views], frames_dir, backend, digest,
                           progress, manifest=manifest)
    finally:
        backend.close()


def film_digest(scene: Scene, render: Render = render_png) -> str:
    """What a frame is made from, for its resume key: the scene and (unless the truecolour
    default) the renderer's repr (mode, palette, ...)."""
    digest = scene_digest(scene)
    return digest if render is render_png else f"{digest} {render!r}"


def frame_files(frames_dir: Path, views: Sequence[View]) -> list[Path]:
    return [frame_file(frames_dir, int(v.frame)) for v in views]


def scene_of(motion_path: str | os.PathLike[str], lights: Lights | None = None) -> Scene:
    from camlab88.apps.snooker.render.scene import load_scene

    return load_scene(motion_path, lights)


def title_film(word: str) -> tuple[Scene, list[View]]:
    """The §6.5 title shot spelling ``word`` and its (fixed) camera's views."""
    from camlab88.apps.snooker.film.titles import title_scene, title_views

    scene, view = title_scene(word)
    return scene, title_views(scene, view)
