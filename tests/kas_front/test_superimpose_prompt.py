"""``kas superimpose --prompt``: the timings asked on entry on the Sigma (§3.1.3), answered by
a scripted keyboard; the bird-and-flower example's 20-frame start."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from camlab88.apps.kas import files
from camlab88.apps.kas.model import AnimSequence, Chain, Drawing
from camlab88.apps.kas.program.superimpose_front import SuperimposeFront
from camlab88.apps.kas.superimpose import superimpose
from camlab88.cli import main


def _seq(n: int, colour: int, dy: float) -> AnimSequence:
    return AnimSequence([Drawing([Chain.from_points([(-2 + 0.1 * k, dy), (0.1 * k, dy + 1)],
                                                    colour)]) for k in range(n)], 25)


def _write(tmp_path: Path) -> tuple[Path, Path]:
    bird, flower = tmp_path / "bird.kas", tmp_path / "flower.kas"
    files.save_sequence(bird, _seq(50, 2, 1.0))
    files.save_sequence(flower, _seq(40, 3, -2.0))
    return bird, flower


def test_prompted_timings_make_the_thesis_composite(tmp_path: Path, capsys) -> None:
    bird, flower = _write(tmp_path)
    script = tmp_path / "answers.script"
    # the flower from the start (Return keeps the default 0); the bird 20 frames later,
    # typed 2, 9, Backspace, 0
    script.write_text("key return\nkey 2\nkey 9\nkey backspace\nkey 0\nkey return\n")
    out, shot = tmp_path / "both.kas", tmp_path / "shot.png"
    assert main(["kas", "superimpose", str(flower), str(bird), "--prompt", "--script",
                 str(script), "--headless", "--out", str(out)]) == 0
    got = files.load_sequence(out)
    want = superimpose([(files.load_sequence(flower), 0), (files.load_sequence(bird), 20)])
    assert len(got) == 70 == len(want)  # 20 still, 20 together, 30 flying on
    for a, b in zip(got.frames, want.frames, strict=True):
        assert [c.points.tolist() for c in a.chains] == [c.points.tolist() for c in b.chains]
    assert f"{out}: 70 frames" in capsys.readouterr().out
    # a screenshot run of the same answers shows the composite and writes no file
    assert main(["kas", "superimpose", str(flower), str(bird), "--prompt", "--script",
                 str(script), "--headless", "--out", str(tmp_path / "no.kas"),
                 "--screenshot", str(shot)]) == 0
    assert shot.exists() and not (tmp_path / "no.kas").exists()


def test_defaults_come_from_the_command_line_form(tmp_path: Path) -> None:
    bird, flower = _write(tmp_path)
    script = tmp_path / "enter.script"
    script.write_text("key return\nkey return\n")
    out = tmp_path / "both.kas"
    assert main(["kas", "superimpose", str(flower), f"{bird}@20", "--prompt", "--script",
                 str(script), "--headless", "--out", str(out)]) == 0
    assert len(files.load_sequence(out)) == 70


def test_unanswered_prompts_are_an_error(tmp_path: Path, capsys) -> None:
    bird, flower = _write(tmp_path)
    script = tmp_path / "short.script"
    script.write_text("key 5\nkey return\n")
    assert main(["kas", "superimpose", str(flower), str(bird), "--prompt", "--script",
                 str(script), "--headless", "--out", str(tmp_path / "x.kas")]) == 2
    assert "the script answers 1 of 2 start prompts" in capsys.readouterr().err
    assert not (tmp_path / "x.kas").exists()


def test_the_prompt_is_on_the_message_line() -> None:
    front = SuperimposeFront([("flower", _seq(40, 3, 0), 0), ("bird", _seq(50, 2, 0), 7)])
    assert front.message == "start of flower (40 frames), frames after the start [0]: "
    front.on_key("return")
    front.on_key("3")
    assert front.message == "start of bird (50 frames), frames after the start [7]: 3"
    assert front.message in [p.text for p in front.prims() if p.kind == "text"]
    front.on_key("return")
    assert front.done and front.starts == [0, 3] and len(front.result) == 53
    assert np.asarray(front.result.frames[0].chains[0].points).shape == (2, 2)
