"""``camlab88 kas ...`` end to end on the shipped library, and its error messages."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from camlab88.apps.kas import demo, files
from camlab88.apps.kas.events import Key, MenuPick, Pointer, parse_script
from camlab88.apps.kas.files import KasFileError
from camlab88.cli import main
from tests.support.refusals import refusal_of


def test_pipeline(tmp_path, capsys):
    walk, sun, both = tmp_path / "w.kas", tmp_path / "s.kas", tmp_path / "ws.kas"
    assert main(["kas", "inbetween", "walk_a", "walk_b", "--path", "walk_path", "--timing",
                 "walk_ticks", "--out", str(walk)]) == 0
    assert main(["kas", "inbetween", "sun_a", "sun_b", "--timing", "ease-in-out",
                 "--frames", "20", "--out", str(sun)]) == 0
    assert main(["kas", "superimpose", str(walk), f"{sun}@8", "--out", str(both)]) == 0
    seq = files.load_sequence(both)
    assert len(seq) == 28
    assert seq.frames[-1].equals(demo.build().frames[-1])
    assert main(["kas", "plot", str(both), "--hpgl", str(tmp_path / "h"), "--svg",
                 str(tmp_path / "v"), "--pdf", str(tmp_path / "p")]) == 0
    assert len(list((tmp_path / "h").iterdir())) == 28
    assert (tmp_path / "p" / "sequence.pdf").exists()
    assert main(["kas", "export", str(both), str(tmp_path / "o.gif"), "--width", "64"]) == 0
    assert main(["kas", "inbetween", "walk_a", "walk_b", "sun_a", "--frames", "4",
                 "--method", "kochanek-bartels", "--tension", "0.5", "--out",
                 str(tmp_path / "m.kas")]) == 0
    assert len(files.load_sequence(tmp_path / "m.kas")) == 7


def test_schedule_command(capsys):
    assert main(["kas", "schedule", ",".join(["300"] * 10)]) == 0
    out = capsys.readouterr().out
    assert "3 shown, 7 dropped" in out and "dropped: 2 3 4 5 6 8 9" in out


def test_errors_name_file_and_line(tmp_path, capsys):
    bad = tmp_path / "bad.kas"
    bad.write_text("KAS keyframe 1\nchains 1\nchain section=0 points=2\n0 0 1\n")
    assert main(["kas", "inbetween", str(bad), "walk_b", "--frames", "3", "--out",
                 str(tmp_path / "o.kas")]) == 2
    assert f"{bad}:4: file ends early" in capsys.readouterr().err
    assert not (tmp_path / "o.kas").exists()
    capsys.readouterr()
    assert main(["kas", "superimpose", "x.kas@z", "--out", str(tmp_path / "o.kas")]) == 2
    assert "x.kas@z" in capsys.readouterr().err  # not an offset: the whole is a file name
    assert main(["kas", "plot", "walk_a"]) == 2


def test_edit_script_headless(tmp_path):
    script = tmp_path / "s.txt"
    script.write_text("# draw an L, then edit it\n"
                      "key 2\ndown 0 0\nup 0 0\ndown 0 -2\nup 0 -2\ndown 1 -2\nup 1 -2\n"
                      "key space\nmenu edit\nkey t\ndown 0 0\nup 0 0\ntype 180\nkey return\n")
    out = tmp_path / "o.kas"
    assert main(["kas", "edit-script", str(script), "--out", str(out)]) == 0
    d = files.load_keyframe(out)
    assert np.allclose(d.chains[0].points, [[0, 0], [0, 2], [-1, 2]])
    assert d.chains[0].colours.tolist() == [2, 2, 2]


def test_parse_script():
    ev = parse_script("move 1 2\ndown 1 2\nup 1.5 2\nkey space\nmenu pen3\ntype a b\n")
    assert ev == [Pointer(1, 2, False), Pointer(1, 2, True), Pointer(1.5, 2, False),
                  Key("space"), MenuPick("pen3"), Key("a"), Key("space"), Key("b")]
    try:
        parse_script("move 1\n", "s.txt")
    except ValueError as exc:
        assert str(exc).startswith("s.txt:1:")
    else:
        raise AssertionError("bad script accepted")


def test_library_and_demo_commands(tmp_path, capsys):
    assert main(["kas", "library"]) == 0
    listing = capsys.readouterr().out
    for name in ("walk_a", "walk_b", "walk_path", "walk_ticks", "sun_a", "ease-in-out"):
        assert name in listing
    assert main(["kas", "demo", "--out", str(tmp_path / "d.kas")]) == 0
    seq = files.load_sequence(tmp_path / "d.kas")
    assert len(seq) == 20 + 8 + 0 and len(seq.frames[0].chains) == 3
    walk_a = files.load_keyframe(demo.LIBRARY / "walk_a.kas")
    # the walk's first frame is its keyframe (redundant points aside), sun waits at sun_a
    assert np.allclose(seq.frames[0].chains[1].points, walk_a.chains[1].points)


@settings(max_examples=60, deadline=None)
@given(st.text(max_size=120))
def test_script_parser_only_raises_named_errors(text):
    refusal_of(parse_script, text, "s.txt", KasFileError)


def test_path_script(tmp_path):
    script = tmp_path / "p.txt"
    script.write_text("down 0 0\ndown 1 1\ndown 2 0\nup 2 0\nkey t\n"
                      "down 1 1\nup 1 1\n")
    p, t = tmp_path / "p.kas", tmp_path / "t.kas"
    assert main(["kas", "path-script", "walk_a", "walk_b", str(script), "--path-out", str(p),
                 "--timing-out", str(t)]) == 0
    assert files.load_path(p).points.tolist() == [[0, 0], [1, 1], [2, 0]]
    assert files.load_timing(t).values.tolist() == [0.5]


def test_superimpose_file_names_with_at_signs(tmp_path, capsys):
    src = tmp_path / "take@2.kas"
    assert main(["kas", "inbetween", "sun_a", "sun_b", "--frames", "5", "--out",
                 str(src)]) == 0
    out = tmp_path / "o.kas"
    assert main(["kas", "superimpose", str(src), f"{src}@3", "--out", str(out)]) == 0
    seq = files.load_sequence(out)
    assert len(seq) == 8
    one = files.load_sequence(src)
    assert seq.frames[0].n_points == 2 * one.frames[0].n_points  # second held at its first
