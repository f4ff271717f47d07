"""Where frames are rendered: a local process pool (one process per core) or a Dask cluster
(``distributed``: a running scheduler's address, or a LocalCluster started here).

Both hand out ``concurrent.futures``-style futures of ``render(scene, task)`` (by default
``render_png``; any picklable callable -> PNG bytes, e.g. the command layer's one-T5688-a-frame
Sigma renderer); the scene goes to every worker once (the pool's initializer, Dask's
scatter), tasks carry only the frame and its view. Workers return PNG bytes, so a remote
cluster needs no shared disk.
"""

from __future__ import annotations

import contextlib
import logging
import multiprocessing
import os
import signal
from collections.abc import Callable
from concurrent.futures import Future, ProcessPoolExecutor
from typing import Any, Protocol

from camlab88.apps.snooker.film.task import FrameTask, render_png
from camlab88.apps.snooker.render.scene import Scene

Render = Callable[[Scene, FrameTask], bytes]
_WORKER_SCENE: Scene | None = None
_WORKER_RENDER: Render = render_png


class Backend(Protocol):
    name: str
    workers: int

    def submit(self, task: FrameTask) -> Future: ...

    def restart(self) -> None: ...

    def close(self) -> None: ...


def _init_worker(scene: Scene, render: Render) -> None:
    global _WORKER_SCENE, _WORKER_RENDER
    _WORKER_SCENE, _WORKER_RENDER = scene, render
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # Ctrl-C is the command's to answer


def _render_here(task: FrameTask) -> bytes:
    assert _WORKER_SCENE is not None, "the pool's initializer sets the scene"
    return _WORKER_RENDER(_WORKER_SCENE, task)


class LocalPool:
    """One process per core (``spawn``: nothing of the parent's threads is inherited)."""

    def __init__(self, scene: Scene, workers: int | None = None,
                 render: Render = render_png) -> None:
        self.scene, self.render = scene, render
        self.workers = workers or os.cpu_count() or 1
        self.name = f"local pool of {self.workers} processes"
        self._pool = self._start()

    def _start(self) -> ProcessPoolExecutor:
        return ProcessPoolExecutor(self.workers, multiprocessing.get_context("spawn"),
                                   initializer=_init_worker,
                                   initargs=(self.scene, self.render))

    def submit(self, task: FrameTask) -> Future:
        return self._pool.submit(_render_here, task)

    def pids(self) -> list[int]:
        return list(getattr(self._pool, "_processes", {}) or {})

    def restart(self) -> None:
        """After a worker died (BrokenProcessPool): a fresh pool."""
        self._pool.shutdown(wait=True, cancel_futures=True)
        self._pool = self._start()

    def close(self) -> None:
        self._pool.shutdown(wait=True, cancel_futures=True)


class InProcess:
    """No pool: every frame in this process (benchmarks' one-process figure, tests)."""

    workers = 1
    name = "this process"

    def __init__(self, scene: Scene, render: Render = render_png) -> None:
        self.scene, self.render = scene, render

    def submit(self, task: FrameTask) -> Future:
        f: Future = Future()
        try:
            f.set_result(self.render(self.scene, task))
        except Exception as exc:  # reported per frame like a worker's error
            f.set_exception(exc)
        return f

    def restart(self) -> None:
        pass

    def close(self) -> None:
        pass


class DaskCluster:
    """``address`` = a scheduler's ``tcp://host:port``, or ``local`` for a LocalCluster of
    ``workers`` single-threaded worker processes started (and stopped) here."""

    def __init__(self, scene: Scene, address: str, workers: int | None = None,
                 timeout_s: float = 30.0, render: Render = render_png) -> None:
        from distributed import Client, LocalCluster

        self._cluster: Any = None
        self._render, self._scene_obj, self._timeout = render, scene, timeout_s
        if address == "local":
            n = workers or os.cpu_count() or 1
            # The scheduler always serves HTTP; with no address it takes port 8787 and, when
            # another cluster holds it, warns (an error under the tests' warning filter):
            # a free port of the loopback's instead.
            # its workers ignore Ctrl-C (quiet_worker): the command answers it, in one line
            self._cluster = LocalCluster(n_workers=n, threads_per_worker=1, processes=True,
                                         dashboard_address="127.0.0.1:0", host="127.0.0.1",
                                         preload=["camlab88.apps.snooker.film.quiet_worker"])
            self._client = Client(self._cluster, timeout=timeout_s)
        else:
            self._client = Client(address, timeout=timeout_s)
        self.workers = max(1, len(self._client.scheduler_info()["workers"]))
        where = self._client.scheduler_info()["address"]
        self.name = f"Dask cluster at {where} ({self.workers} workers)"
        self._scatter()

    def _scatter(self) -> None:
        """The scene to every worker (again, once the workers holding it are all gone)."""
        self._client.wait_for_workers(1, timeout=self._timeout)
        self._scene = self._client.scatter(self._scene_obj, broadcast=True, hash=False)

    def submit(self, task: FrameTask) -> Future:
        if self._scene.status != "finished":  # lost with every worker that held it
            self._scatter()
        # pure=False: a frame asked for again (a retry) is computed again, not looked up
        dask_future = self._client.submit(self._render, self._scene, task, pure=False)
        return _as_concurrent(dask_future)

    def restart(self) -> None:
        pass  # the scheduler moves a dead worker's tasks; submit re-sends a lost scene

    def close(self) -> None:
        # stopping a cluster of our own: its workers' and scheduler's parting complaints
        # (lost data, a busy worker killed) are not the user's news
        quiet = contextlib.nullcontext() if self._cluster is None else _quiet("distributed")
        with quiet:
            self._client.close()
            if self._cluster is not None:
                self._cluster.close()


@contextlib.contextmanager
def _quiet(name: str):
    log = logging.getLogger(name)
    level = log.level
    log.setLevel(logging.CRITICAL)
    try:
        yield
    finally:
        log.setLevel(level)


def _as_concurrent(dask_future: Any) -> Future:
    out: Future = Future()

    def done(f: Any) -> None:
        try:
            out.set_result(f.result())
        except BaseException as exc:  # KilledWorker, CancelledError, ...
            out.set_exception(exc)
    dask_future.add_done_callback(done)
    return out


def open_backend(scene: Scene, dask: str | None = None, workers: int | None = None,
                 render: Render = render_png) -> Backend:
    if dask is None:
        return LocalPool(scene, workers, render) if (workers or os.cpu_count() or 1) > 1 \
            else InProcess(scene, render)
    return DaskCluster(scene, dask, workers, render=render)
