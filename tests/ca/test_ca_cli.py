"""``camlab88 ca run / convert / replay / library`` headless."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from camlab88.apps.ca import log
from camlab88.apps.ca.library import rules_path
from camlab88.cli import main


def _json_last(capsys) -> dict:
    return json.loads(capsys.readouterr().out.strip().splitlines()[-1])


def test_run_life_gun_json(capsys) -> None:
    assert main(["ca", "run", "--rules", "life", "--pattern", "gosper_gun",
                 "--generations", "60", "--json"]) == 0
    stats = _json_last(capsys)
    assert stats["generation"] == 60 and stats["population"] == 46
    assert stats["by_type"] == {"1": 46}
    x0, y0, x1, y1 = stats["bbox"]
    assert (x0, y0) == (32768, 32768) and x1 > x0 and y1 > y0


def test_run_with_paths_edges_seed_and_every(tmp_path: Path, capsys) -> None:
    rules = tmp_path / "coin.rules"
    rules.write_text("1 0 0 0 0 |1 $ 1 50% 1 50% 2\n")
    pat = tmp_path / "row.rle"
    pat.write_text("x = 20, y = 1\n20o!\n")
    args = ["ca", "run", "--rules", str(rules), "--pattern", str(pat), "--generations", "1",
            "--json", "--edges", "bounded"]
    assert main([*args, "--seed", "1"]) == 0
    a = _json_last(capsys)
    assert main([*args, "--seed", "1"]) == 0
    assert _json_last(capsys) == a
    assert set(a["by_type"]) == {"1", "2"}
    assert main(["ca", "run", "--rules", "life", "--pattern", "glider", "--generations", "8",
                 "--every", "4"]) == 0
    out = capsys.readouterr().out.splitlines()
    assert len(out) == 2 and out[0].startswith("generation 4 ") and "population 5" in out[1]


def test_run_errors_name_the_file(tmp_path: Path, capsys) -> None:
    bad = tmp_path / "bad.rules"
    bad.write_text("1 1 1 1 1\n+1 +1\n$")
    assert main(["ca", "run", "--rules", str(bad), "--pattern", "glider",
                 "--generations", "1"]) == 2
    assert f"{bad}:2:1: message grid has 2 entries" in capsys.readouterr().err
    assert main(["ca", "run", "--rules", "nothing", "--pattern", "glider",
                 "--generations", "1"]) == 2
    assert "no rules file or library entry named 'nothing'" in capsys.readouterr().err


def test_convert_and_library(tmp_path: Path, capsys) -> None:
    out = tmp_path / "gun.cells"
    assert main(["ca", "convert", "gosper_gun", str(out)]) == 0
    assert out.read_text().count("O") == 36
    assert main(["ca", "convert", "primes_25", str(tmp_path / "p.cells")]) == 2
    assert "one life-form" in capsys.readouterr().err
    assert main(["ca", "library"]) == 0
    assert "life" in capsys.readouterr().out


def test_replay_command(tmp_path: Path, capsys) -> None:
    path = str(tmp_path / "s.log")
    w = log.LogWriter(path)
    w.add(log.ev_rules(0, "life", Path(rules_path("life")).read_text()))
    for x, y in ((1, 0), (2, 1), (0, 2), (1, 2), (2, 2)):
        w.add(log.ev_edit(0, 100 + x, 100 + y, 1))
    assert main(["ca", "replay", "--script", path, "--generation", "40", "--json"]) == 0
    stats = _json_last(capsys)
    assert stats["population"] == 5 and stats["bbox"] == [110, 110, 112, 112]


@pytest.mark.parametrize("sub", ["run", "convert", "replay", "library"])
def test_help(sub: str, capsys) -> None:
    with pytest.raises(SystemExit) as info:
        main(["ca", sub, "--help"])
    assert info.value.code == 0
    assert "usage" in capsys.readouterr().out


def test_png_rendering_uses_rule_colours(tmp_path: Path) -> None:
    from PIL import Image

    out = tmp_path / "maze.png"
    assert main(["ca", "run", "--rules", "maze", "--pattern", "maze_demo", "--generations", "0",
                 "--png", str(out), "--zoom", "8"]) == 0
    img = Image.open(out).convert("RGB")
    colours = {c for _, c in img.getcolors(1 << 16)}
    assert {(0, 255, 0), (255, 0, 0), (0, 0, 255), (0, 0, 0)} <= colours


def test_replay_uses_the_logged_edges_and_warns_about_disagreeing_flags(tmp_path: Path,
                                                                        capsys) -> None:
    path = str(tmp_path / "b.log")
    w = log.LogWriter(path, settings=log.LogSettings("bounded", 5))
    w.add(log.ev_rules(0, "life", Path(rules_path("life")).read_text()))
    for x, y in ((1, 1), (2, 1), (3, 1), (1, 2), (2, 3)):  # a glider heading up-left
        w.add(log.ev_edit(0, x, y, 1))
    assert main(["ca", "replay", "--script", path, "--generation", "16", "--json"]) == 0
    bounded = _json_last(capsys)
    assert main(["ca", "replay", "--script", path, "--generation", "16", "--json",
                 "--edges", "wrap"]) == 0
    out = capsys.readouterr()
    assert json.loads(out.out.strip().splitlines()[-1]) == bounded
    assert "recorded with edges bounded" in out.err
    # the glider broke up on the bounded edge instead of wrapping round
    assert bounded["population"] != 5 or bounded["bbox"][0] < 65000


COIN_RULES = """1 1 1 1 1 +1 +1 +1 +1 |16 +1 +1 +1 +1 $
#X12 1  #X13 1  3 50% 1 50% 0  #X11 50% 1 50% 0
"""
STEPS = "press middle 300 300\nrelease middle 300 300\nframes 1\n" + \
    "click right 600 500\nframes 2\n" * 12


@pytest.mark.claim("§8.1: the animator decides whether the random numbers are repeatable; "
                   "truly random ones give different runs, which contradicts replaying a "
                   "sequence from the log file", measured="ca program --random: two runs "
                   "draw different seeds from the operating system; each run's log header "
                   "and its recording carry the seed, and the recording replays with "
                   "--check; --seed stays the repeatable choice",
                   verdict="agrees (the seed written down is ours: it lets a truly random "
                   "run be replayed after all)")
def test_truly_random_program_runs_differ_and_replay(tmp_path: Path, capsys,
                                                      monkeypatch) -> None:
    monkeypatch.chdir(tmp_path)
    (tmp_path / "coin.rules").write_text(COIN_RULES)
    (tmp_path / "steps.events").write_text(STEPS)
    seeds = []
    for k in (1, 2):
        assert main(["ca", "program", "--rules", "coin.rules", "--pattern", "r_pentomino",
                     "--random", "--headless", "--events", "steps.events", "--log",
                     f"s{k}.log", "--record", f"r{k}.session"]) == 0
        out = capsys.readouterr().out
        seed = int(out.split("truly random outcomes: seed ")[1].split()[0])
        assert f"seed {seed}" in (tmp_path / f"s{k}.log").read_text().splitlines()[:3]
        from camlab88.protocols.session import read

        argv = read(tmp_path / f"r{k}.session").argv
        assert "--random" not in argv and argv[argv.index("--seed") + 1] == str(seed)
        seeds.append(seed)
    assert seeds[0] != seeds[1]  # 30 bits from the OS: equal once in 10**9
    assert main(["replay", "r1.session", "--headless", "--check"]) == 0
    assert "screen hashes agree" in capsys.readouterr().out
    assert main(["ca", "program", "--random", "--seed", "3", "--headless"]) == 2
    assert "--random or --seed, not both" in capsys.readouterr().err
