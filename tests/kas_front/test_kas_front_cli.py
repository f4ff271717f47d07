"""``camlab88 kas edit|path|view|export`` headless, end to end."""

from __future__ import annotations

import numpy as np
from PIL import Image

from camlab88.apps.kas import files
from camlab88.cli import main
from tests.kas_front.helpers import DATA, model_only

ROOT_EXAMPLES = DATA.parents[2] / "examples" / "kas"


def test_edit_headless_saves_and_screenshots(tmp_path, capsys) -> None:
    key, shot = tmp_path / "k.kas", tmp_path / "shot.png"
    assert main(["kas", "edit", str(key), "--script", str(DATA / "edit_all.txt"),
                 "--headless", "--seed", "1"]) == 0
    out = capsys.readouterr().out
    assert f"created {key}" in out and f"saved {key}" in out and "characters to the Sigma" in out
    got = files.load_keyframe(key)
    want = model_only("edit_all.txt").drawing
    assert [len(c) for c in got.chains] == [len(c) for c in want.chains]
    # a screenshot run of a new file shows the same screen and writes nothing but the PNG
    other = tmp_path / "new.kas"
    assert main(["kas", "edit", str(other), "--script", str(DATA / "edit_all.txt"),
                 "--headless", "--seed", "1", "--screenshot", str(shot)]) == 0
    assert "screenshot run: nothing saved" in capsys.readouterr().out
    assert not other.exists()
    img = np.asarray(Image.open(shot))
    assert img.shape == (512, 768, 3) and img.any()
    # editing it again starts from the saved file
    assert main(["kas", "edit", str(key), "--script", str(DATA / "white.txt"), "--headless",
                 "--background", "white"]) == 0
    assert "7 chains" in capsys.readouterr().out


def test_edit_errors(tmp_path, capsys) -> None:
    assert main(["kas", "edit", str(tmp_path / "k.kas"), "--headless"]) == 2
    assert "--headless needs --script" in capsys.readouterr().err
    bad = tmp_path / "bad.txt"
    bad.write_text("move 0 0\nfly 1 2\n")
    assert main(["kas", "edit", str(tmp_path / "k.kas"), "--script", str(bad),
                 "--headless"]) == 2
    assert "bad.txt:2:" in capsys.readouterr().err


def test_path_headless(tmp_path, capsys) -> None:
    p = tmp_path / "p.kas"
    assert main(["kas", "path", "walk_a", "walk_b", "--out", str(p), "--script",
                 str(DATA / "path.txt"), "--headless"]) == 0
    assert len(files.load_path(p).points) == 6
    assert len(files.load_timing(tmp_path / "p_ticks.kas").values) == 4
    assert "4 ticks" in capsys.readouterr().out


def test_view_headless_counts_and_frames(tmp_path, capsys) -> None:
    seq = tmp_path / "d.kas"
    assert main(["kas", "demo", "--out", str(seq)]) == 0
    capsys.readouterr()
    assert main(["kas", "view", str(seq), "--headless", "--realtime"]) == 0
    slow = capsys.readouterr().out
    assert main(["kas", "view", str(seq), "--headless", "--baud", "38400", "--frames",
                 str(tmp_path / "f")]) == 0
    fast = capsys.readouterr().out
    n_slow = int(slow.split(": ")[1].split()[0])
    n_fast = int(fast.split(": ")[1].split()[0])
    assert n_slow < n_fast
    # the characters reported are those really sent: dropped frames never go down the line
    from camlab88.apps.kas.program.viewer import LineTest

    test = LineTest(files.load_sequence(seq))
    rep = test.run("realtime", 9600)
    sizes = test.sizes()
    assert rep.frame_chars == sum(sizes[j] for j in rep.shown_frames) < sum(sizes)
    assert f"{rep.frame_chars} characters sent for the frames shown" in slow
    assert len(list((tmp_path / "f").glob("frame_*.png"))) >= 25
    assert main(["kas", "view", str(seq), "--headless", "--every", "--swap", "mask"]) == 0
    assert "28 shown, 0 dropped" in capsys.readouterr().out


