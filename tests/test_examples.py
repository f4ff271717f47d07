"""examples/: up to date with examples/make_examples.py, and each file accepted by the
command that takes it (the README's walkthrough and examples/README.md use them)."""

from __future__ import annotations

import importlib.util
import json
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from camlab88.cli import main

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
HAND_WRITTEN = {"README.md", "make_examples.py"}


def _maker():  # the script's module
    spec = importlib.util.spec_from_file_location("make_examples", EXAMPLES / "make_examples.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@pytest.fixture(scope="module")
def regenerated(tmp_path_factory: pytest.TempPathFactory) -> Path:
    out = tmp_path_factory.mktemp("examples")
    _maker().make(out)
    return out


def _files(root: Path) -> dict[str, bytes]:
    return {str(p.relative_to(root)): p.read_bytes() for p in sorted(root.rglob("*"))
            if p.is_file() and p.name not in HAND_WRITTEN and "__pycache__" not in p.parts
            and p.relative_to(root).parts[0] != "figures"}  # own maker: tests/test_figures.py


def test_examples_are_up_to_date(regenerated: Path) -> None:
    shipped, made = _files(EXAMPLES), _files(regenerated)
    assert sorted(shipped) == sorted(made)
    stale = [name for name in made if made[name] != shipped[name]]
    assert not stale, f"run `python examples/make_examples.py`: {stale} changed"


def test_every_example_is_listed_in_the_examples_readme() -> None:
    listing = (EXAMPLES / "README.md").read_text(encoding="utf-8")
    for name in _files(EXAMPLES):
        assert f"`{name}`" in listing, name


def _png(path: Path) -> np.ndarray:
    return np.asarray(Image.open(path).convert("RGB"))


@pytest.mark.parametrize("stream,model", [("pgplot_goc", "t5684"), ("ral_gks_t5684", "t5684"),
                                          ("ral_gks_t5688", "t5688"),
                                          ("crystals_cameron", "t5684")])
def test_sigma_streams_draw(stream: str, model: str, tmp_path: Path) -> None:
    out = tmp_path / "screen.png"
    assert main(["sigma", "render", "--model", model, "--in",
                 str(EXAMPLES / "sigma" / f"{stream}.sig"), "--out", str(out)]) == 0
    img = _png(out)
    lit = img.reshape(-1, 3).any(axis=1).mean()
    assert 0.002 < lit < 0.5  # a drawing, not a blank or flooded screen
    if stream != "pgplot_goc":  # PGPLOT's GOC driver draws in one colour
        assert len(np.unique(img.reshape(-1, 3), axis=0)) >= 4


def test_the_cameron_polygon_is_filled_from_its_shifted_seed(tmp_path: Path) -> None:
    out = tmp_path / "cameron.png"
    assert main(["sigma", "render", "--in", str(EXAMPLES / "sigma" / "crystals_cameron.sig"),
                 "--out", str(out)]) == 0
    img = _png(out)
    inside = img[512 - 180, 660]  # the square's middle (row 0 = top)
    assert inside[2] > 128 and inside[0] < 64  # blue fill reached it


def test_the_rainbow_scene_renders(tmp_path: Path) -> None:
    out = tmp_path / "scene.png"
    assert main(["rainbow", "render", str(EXAMPLES / "rainbow" / "scene.json"), "--out",
                 str(out)]) == 0
    img = _png(out)
    assert tuple(img[0, 0]) == (0x20, 0x28, 0x30)
    assert tuple(img[188 + 50 + 47, 184 + 150 + 10]) == (0xF0, 0xD0, 0x20)  # on the ring


def test_kas_scripts_make_keyframes_path_and_ticks(tmp_path: Path) -> None:
    a, b = tmp_path / "a.kas", tmp_path / "b.kas"
    kas = EXAMPLES / "kas"
    assert main(["kas", "edit-script", str(kas / "house.script"), "--out", str(a)]) == 0
    assert main(["kas", "edit-script", str(kas / "move.script"), "--start", str(a),
                 "--out", str(b)]) == 0
    assert a.read_text() != b.read_text()
    p, t = tmp_path / "p.kas", tmp_path / "t.kas"
    assert main(["kas", "path-script", str(a), str(b), str(kas / "arc.script"),
                 "--path-out", str(p), "--timing-out", str(t)]) == 0
    assert t.read_text().startswith("KAS timing")


def test_the_ca_log_replays(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["ca", "replay", "--script", str(EXAMPLES / "ca" / "session.log"),
                 "--generation", "8", "--json"]) == 0
    stats = json.loads(capsys.readouterr().out.strip().splitlines()[-1])
    assert stats["generation"] == 8 and stats["population"] == 8  # glider + blinker


def test_the_snooker_session_and_checkpoint_start_shots(tmp_path: Path) -> None:
    snooker = EXAMPLES / "snooker"
    for source in ("opening.json", "break.cp"):
        out = tmp_path / f"{source}.cp"
        assert main(["snooker", "simulate", "--from", str(snooker / source), "--shot", "cue",
                     "1.0", "90", "--out", str(out)]) == 0
        assert out.stat().st_size > 0
