"""Losing every Dask worker at once (a LocalCluster whose worker processes are all
SIGKILLed mid-film) loses no frame: the scene scattered to the workers went with them, so
it is sent again to the workers that replace them and the lost frames are rendered again."""

from __future__ import annotations

import os
import signal
from pathlib import Path

from camlab88.apps.snooker.film.backends import DaskCluster
from camlab88.apps.snooker.film.schedule import render_film
from camlab88.apps.snooker.film.task import scene_digest
from tests.snooker_film.helpers import break_scene, frame_bytes, small_tasks


def test_a_film_survives_losing_every_dask_worker_at_once(reference: dict[int, bytes],
                                                          tmp_path: Path) -> None:
    scene, tasks = break_scene(), small_tasks()
    cluster = DaskCluster(scene, "local", 2)
    killed: list[int] = []

    def kill_all(done: int, total: int) -> None:
        if done == 2 and not killed:
            killed.extend(cluster._client.run(os.getpid).values())
            for pid in killed:
                os.kill(pid, signal.SIGKILL)
    try:
        report = render_film(tasks, tmp_path, cluster, scene_digest(scene), kill_all)
    finally:
        cluster.close()
    assert len(killed) == 2
    assert sorted(report.rendered) == [t.frame for t in tasks]
    assert frame_bytes(tmp_path, tasks) == reference
