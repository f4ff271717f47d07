"""Rainbow edge cases: strict video memory and virtual pads, the compiler's path limit, scene
files' key and name checks, device ids, frame copies, strict-memory record and replay
(each test failed before its fix)."""

from __future__ import annotations

import base64
import json

import numpy as np
import pytest

from camlab88.cli import main
from camlab88.emulator.rainbow import GraphError, OutOfVideoMemory, Rainbow, RainbowError
from camlab88.emulator.rainbow.graph import MAX_COORD
from camlab88.emulator.rainbow.reference import reference_frame
from camlab88.emulator.rainbow.scene import SceneError, build_scene


# -- 1. virtual pads are limited by the coordinate range, not by video memory --------------
def test_strict_memory_allows_a_full_screen_virtual_pad() -> None:
    r = Rainbow(strict=True)
    bg = r.create_pad(768, 576, 0)  # bigger than the 512x256 memory, but needs none
    r.map(0, bg)
    r.create_pad(MAX_COORD, MAX_COORD, 0)
    with pytest.raises(RainbowError, match="width"):
        r.create_pad(MAX_COORD + 1, 1, 0)


def test_strict_memory_too_big_pad_is_out_of_memory_not_a_range_error() -> None:
    r = Rainbow(strict=True)
    with pytest.raises(OutOfVideoMemory, match="does not fit in 512x256 video memory"):
        r.create_pad(768, 100, 1)
    with pytest.raises(OutOfVideoMemory, match="does not fit in 512x256 video memory"):
        r.create_pad(100, 300, 8)
    r.create_pad(512, 256, 8)  # the whole memory still allocates


def test_run_demo_headless_in_strict_memory(capsys) -> None:
    assert main(["rainbow", "run", "--headless", "--strict", "--stop-after", "5"]) == 0
    assert "5 frames" in capsys.readouterr().out


# -- 2. too many paths is a clean error in render, with or without --reference -------------
def _many_paths_scene() -> dict:
    """21 nested clusters, each mapped twice into the next: 2^21 paths to the pad."""
    nodes = {f"c{i}": {"type": "cluster", "width": 8, "height": 8} for i in range(21)}
    nodes["p"] = {"type": "pad", "width": 1, "height": 1, "depth": 1}
    arcs = [{"parent": "screen", "child": "c0"}]
    for i in range(20):
        arcs += [{"parent": f"c{i}", "child": f"c{i + 1}"}] * 2
    arcs += [{"parent": "c20", "child": "p"}] * 2
    return {"nodes": nodes, "arcs": arcs}


@pytest.mark.parametrize("reference", [False, True])
def test_render_with_too_many_paths_is_a_one_line_error(tmp_path, capsys, reference) -> None:
    p = tmp_path / "s.json"
    p.write_text(json.dumps(_many_paths_scene()))
    args = ["rainbow", "render", str(p), "--out", str(tmp_path / "o.png")]
    assert main(args + (["--reference"] if reference else [])) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "more than" in err and "Traceback" not in err
    assert not (tmp_path / "o.png").exists()


def test_reference_applies_the_compilers_path_limit() -> None:
    r = build_scene(_many_paths_scene())
    with pytest.raises(GraphError, match="more than"):
        reference_frame(r.graph, r.memory.words, r.lut)


# -- 3. misspelt keys are refused, naming the JSON path ------------------------------------
def _scene_error(scene: dict) -> str:
    with pytest.raises(SceneError) as e:
        build_scene(scene)
    return str(e.value)


def test_unknown_keys_in_nodes_and_arcs_are_refused() -> None:
    pad = {"type": "pad", "width": 4, "height": 4, "depth": 2}
    assert "$.nodes.p.lutpage: unknown key" in _scene_error({"nodes": {"p": {**pad,
                                                                              "lutpage": 3}}})
    assert "$.nodes.c.depth: unknown key" in _scene_error(
        {"nodes": {"c": {"type": "cluster", "width": 4, "height": 4, "depth": 1}}})
    assert "$.arcs[0].prio: unknown key" in _scene_error(
        {"nodes": {"p": pad}, "arcs": [{"parent": "screen", "child": "p", "prio": 5}]})


# -- 4. errors name the scene's nodes, not internal ids ------------------------------------
def test_graph_errors_use_scene_names() -> None:
    msg = _scene_error({
        "nodes": {"outer": {"type": "cluster", "width": 5, "height": 5},
                  "inner": {"type": "cluster", "width": 5, "height": 5}},
        "arcs": [{"parent": "outer", "child": "inner"}, {"parent": "inner", "child": "outer"}]})
    assert "$.arcs[1]" in msg and "'outer'" in msg and "'inner'" in msg and "cycle" in msg
    assert "node 1" not in msg and "node 2" not in msg
    msg = _scene_error({"nodes": {"p": {"type": "pad", "width": 4, "height": 4, "depth": 1},
                                  "q": {"type": "pad", "width": 4, "height": 4, "depth": 1}},
                        "arcs": [{"parent": "p", "child": "q"}]})
    assert "$.arcs[0].parent" in msg and "'p' is a pad, not a cluster" in msg
    assert "node 1" not in msg


