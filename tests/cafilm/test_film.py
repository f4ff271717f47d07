"""The film's frames: byte-identical wherever rendered (this process, the local pool, Dask),
and the period mode on a T5688 in Sigma orders only."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from camlab88.apps.cafilm.film import digest, render_png, stage_at, tasks
from camlab88.apps.cafilm.period import host_for, period_frames
from camlab88.apps.snooker.film.backends import DaskCluster, InProcess, LocalPool
from camlab88.apps.snooker.film.schedule import frame_file, render_film
from tests.cafilm.helpers import glider_film


def _frames(out: Path, n: int) -> dict[int, bytes]:
    return {k: frame_file(out, k).read_bytes() for k in range(1, n + 1)}


@pytest.fixture(scope="module")
def film():
    return glider_film(generations=2, per_generation=2)


@pytest.fixture(scope="module")
def reference(film, tmp_path_factory: pytest.TempPathFactory) -> dict[int, bytes]:
    out = tmp_path_factory.mktemp("ref")
    render_film(tasks(film), out, InProcess(film, render_png), digest(film))
    return _frames(out, film.n_frames)


def test_local_pool_frames_are_byte_identical_to_this_process(film, reference,
                                                              tmp_path: Path) -> None:
    pool = LocalPool(film, 2, render_png)
    try:
        report = render_film(tasks(film), tmp_path, pool, digest(film))
    finally:
        pool.close()
    assert sorted(report.rendered) == list(range(1, film.n_frames + 1))
    assert _frames(tmp_path, film.n_frames) == reference


def test_dask_frames_are_byte_identical_to_the_pool(film, reference, tmp_path: Path) -> None:
    cluster = DaskCluster(film, "local", 2, render=render_png)
    try:
        render_film(tasks(film), tmp_path, cluster, digest(film))
    finally:
        cluster.close()
    assert _frames(tmp_path, film.n_frames) == reference


def test_a_resumed_film_renders_only_what_is_missing_or_changed(film, reference,
                                                                tmp_path: Path) -> None:
    render_film(tasks(film), tmp_path, InProcess(film, render_png), digest(film))
    frame_file(tmp_path, 2).unlink()
    frame_file(tmp_path, 3).write_bytes(b"torn")
    report = render_film(tasks(film), tmp_path, InProcess(film, render_png), digest(film))
    assert sorted(report.rendered) == [2, 3]
    assert _frames(tmp_path, film.n_frames) == reference
    other = glider_film(generations=2, per_generation=2, glide="none")
    assert digest(other) != digest(film)


def test_the_period_mode_talks_only_sigma_orders_and_shows_what_the_host_meant(film) -> None:
    from camlab88.emulator.machine.sigma import SigmaMachine
    from camlab88.protocols.link import LineSettings

    machine = SigmaMachine("t5688", LineSettings(baud=9600))
    orders: list[object] = []
    machine.trace(orders.append, strict=True)  # an unknown or malformed order raises

    def send(data: bytes):
        start = machine.now
        machine.host.write(data)
        machine.run_until(machine.idle_time())
        return machine.frame(), float(machine.now - start)

    lut = host_for(film).palette.lut
    shown = list(period_frames(film, send))
    assert [f.frame for f in shown] == list(range(1, film.n_frames + 1))
    for f in shown:
        assert np.array_equal(f.image, lut[f.intended])  # every pixel as the host meant
        assert f.line_seconds == pytest.approx(f.orders * 10 / 9600, rel=0.05)
    assert len(orders) > 100
    assert machine.host.read() == b""  # the terminal never had to answer
    # frames after the first send only what changed
    assert shown[1].orders < shown[0].orders / 2


def test_frames_differ_between_generations_and_stay_put_when_nothing_moves(film) -> None:
    a, b = stage_at(film, 1)[0], stage_at(film, film.n_frames)[0]
    assert {(p.col, p.row) for p in a.placed} != {(p.col, p.row) for p in b.placed}
