"""Video memory and its allocator, the pad graph's rules, drawing, LUT timing."""

from __future__ import annotations

import numpy as np
import pytest

from camlab88.emulator.rainbow import (
    GraphError,
    OutOfVideoMemory,
    Rainbow,
    RainbowError,
    VideoMemory,
)


def test_strict_memory_is_64k_16bit_words_and_runs_out_clearly() -> None:
    r = Rainbow(strict=True)
    assert r.memory.words_16bit == 65536
    r.create_pad(512, 256, 4, plane=0)
    r.create_pad(512, 256, 4, plane=4)  # the other planes of the same words
    with pytest.raises(OutOfVideoMemory, match="out of video memory"):
        r.create_pad(8, 8, 1, plane=2)
    r.create_pad(8, 8, 0)  # virtual pads need no memory


def test_allocator_reuses_freed_space_and_never_overlaps() -> None:
    r = Rainbow(memory=VideoMemory(256, 256))
    pads = [r.create_pad(100, 100, 8) for _ in range(4)]
    with pytest.raises(OutOfVideoMemory):
        r.create_pad(100, 100, 8)
    r.destroy(pads[1])
    p = r.create_pad(100, 100, 8)
    rects = [r.graph.nodes[n].alloc for n in (pads[0], pads[2], pads[3], p)]
    for i, a in enumerate(rects):
        for b in rects[i + 1:]:
            assert (a.x + a.width <= b.x or b.x + b.width <= a.x
                    or a.y + a.height <= b.y or b.y + b.height <= a.y)


def test_drawing_touches_only_the_pads_planes() -> None:
    r = Rainbow(memory=VideoMemory(64, 64))
    lo = r.create_pad(64, 64, 3, plane=0)
    hi = r.create_pad(64, 64, 5, plane=3)
    assert r.graph.nodes[lo].alloc.x == r.graph.nodes[hi].alloc.x  # shared words
    r.canvas(lo).clear(5)
    r.canvas(hi).circle(32, 32, 10, 31)
    assert (r.canvas(lo).read() == 5).all()
    assert r.canvas(hi).read()[32, 32] == 31 and r.canvas(hi).read()[0, 0] == 0


def test_cycles_rejected_and_nodes_mapped_many_times() -> None:
    r = Rainbow()
    a, b, c = (r.create_cluster(100, 100) for _ in range(3))
    r.map(a, b)
    r.map(b, c)
    with pytest.raises(GraphError, match="cycle"):
        r.map(c, a)
    with pytest.raises(GraphError, match="cycle"):
        r.map(a, a)
    p = r.create_pad(10, 10, 1)
    for i in range(5):
        r.map(0, p, 20 * i, 0)
    r.map(c, p)
    r.map(0, a, 300, 300)
    assert len(r.graph.instances()) == 6


def test_clusters_clip_and_resize() -> None:
    r = Rainbow()
    r.set_lut(0, [[0, 0, 0], [255, 255, 255]])
    cl = r.create_cluster(20, 20)
    p = r.create_pad(100, 100, 1)
    r.canvas(p).clear(1)
    r.map(cl, p, -10, -10)
    r.map(0, cl, 50, 50)
    assert (r.frame()[:, :, 0] > 0).sum() == 400
    r.resize(cl, 40, 30)
    assert (r.frame()[:, :, 0] > 0).sum() == 1200


def test_lut_writes_take_effect_at_the_next_frame() -> None:
    r = Rainbow()
    v = r.create_pad(768, 576, 0)
    r.map(0, v)
    r.frame()
    r.set_lut(0, [[9, 8, 7]])
    assert (r.peek() == 0).all()  # still showing the old table
    assert (r.frame() == [9, 8, 7]).all()


def test_primitives() -> None:
    r = Rainbow()
    p = r.create_pad(40, 30, 8)
    c = r.canvas(p)
    c.line(0, 0, 9, 3, 1)
    assert c.read()[0, 0] == 1 and c.read()[3, 9] == 1 and (c.read() == 1).sum() == 10
    c.rect(10, 10, 5, 4, 2, filled=False)
    assert (c.read() == 2).sum() == 14
    c.polygon([(20, 0), (30, 0), (30, 10), (20, 10)], 3)
    assert (c.read() == 3).sum() == 100
    c.circle(5, 20, 3, 4)
    assert (c.read() == 4).sum() == 29  # rows of 1, 5, 5, 7, 5, 5, 1 pixels
    w = c.text(0, 12, "Hi", 5)
    assert w == 12 and (c.read()[12:22, 0:12] == 5).any()
    r2 = r.create_pad(10, 10, 2)
    r.copy(p, 20, 0, 10, 10, r2, 0, 0)
    assert (r.canvas(r2).read() == 3).all()
    with pytest.raises(RainbowError, match="does not fit"):
        c.point(0, 0, 256)
    with pytest.raises(RainbowError, match="virtual"):
        r.canvas(r.create_pad(5, 5, 0))
    c.put(-5, -5, np.full((10, 10), 9))  # clipped
    assert (c.read()[:5, :5] == 9).all() and c.read()[5, 5] != 9
