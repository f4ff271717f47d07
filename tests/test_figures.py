"""The thesis's screen figures as shipped recordings (examples/figures): every one replays
with --check, each was made from a script kept beside it with ordinary program options, and
``camlab88 figures`` lists them and writes one's last screen headless."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

from camlab88.commands.figures import FIGURES_DIR
from camlab88.figure_catalogue import CatalogueError, by_number, markdown_table, parse
from camlab88.protocols.session import read

CAPTIONS = by_number()

ROOT = Path(__file__).resolve().parents[1]
SHIPPED = sorted(FIGURES_DIR.glob("fig-*.session"))
ALLOWED = {"--headless", "--events", "--record", "--pattern", "--rules", "--script",
           "--background", "--ops", "--baud", "--seed",
           "--out", "--no-library",  # kas path's --out: a replay writes it to its scratch
           "--model", "--in", "--seconds",  # sigma run fed a stream the maker computed
           "--inspect"}  # Appendix I fig. 2: the pad graph beside the screen


def _cli(*args: str, cwd: Path) -> subprocess.CompletedProcess[str]:
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    for k in ("DISPLAY", "WAYLAND_DISPLAY", "SDL_VIDEODRIVER"):
        env.pop(k, None)
    return subprocess.run([sys.executable, "-m", "camlab88", *args], cwd=cwd, env=env,
                          capture_output=True, text=True, timeout=300)


def test_every_recording_is_a_listed_figure_with_its_script() -> None:
    assert SHIPPED, "no figure recordings ship"
    maker = (FIGURES_DIR / "make_figures.py").read_text(encoding="utf-8")
    for path in SHIPPED:
        number = path.stem.removeprefix("fig-")
        assert number in CAPTIONS, path.name
        assert f'"{number}": (' in maker, f"{number} is not made by make_figures.py"
        scripts = [FIGURES_DIR / "scripts" / f"fig-{number}.{ext}" for ext in ("events", "script")]
        from_inputs = f'"{number}": (VISUALISE, None)' in maker or \
            f'"{number}": (SIGMA, None)' in maker
        assert any(s.is_file() for s in scripts) or from_inputs


def test_every_screen_figure_ships() -> None:
    assert [p.stem.removeprefix("fig-") for p in SHIPPED] == sorted(CAPTIONS)


@pytest.mark.parametrize("path", SHIPPED, ids=[p.stem for p in SHIPPED])
def test_figure_recording_replays_with_check(path: Path, tmp_path: Path,
                                             capsys: pytest.CaptureFixture[str],
                                             monkeypatch: pytest.MonkeyPatch) -> None:
    rec = read(path)
    opts = {a.split("=")[0] for a in rec.argv if a.startswith("--")}
    assert opts <= ALLOWED, f"{path.name}: options beyond ordinary program ones: {opts - ALLOWED}"
    assert path.stat().st_size < 400_000  # kilobytes, not megabytes
    from camlab88.cli import main

    monkeypatch.chdir(tmp_path)  # in process (a fresh interpreter per figure would double the time)
    assert main(["replay", str(path), "--headless", "--check"]) == 0
    assert "screen hashes agree" in capsys.readouterr().out


def test_figures_lists_and_writes_a_png_headless(tmp_path: Path) -> None:
    r = _cli("figures", cwd=tmp_path)
    assert r.returncode == 0 and all(f"fig {n}" in r.stdout for n in CAPTIONS)
    number = SHIPPED[0].stem.removeprefix("fig-")
    r = _cli("figures", number, cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    png = tmp_path / f"fig-{number}.png"
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert "no display; running headless" in r.stderr
    fig = CAPTIONS[number]
    assert f"thesis {fig.section_label}, figure {number}: {fig.caption}" in r.stdout
    r = _cli("figures", "9.9", cwd=tmp_path)
    assert r.returncode == 2 and "no screen figure '9.9'" in r.stderr


def test_docs_table_is_the_catalogues() -> None:
    """docs/figures.md's table is made from camlab88/figure_catalogue.toml (make_figures.py
    --docs): the one place the figures' captions, sections and differences live."""
    doc = (ROOT / "docs" / "figures.md").read_text(encoding="utf-8")
    assert markdown_table() in doc, "run: python examples/figures/make_figures.py --docs"


def test_catalogue_entries_are_whole() -> None:
    for fig in CAPTIONS.values():
        assert fig.caption and fig.section and fig.shows, fig.number
        assert (fig.verdict == "agrees") == (fig.differs == ""), fig.number


@pytest.mark.parametrize(("text", "says"), [
    ("version = 2\n", "version 2"),
    ("version = 1\n[[figure]]\nnumber = \"1.1\"\n", "figure entry 1"),
    ("version = 1\n[[figure]]\nnumber = \"1.1\"\nsection = \"1\"\ncaption = \"c\"\n"
     "short = \"s\"\nverdict = \"agrees\"\nshows = \"x\"\ndiffers = \"but\"\n",
     "figure 1.1: say what differs"),
    ("version = [", "cat.toml:"),
])
def test_damaged_catalogue_is_named(text: str, says: str) -> None:
    with pytest.raises(CatalogueError, match=says.replace(".", r"\.")):
        parse(text, "cat.toml")


def test_appendix_i_figure_shows_the_pad_graph_beside_the_screen(tmp_path: Path) -> None:
    """Appendix I fig. 2 is the screen and its pad structure: the figure's PNG is the
    Rainbow's 768-pixel screen with the inspector's panel (the pad graph) to its right."""
    from PIL import Image

    from camlab88.emulator.inspect import PANEL_WIDTH

    r = _cli("figures", "I.2", "--headless", "--screenshot", "i2.png", cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    with Image.open(tmp_path / "i2.png") as img:
        assert img.size == (768 + PANEL_WIDTH, 576)
    assert "differs: Kathy Carter's sample screen" in r.stdout  # where and why it differs