# -- 5. line-wrapped base64 (as the base64 tool writes it) is accepted ---------------------
def test_wrapped_base64_pixels_are_accepted() -> None:
    w, h = 40, 10
    data = bytes(i % 4 for i in range(w * h))
    text = base64.b64encode(data).decode()
    wrapped = "\n".join(text[i: i + 76] for i in range(0, len(text), 76)) + "\n"
    assert "\n" in wrapped.strip()
    r = build_scene({"nodes": {"p": {"type": "pad", "width": w, "height": h, "depth": 2,
                                     "pixels": wrapped}}})
    pid = max(r.graph.nodes)
    assert np.array_equal(r.canvas(pid).read(), np.frombuffer(data, np.uint8).reshape(h, w))
    assert "bad base64" in _scene_error(
        {"nodes": {"p": {"type": "pad", "width": 2, "height": 1, "depth": 2,
                         "pixels": "AA*E"}}})


# -- 7. node and arc ids are never reused --------------------------------------------------
def test_device_ids_are_monotonic() -> None:
    r = Rainbow()
    a = r.create_pad(4, 4, 1)
    c = r.create_cluster(4, 4)
    arc = r.map(0, a)
    r.unmap(arc)
    r.destroy(a)
    r.destroy(c)
    b = r.create_pad(4, 4, 1)
    assert b not in (a, c) and b > c
    assert r.map(0, b) > arc
    explicit = r.create_cluster(4, 4, node=50)
    assert r.create_cluster(4, 4) > explicit


# -- 6. a virtual pad's page counts in a tie (hand-computed) -------------------------------
def test_virtual_pads_page_counts_in_a_tie() -> None:
    r = Rainbow()
    lut = np.zeros((4096, 3), np.int64)
    lut[:, 0] = np.arange(4096) % 256  # every entry distinct: (index % 256, index // 256, 7)
    lut[:, 1] = np.arange(4096) // 256
    lut[:, 2] = 7
    r.set_lut(0, lut)
    real = r.create_pad(20, 10, 2, plane=1, lut_page=4)
    r.canvas(real).clear(3)  # stored as 3 << 1 = 6
    virt = r.create_pad(20, 10, 0, lut_page=5)
    low_virt = r.create_pad(10, 10, 0, lut_page=2)
    r.map(0, real, 100, 100, priority=2)
    r.map(0, virt, 110, 100, priority=2)  # overlaps columns 110..119: a tie
    r.map(0, low_virt, 95, 100, priority=2)  # overlaps columns 100..104: a tie, lower page
    f = r.frame()
    assert tuple(f[105, 107]) == (6, 4, 7)  # real alone: page 4, word 6
    assert tuple(f[105, 115]) == (6, 5, 7)  # tie: word 6 | 0, page max(4, 5) = 5
    assert tuple(f[105, 125]) == (0, 5, 7)  # virtual alone: page 5, word 0
    assert tuple(f[105, 102]) == (6, 4, 7)  # tie: word 6 | 0, page max(4, 2) = 4
    assert tuple(f[105, 97]) == (0, 2, 7)  # low virtual alone: page 2, word 0
    assert tuple(f[50, 50]) == (0, 0, 7)  # uncovered: LUT[0]
    assert np.array_equal(f, r.reference())


# -- 8. last_frame is one reused buffer; frame_copy() is a snapshot ------------------------
def test_frame_copy_survives_later_frames() -> None:
    from camlab88.emulator.machine import RainbowMachine

    s = RainbowMachine()
    c = s.client
    c.set_lut(0, ["#000000", "#ff0000"])
    pad = c.create_pad(10, 10, 1)
    c.map(0, pad)
    assert s.executor.frame_copy() is None
    c.clear(pad, 1)
    c.wait_frame()
    shown, snap = s.executor.last_frame, s.executor.frame_copy()
    c.clear(pad, 0)
    c.wait_frame()
    assert s.executor.last_frame is shown  # the same buffer, now holding the new frame
    assert tuple(shown[0, 0]) == (0, 0, 0) and tuple(snap[0, 0]) == (255, 0, 0)


def test_strict_run_records_and_replays_on_strict_memory(tmp_path, capsys) -> None:
    rec, a, b = tmp_path / "s.rec", tmp_path / "a.png", tmp_path / "b.png"
    assert main(["rainbow", "run", "--headless", "--strict", "--stop-after", "6", "--record",
                 str(rec), "--screenshot", str(a), "--screenshot-frame", "6"]) == 0
    assert main(["rainbow", "replay", str(rec), "--headless", "--strict", "--screenshot",
                 str(b)]) == 0
    assert "0 mismatches" in capsys.readouterr().out
    from PIL import Image

    assert np.array_equal(np.asarray(Image.open(a)), np.asarray(Image.open(b)))
