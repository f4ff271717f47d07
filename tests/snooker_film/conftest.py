from __future__ import annotations

import pytest

from camlab88.apps.snooker.film.backends import InProcess
from camlab88.apps.snooker.film.schedule import render_film
from camlab88.apps.snooker.film.task import scene_digest
from tests.snooker_film.helpers import break_scene, frame_bytes, small_tasks


@pytest.fixture(scope="session")
def reference(tmp_path_factory: pytest.TempPathFactory) -> dict[int, bytes]:
    """The small frames rendered in this process (this also fills the numba cache the
    worker processes then load, so none of them compiles)."""
    out = tmp_path_factory.mktemp("reference")
    scene, tasks = break_scene(), small_tasks()
    render_film(tasks, out, InProcess(scene), scene_digest(scene))
    return frame_bytes(out, tasks)
