"""What a newcomer sees: bare ``camlab88`` prints the help, a misspelt command
gets "did you mean", ``demo --help`` names every act, commands say what they wrote."""

from __future__ import annotations

from pathlib import Path

import pytest

from camlab88.cli import main

ROOT = Path(__file__).resolve().parents[2]


def test_bare_camlab88_prints_the_help(capsys) -> None:
    assert main([]) == 0
    assert "usage: camlab88" in capsys.readouterr().out


@pytest.mark.parametrize("argv, hint", [(["snoker"], "did you mean 'snooker'?"),
                                        (["kas", "edti"], "did you mean 'edit'?")])
def test_misspelt_commands_get_did_you_mean(argv: list[str], hint: str, capsys) -> None:
    with pytest.raises(SystemExit):
        main(argv)
    assert hint in capsys.readouterr().err


def test_demo_help_describes_every_act(capsys) -> None:
    from camlab88.commands.demo.acts import ACTS

    with pytest.raises(SystemExit):
        main(["demo", "--help"])
    out = " ".join(capsys.readouterr().out.split())
    for act in ACTS:
        assert f"{act.name}: {' '.join(act.about.split())[:30]}" in out


def test_commands_name_what_they_wrote(tmp_path: Path, capsys) -> None:
    scene = ROOT / "examples" / "rainbow" / "scene.json"
    assert main(["rainbow", "render", str(scene), "--out", str(tmp_path / "s.png")]) == 0
    assert f"wrote {tmp_path / 's.png'}" in capsys.readouterr().out
    assert main(["ca", "convert", "glider", str(tmp_path / "g.rle")]) == 0
    assert f"wrote {tmp_path / 'g.rle'}" in capsys.readouterr().out
    assert main(["kas", "demo", "--out", str(tmp_path / "d.kas")]) == 0
    assert main(["kas", "export", str(tmp_path / "d.kas"), str(tmp_path / "d.png"),
                 "--renderer", "raster", "--width", "64"]) == 0
    out = capsys.readouterr().out
    assert "frames, " in out and "d_0001.png .. d_" in out


def test_a_text_file_rendered_as_a_sigma_stream_is_named(tmp_path: Path, capsys) -> None:
    text = tmp_path / "notes.txt"
    text.write_text("just some words\n")
    assert main(["sigma", "render", "--in", str(text), "--out", str(tmp_path / "n.png")]) == 0
    assert "drew nothing: is it a Sigma stream?" in capsys.readouterr().err


def test_library_save_of_a_missing_file_says_how_to_make_it(tmp_path: Path, capsys) -> None:
    assert main(["kas", "library", "--save", str(tmp_path / "p.kas"), "my_arc"]) == 2
    assert "does not exist: make it first" in capsys.readouterr().err