def test_export_through_the_sigma(tmp_path, capsys) -> None:
    seq = tmp_path / "d.kas"
    assert main(["kas", "demo", "--out", str(seq)]) == 0
    assert main(["kas", "export", str(seq), str(tmp_path / "o.png")]) == 0
    assert "sigma renderer" in capsys.readouterr().out
    img = np.asarray(Image.open(tmp_path / "o_0001.png"))
    assert img.shape == (512, 768, 3) and img.any()
    assert len(list(tmp_path.glob("o_*.png"))) == 28


def test_edit_in_a_window_dummy_driver(tmp_path, capsys) -> None:
    """The windowed loop (SDL dummy driver): script events and the window's input together."""
    shot = tmp_path / "w.png"
    assert main(["kas", "edit", str(tmp_path / "k.kas"), "--script",
                 str(DATA / "white.txt"), "--screenshot", str(shot)]) == 0
    assert "screenshot" in capsys.readouterr().out
    img = np.asarray(Image.open(shot).convert("RGB"))
    assert img.shape == (512, 768, 3) and img.any()
    assert main(["kas", "view", "walk_ticks", "--screenshot", str(shot)]) == 2  # not a sequence


def test_failed_f2_save_keeps_editing_and_says_not_saved(tmp_path, capsys) -> None:
    # F2 into a directory that does not exist: an OSError on the message line, the drawing
    # stays, the script goes on drawing, the summary does not claim "saved", and the run
    # exits 1 saying why (a script run must not report success when its save failed).
    script = tmp_path / "s.txt"
    script.write_text("down 0 0\nup 0 0\ndown 1 1\nup 1 1\nkey f2\ndown 2 0\nup 2 0\n"
                      "key space\n")
    target = tmp_path / "missing" / "k.kas"
    assert main(["kas", "edit", str(target), "--script", str(script), "--headless"]) == 1
    said = capsys.readouterr()
    assert "1 chains, 3 points" in said.out and "NOT saved" in said.out
    # the one output rule's wording (docs/exit_status.md): the missing directory named
    assert f"{target}: NOT saved: no such directory {target.parent}" in said.err
    assert not target.exists()


def test_summary_says_when_later_edits_are_unsaved(tmp_path, capsys) -> None:
    script = tmp_path / "s.txt"
    script.write_text("down 0 0\nup 0 0\ndown 1 1\nup 1 1\nkey f2\ndown 2 0\nup 2 0\n")
    target = tmp_path / "k.kas"
    assert main(["kas", "edit", str(target), "--script", str(script), "--headless"]) == 0
    out = capsys.readouterr().out
    assert "last edits are NOT saved" in out
    assert files.load_keyframe(target).n_points == 2


def test_user_library_and_the_previous_pairs_path(tmp_path, capsys, monkeypatch) -> None:
    lib = tmp_path / "lib"
    monkeypatch.setenv("CAMLAB88_KAS_LIBRARY", str(lib))
    # draw the path for (walk_a, walk_b): kept in the user library under the pair's name
    assert main(["kas", "path", "walk_a", "walk_b", "--out", str(tmp_path / "p.kas"),
                 "--script", str(DATA / "path.txt"), "--headless"]) == 0
    assert "previous pair" not in capsys.readouterr().out
    kept = lib / "pair_walk_a--walk_b_path.kas"
    assert files.load_path(kept).points.tolist() == \
        files.load_path(tmp_path / "p.kas").points.tolist()
    assert (lib / "pair_walk_a--walk_b_ticks.kas").exists()
    # the next pair (walk_b, walk_a) shows that path automatically (under a new one)
    other = tmp_path / "other.txt"
    other.write_text("move -4 2.5\ndown -4 2.5\ndown 0 3\ndown 4 2.5\nup 4 2.5\n")
    shot = tmp_path / "next.png"
    assert main(["kas", "path", "walk_b", "walk_a", "--out", str(tmp_path / "q.kas"),
                 "--script", str(other), "--headless", "--screenshot", str(shot)]) == 0
    assert f"showing the previous pair's path {kept}" in capsys.readouterr().out
    plain = tmp_path / "plain.png"
    assert main(["kas", "path", "walk_b", "walk_a", "--out", str(tmp_path / "r.kas"),
                 "--script", str(other), "--headless", "--no-library",
                 "--screenshot", str(plain)]) == 0
    # the previous pair's path is on the Sigma's screen only when it was looked up
    assert (np.asarray(Image.open(shot)) != np.asarray(Image.open(plain))).any()
    # listing and saving by name; the saved name resolves wherever a file is asked for
    assert main(["kas", "library", "--save", str(tmp_path / "p.kas"), "my_arc"]) == 0
    capsys.readouterr()
    assert main(["kas", "library"]) == 0
    out = capsys.readouterr().out
    assert "my_arc" in out and "user" in out and "walk_a" in out and "shipped" in out
    seq = tmp_path / "s.kas"
    assert main(["kas", "inbetween", "walk_a", "walk_b", "--path", "my_arc", "--frames", "4",
                 "--out", str(seq)]) == 0
    bad = tmp_path / "bad.kas"
    bad.write_text("KAS path 1\npoints 2\n0 0\nend\n")
    assert main(["kas", "library", "--save", str(bad), "x"]) == 2
    assert "bad.kas" in capsys.readouterr().err and not (lib / "x.kas").exists()


