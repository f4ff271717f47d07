"""Property tests: band structure + video processor == the per-pixel reference, and an
incremental compile after random edits == a compile from scratch."""

from __future__ import annotations

import numpy as np
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from camlab88.emulator.rainbow import Rainbow, RainbowError
from camlab88.emulator.rainbow.bands import BandStructure, Span
from camlab88.emulator.rainbow.compiler import compile_graph
from camlab88.emulator.rainbow.memory import VideoMemory
from tests.rainbow.conftest import random_lut

coord = st.integers(-120, 800) | st.integers(0, 200)  # the second crowds pads together
small = st.integers(1, 30)
prio = st.integers(0, 2)  # few values, so ties (concatenation) are common


@st.composite
def graphs(draw):
    """A random device: pads of every depth, nested clusters, arcs (some off, some repeated)."""
    r = Rainbow(memory=VideoMemory(1024, 1024))
    r.set_lut(0, random_lut(draw(st.integers(0, 3))))
    clusters = [0]
    for _ in range(draw(st.integers(0, 3))):
        cw, ch = draw(st.integers(120, 500) | small), draw(st.integers(100, 400) | small)
        cid = r.create_cluster(cw, ch)
        # into the screen or an earlier cluster, so it is (usually) visible
        r.map(draw(st.sampled_from(clusters)), cid, draw(coord), draw(coord), draw(prio))
        clusters.append(cid)
    nodes = clusters[1:]
    for _ in range(draw(st.integers(2, 10))):
        depth = draw(st.integers(0, 8))
        plane = draw(st.integers(0, min(7, 8 - depth)))
        w, h = draw(st.integers(20, 300) | small), draw(st.integers(20, 250) | small)
        pid = r.create_pad(w, h, depth, plane, draw(st.integers(0, 15)))
        if depth:
            rng = np.random.default_rng(draw(st.integers(0, 1000)))
            r.canvas(pid).put(0, 0, rng.integers(0, 1 << depth, (h, w)))
        r.map(draw(st.sampled_from(clusters)), pid, draw(coord), draw(coord), draw(prio))
        nodes.append(pid)
    for _ in range(draw(st.integers(1, 8))):  # extra arcs: nodes mapped many times
        try:
            r.map(draw(st.sampled_from(clusters)), draw(st.sampled_from(nodes)), draw(coord),
                  draw(coord), draw(prio), not draw(st.booleans()))
        except RainbowError:
            pass  # a cycle: refused, as it should be
    return r


def _continues(a: Span, b: Span, dx: int, dy: int) -> bool:
    """Would span b be span a carried on dx columns right / dy rows down?"""
    return a.page == b.page and len(a.sources) == len(b.sources) and all(
        (s.pad, s.mem_x + dx, s.mem_y + dy, s.plane, s.depth)
        == (t.pad, t.mem_x, t.mem_y, t.plane, t.depth)
        for s, t in zip(a.sources, b.sources))


def assert_canonical(bs: BandStructure) -> None:
    """Bands tile the screen, spans tile each band, and nothing more could be merged."""
    bands = list(bs)
    assert bands[0].y0 == 0 and bands[-1].y1 == 576
    for a, b in zip(bands, bands[1:]):
        assert a.y1 == b.y0
        same_cuts = [(s.x0, s.x1) for s in a.spans] == [(s.x0, s.x1) for s in b.spans]
        assert not (same_cuts and all(_continues(s, t, 0, a.y1 - a.y0)
                                      for s, t in zip(a.spans, b.spans))), (a.y0, b.y0)
    for band in bands:
        assert band.spans[0].x0 == 0 and band.spans[-1].x1 == 768
        for s, t in zip(band.spans, band.spans[1:]):
            assert s.x1 == t.x0 and not _continues(s, t, s.x1 - s.x0, 0), (band.y0, s.x0)


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(graphs())
def test_band_structure_output_equals_reference(r: Rainbow) -> None:
    frame = r.frame()
    ref = r.reference()
    diff = np.argwhere(np.any(frame != ref, axis=-1))
    assert len(diff) == 0, f"{len(diff)} pixels differ, first at (row, col) {diff[0]}"
    assert_canonical(r.bands())


edits = st.lists(
    st.tuples(st.sampled_from(["move", "prio", "onoff", "resize", "unmap", "page", "map",
                               "new_pad", "new_cluster", "destroy", "draw"]),
              st.integers(0, 1000), coord, coord),
    min_size=1, max_size=8,
)


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(graphs(), edits)
def test_incremental_compile_equals_scratch(r: Rainbow, ops) -> None:
    r.bands()
    for op, pick, a, b in ops:
        arcs = sorted(r.graph.arcs)
        clusters = [n for n in sorted(r.graph.nodes) if n and r.node_kind(n) == "cluster"]
        pads = [n for n in sorted(r.graph.nodes) if n and r.node_kind(n) == "pad"]
        if op == "move" and arcs:
            r.move(arcs[pick % len(arcs)], a, b)
        elif op == "prio" and arcs:
            r.set_priority(arcs[pick % len(arcs)], a % 3)
        elif op == "onoff" and arcs:
            arc = arcs[pick % len(arcs)]
            r.set_on(arc, not r.graph.arcs[arc].on)
        elif op == "resize" and clusters:
            r.resize(clusters[pick % len(clusters)], abs(a) % 500 + 1, abs(b) % 400 + 1)
        elif op == "unmap" and arcs:
            r.unmap(arcs[pick % len(arcs)])
        elif op == "page" and pads:
            r.set_page(pads[pick % len(pads)], abs(a) % 16)
        elif op == "map":
            parent = ([0] + clusters)[pick % (len(clusters) + 1)]
            nodes = clusters + pads
            if nodes:
                try:
                    r.map(parent, nodes[(pick // 7) % len(nodes)], a, b, pick % 3,
                          pick % 5 != 0)
                except RainbowError:
                    pass  # a cycle: refused, and the graph must be as it was
        elif op == "new_pad":
            depth = pick % 9
            pid = r.create_pad(abs(a) % 200 + 1, abs(b) % 150 + 1, depth,
                               (pick // 9) % min(8, 9 - depth), pick % 16)
            r.map(([0] + clusters)[pick % (len(clusters) + 1)], pid, a, b, pick % 3)
        elif op == "new_cluster":
            cid = r.create_cluster(abs(a) % 400 + 1, abs(b) % 300 + 1)
            r.map(([0] + clusters)[pick % (len(clusters) + 1)], cid, a % 300, b % 300,
                  pick % 3)
        elif op == "destroy" and (clusters or pads):
            nodes = clusters + pads
            r.destroy(nodes[pick % len(nodes)])
        elif op == "draw" and pads:
            pid = pads[pick % len(pads)]
            pad = r.graph.pad(pid)
            if pad.depth:
                r.canvas(pid).rect(a % 50, b % 50, pick % 60 + 1, pick % 40 + 1,
                                   pick % (1 << pad.depth))
        incremental = r.bands()
        assert incremental == compile_graph(r.graph)
        assert_canonical(incremental)
    assert np.array_equal(r.frame(), r.reference())


def test_rows_split_by_a_hidden_pad_merge_back() -> None:
    """A pad wholly obscured adds edges but no visible change: one band, not three."""
    r = Rainbow()
    top = r.create_pad(100, 100, 1)
    hidden = r.create_pad(20, 20, 1)
    r.map(0, top, 10, 10, priority=1)
    r.map(0, hidden, 20, 20, priority=0)
    bands = list(r.bands())
    assert [(b.y0, b.y1) for b in bands] == [(0, 10), (10, 110), (110, 576)]
    assert_canonical(r.bands())
