"""Frames rendered anywhere are byte-identical to frames rendered here: the local process
pool, a LocalCluster (--dask local) and a real `dask scheduler` with two `dask worker`
processes on 127.0.0.1; a worker killed mid-sequence loses no frame."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path

import pytest

from camlab88.apps.snooker.film.backends import DaskCluster, LocalPool
from camlab88.apps.snooker.film.schedule import render_film
from camlab88.apps.snooker.film.task import scene_digest
from tests.snooker_film.helpers import break_scene, frame_bytes, free_port, small_tasks

ROOT = Path(__file__).resolve().parents[2]
DASK = str(Path(sys.executable).with_name("dask"))


def test_local_pool_frames_match_this_process(reference: dict[int, bytes],
                                              tmp_path: Path) -> None:
    scene, tasks = break_scene(), small_tasks()
    pool = LocalPool(scene, 2)
    try:
        report = render_film(tasks, tmp_path, pool, scene_digest(scene))
    finally:
        pool.close()
    assert sorted(report.rendered) == [t.frame for t in tasks]
    assert frame_bytes(tmp_path, tasks) == reference


def test_dask_local_cluster_frames_match(reference: dict[int, bytes], tmp_path: Path) -> None:
    scene, tasks = break_scene(), small_tasks()
    cluster = DaskCluster(scene, "local", 2)
    try:
        assert cluster.workers == 2
        render_film(tasks, tmp_path, cluster, scene_digest(scene))
    finally:
        cluster.close()
    assert frame_bytes(tmp_path, tasks) == reference


def test_local_pool_survives_a_killed_worker(tmp_path: Path) -> None:
    scene, tasks = break_scene(), small_tasks(range(1, 13), blur=4)
    pool = LocalPool(scene, 2)
    killed: list[int] = []

    def kill_one(done: int, total: int) -> None:
        if done == 2 and not killed:
            killed.append(pool.pids()[0])
            os.kill(killed[0], signal.SIGKILL)
    try:
        report = render_film(tasks, tmp_path, pool, scene_digest(scene), kill_one)
    finally:
        pool.close()
    assert killed and report.retries  # the lost frames were reported and rendered again
    assert sorted(report.rendered) == [t.frame for t in tasks]
    assert frame_bytes(tmp_path, tasks) == _in_process(tasks, tmp_path / "ref")


def _in_process(tasks: list, out: Path) -> dict[int, bytes]:
    from camlab88.apps.snooker.film.backends import InProcess

    scene = break_scene()
    render_film(tasks, out, InProcess(scene), scene_digest(scene))
    return frame_bytes(out, tasks)


@pytest.fixture()
def real_cluster(tmp_path: Path) -> Iterator[tuple[str, list[subprocess.Popen]]]:
    """`dask scheduler` and two `dask worker` processes on 127.0.0.1, stopped by pid."""
    port = free_port()
    address = f"tcp://127.0.0.1:{port}"
    quiet = {"stdout": subprocess.DEVNULL, "stderr": subprocess.DEVNULL, "cwd": ROOT}
    procs = [subprocess.Popen([DASK, "scheduler", "--host", "127.0.0.1", "--port", str(port),
                               "--no-dashboard"], **quiet)]
    try:
        for k in range(2):
            procs.append(subprocess.Popen(
                [DASK, "worker", address, "--nthreads", "1", "--no-nanny", "--no-dashboard",
                 "--host", "127.0.0.1", "--name", f"film-test-{k}",
                 "--local-directory", str(tmp_path / f"w{k}")], **quiet))
        from distributed import Client

        with Client(address, timeout=60) as c:
            c.wait_for_workers(2, timeout=60)
        yield address, procs[1:]
    finally:
        for p in reversed(procs):  # workers first, then the scheduler
            if p.poll() is None:
                p.terminate()
            try:
                p.wait(timeout=5)
            except subprocess.TimeoutExpired:
                p.kill()
                p.wait(timeout=5)


def test_real_cluster_matches_and_loses_no_frame_to_a_killed_worker(
        reference: dict[int, bytes], real_cluster: tuple[str, list[subprocess.Popen]],
        tmp_path: Path) -> None:
    address, workers = real_cluster
    scene, tasks = break_scene(), small_tasks()
    cluster = DaskCluster(scene, address)
    try:
        assert cluster.workers == 2
        render_film(tasks, tmp_path / "a", cluster, scene_digest(scene))
        assert frame_bytes(tmp_path / "a", tasks) == reference
        slow = small_tasks(range(1, 13), blur=4)  # long enough to kill a worker mid-way
        killed: list[int] = []

        def kill_one(done: int, total: int) -> None:
            if done == 2 and not killed:
                killed.append(done)
                workers[0].send_signal(signal.SIGKILL)
        report = render_film(slow, tmp_path / "b", cluster, scene_digest(scene), kill_one)
    finally:
        cluster.close()
    assert killed and workers[0].wait(timeout=10) == -signal.SIGKILL
    assert sorted(report.rendered) == [t.frame for t in slow]
    assert frame_bytes(tmp_path / "b", slow) == _in_process(slow, tmp_path / "ref")


def test_film_frames_are_the_renderers_frames(reference: dict[int, bytes],
                                              tmp_path: Path) -> None:
    """The same bytes `snooker render --mode truecolour` writes (render_frame + write_png)."""
    from camlab88.apps.snooker.render.truecolour import RenderOptions, render_frame
    from camlab88.base.png import write_png

    t = small_tasks()[3]
    write_png(render_frame(break_scene(), t.view, RenderOptions(t.width, t.height)),
              tmp_path / "f.png")
    assert (tmp_path / "f.png").read_bytes() == reference[t.frame]