def test_closing_the_window_with_unsaved_edits_warns_once(tmp_path, capsys, monkeypatch) -> None:
    from camlab88.emulator.host_input import Quit
    from camlab88.emulator.window import Window

    polls: list[int] = []
    quits: list[int] = []

    def poll(self) -> list:
        polls.append(1)
        if len(polls) < 20:  # let the script's drawing arrive first
            return []
        quits.append(len(polls))
        return [Quit()]

    monkeypatch.setattr(Window, "poll", poll)
    script = tmp_path / "s.txt"
    script.write_text("down 0 0\nup 0 0\ndown 1 1\nup 1 1\n")
    target = tmp_path / "k.kas"
    assert main(["kas", "edit", str(target), "--script", str(script)]) == 0
    assert len(quits) == 2  # the first close only warned; the second one closed
    out = capsys.readouterr().out
    assert "1 chains, 2 points" in out and "NOT saved" in out
    assert files.load_keyframe(target).chains == []  # created empty on opening, never saved
    # nothing drawn: the first close closes
    polls.clear()
    quits.clear()
    script.write_text("move 0 0\n")
    assert main(["kas", "edit", str(target), "--script", str(script)]) == 0
    assert len(quits) == 1


def test_saving_over_a_library_entry_needs_force(tmp_path, capsys, monkeypatch) -> None:
    lib = tmp_path / "lib"
    monkeypatch.setenv("CAMLAB88_KAS_LIBRARY", str(lib))
    first, second = tmp_path / "a.kas", tmp_path / "b.kas"
    assert main(["kas", "path-script", "walk_a", "walk_b", str(ROOT_EXAMPLES / "arc.script"),
                 "--path-out", str(first), "--timing-out", str(tmp_path / "t.kas")]) == 0
    second.write_text(first.read_text().replace("\n0", "\n1", 1))
    assert main(["kas", "library", "--save", str(first), "my_arc"]) == 0
    kept = (lib / "my_arc.kas").read_bytes()
    capsys.readouterr()
    assert main(["kas", "library", "--save", str(second), "my_arc"]) == 2
    err = capsys.readouterr().err
    assert "my_arc is already in your library" in err and "--force" in err
    assert (lib / "my_arc.kas").read_bytes() == kept
    assert main(["kas", "library", "--save", str(second), "my_arc", "--force"]) == 0
    assert (lib / "my_arc.kas").read_bytes() == second.read_bytes()


def test_the_editor_drives_a_t5684_at_9600_baud_by_default(tmp_path, monkeypatch) -> None:
    # §3.1, §3.1.4: the KAS programs ran on a Sigma T5684 over a 9600-baud line
    from camlab88.emulator import machine

    made = []
    real = machine.SigmaMachine

    def recording(model, settings, *a, **kw):
        made.append((model, settings.baud))
        return real(model, settings, *a, **kw)

    monkeypatch.setattr(machine, "SigmaMachine", recording)
    assert main(["kas", "edit", str(tmp_path / "k.kas"), "--script",
                 str(DATA / "white.txt"), "--headless"]) == 0
    assert made == [("t5684", 9600)]
