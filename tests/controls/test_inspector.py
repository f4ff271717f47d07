"""The inspector's panels (--inspect-out) as golden images: a Sigma whose LUT cycles (the
swatches change, the planes do not) and a Rainbow scene (bands, memory, pad graph)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from camlab88.cli import main
from tests.support.golden import assert_matches_golden

DATA = Path(__file__).resolve().parents[1] / "data"
GOLDEN = DATA / "controls" / "golden"
SCENE = DATA / "rainbow" / "golden_scene.json"
ROOT_EXAMPLES = DATA.parents[1] / "examples" / "sigma"


def lut_animation() -> bytes:
    """Six colour bars drawn once, then the LUT rotated a step at a time (12 steps)."""
    from camlab88.protocols.sigma.encoder import Encoder

    e = Encoder()
    out = bytearray(e.flag() + e.reset())
    for i in range(6):
        out += e.colour(i + 1) + e.move(40 + 110 * i, 60) + e.block(130 + 110 * i, 400)
    hues = [(15, 0, 0), (15, 15, 0), (0, 15, 0), (0, 15, 15), (0, 0, 15), (15, 0, 15)]
    for step in range(12):
        for i in range(6):
            out += e.lut(i + 1, *hues[(i + step) % 6])
        out += e.order("HI", 1) * 40  # line time between steps (no change on the screen)
    return bytes(out)


def png(path: Path) -> np.ndarray:
    return np.asarray(Image.open(path).convert("RGB"))


@pytest.fixture(scope="module")
def sigma_panels(tmp_path_factory) -> Path:
    tmp = tmp_path_factory.mktemp("sigma")
    (tmp / "lut.bin").write_bytes(lut_animation())
    assert main(["sigma", "render", "--in", str(tmp / "lut.bin"), "--inspect-out",
                 str(tmp / "panels"), "--video", str(tmp / "lut.mp4")]) == 0
    return tmp


def test_sigma_lut_animation_panels_are_golden(sigma_panels) -> None:
    panels = sorted((sigma_panels / "panels").iterdir())
    assert len(panels) > 12
    first, last = png(panels[0]), png(panels[-1])
    assert first.shape == (512, 384, 3)
    assert_matches_golden(png(panels[len(panels) // 2]), GOLDEN / "sigma_lut_middle.png")
    assert_matches_golden(last, GOLDEN / "sigma_lut_last.png")
    # the swatches took each of the six rotations (and frames caught mid-rotation); the
    # planes (drawn once, early) did not
    swatches, planes = slice(30, 60), slice(80, 160)
    later = [png(p) for p in panels[len(panels) // 2:]]
    assert len({p[swatches].tobytes() for p in later}) >= 6
    assert all(np.array_equal(p[planes], last[planes]) for p in later)


def test_sigma_render_video_has_a_frame_per_panel(sigma_panels) -> None:
    imageio_ffmpeg = pytest.importorskip("imageio_ffmpeg", reason="--video needs it")
    frames, _ = imageio_ffmpeg.count_frames_and_secs(str(sigma_panels / "lut.mp4"))
    assert frames == len(list((sigma_panels / "panels").iterdir()))


def test_rainbow_scene_panel_is_golden(tmp_path) -> None:
    assert main(["rainbow", "render", str(SCENE), "--out", str(tmp_path / "scene.png"),
                 "--inspect-out", str(tmp_path / "panel")]) == 0
    panel = png(tmp_path / "panel" / "frame_00000.png")
    assert panel.shape == (576, 384, 3)
    assert_matches_golden(panel, GOLDEN / "rainbow_scene.png")


def test_pad_graph_tree_names_every_arc_with_its_offset() -> None:
    from camlab88.emulator.inspect.rainbow import tree_lines
    from camlab88.emulator.rainbow import Rainbow
    from camlab88.emulator.rainbow.scene import load_scene

    device = load_scene(str(SCENE), Rainbow())
    lines = tree_lines(device.graph)
    assert lines[0] == "screen 768x576"
    assert len([ln for ln in lines if " > " in ln]) == len(device.graph.arcs)
    arc = next(iter(device.graph.arcs.values()))
    assert any(f"a{arc.id} {arc.x:+d},{arc.y:+d} p{arc.priority}" in ln for ln in lines)


def test_a_program_without_a_known_device_is_told_so() -> None:
    from camlab88.emulator.inspect import panel_for

    assert panel_for(object()) is None


def test_the_inspector_changes_nothing_the_device_shows(tmp_path) -> None:
    """Its order list comes from a tracer in front of the terminal's feed (byte by byte):
    every frame equals the frame of a run without it."""
    stream = ROOT_EXAMPLES / "crystals_cameron.sig"
    assert main(["sigma", "render", "--in", str(stream), "--frames", str(tmp_path / "plain"),
                 "--fps", "25"]) == 0
    assert main(["sigma", "render", "--in", str(stream), "--frames", str(tmp_path / "seen"),
                 "--fps", "25", "--inspect-out", str(tmp_path / "panels")]) == 0
    plain = sorted((tmp_path / "plain").iterdir())
    seen = sorted((tmp_path / "seen").iterdir())
    assert [p.name for p in plain] == [p.name for p in seen] and len(plain) > 5
    assert all(np.array_equal(png(a), png(b)) for a, b in zip(plain, seen))
    assert len(list((tmp_path / "panels").iterdir())) == len(seen)
