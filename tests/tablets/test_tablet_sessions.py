"""A program session with a tablet, recorded and replayed without the tablet.

``kas edit --tablet SOURCE --record FILE`` puts what the tablet sent on the session's tablet
tape (``T`` wire records); ``replay FILE --check`` decodes the same bytes with the same
decoder at the same polls, never opening the tablet, and every screen hash agrees.
"""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

from camlab88.protocols.session import read, write
from tests.tablets.helpers import DIGIMEND, load_dump
from tests.tablets.umockdev_bed import gaomon_m106k, run_in_bed, skip_reason

SCRIPT = ("0.2 move 0 0\n0.4 down 0 0\n0.6 down 1 1\n0.8 down 2 1\n1.0 up 2 1\n"
          "1.5 key f2\n2.5 wait\n")


def _camlab88(args: list[str], cwd: Path, env: dict | None = None):
    return subprocess.run([sys.executable, "-m", "camlab88", *args], cwd=cwd, text=True,
                          capture_output=True, timeout=180, env=dict(os.environ, **(env or {})))


def _chains(stdout: str) -> tuple[int, int]:
    m = re.search(r"kas edit: (\d+) chains, (\d+) points", stdout)
    assert m, stdout
    return int(m.group(1)), int(m.group(2))


def test_emulated_tablet_session_records_and_replays_from_its_tape(tmp_path: Path) -> None:
    (tmp_path / "s.txt").write_text(SCRIPT)
    env = {"CAMLAB88_CONFIG_DIR": str(tmp_path / "config")}
    done = _camlab88(["kas", "edit", "k.kas", "--tablet", "emulated:summa-mm", "--headless",
                      "--script", "s.txt", "--record", "r.rec"], tmp_path, env)
    assert done.returncode == 0, done.stderr
    assert _chains(done.stdout) == (1, 3)
    rec = read(tmp_path / "r.rec")
    tape = [json.loads(data) for _t, d, data in rec.wire if d == "T"]
    kinds = {entry[1] for chunk in tape for entry in chunk}
    assert {"calibration", "open", "raw"} <= kinds
    replayed = _camlab88(["replay", "r.rec", "--check"], tmp_path, env)
    assert replayed.returncode == 0, replayed.stdout + replayed.stderr
    assert "screen hashes agree" in replayed.stdout
    # without its tape the replay has no stylus: the check must notice
    rec.wire = [w for w in rec.wire if w[1] != "T"]
    write(tmp_path / "untaped.rec", rec)
    bare = _camlab88(["replay", "untaped.rec", "--check"], tmp_path, env)
    assert bare.returncode == 1, bare.stdout + bare.stderr


@pytest.mark.skipif(skip_reason() is not None, reason=skip_reason() or "")
def test_kas_edit_draws_with_a_hidraw_tablet_and_replays_without_it(tmp_path: Path) -> None:
    reports = [r for r in load_dump(DIGIMEND / "Gaomon_M106K/dumps/pen_cords.txt")
               if r[0] == 0x0A]
    config = tmp_path / "config"
    config.mkdir()
    # a calibration that spreads the captured stroke (x 14281..14284, y 6656..6711) over
    # the screen; it is recorded on the tape, so the replay does not need it
    (config / "calibration.json").write_text(json.dumps(
        {"hid:256c:006d": {"top_left": [14270, 6600], "bottom_right": [14300, 6760]}}))
    (tmp_path / "s.txt").write_text("2.5 key f2\n3.5 wait\n")
    scenario = dict(gaomon_m106k(reports), first_after=0.5)
    done = run_in_bed(tmp_path, scenario, [
        "kas", "edit", "g.kas", "--tablet", "hid:256c:006d", "--headless", "--script",
        "s.txt", "--record", "g.rec"], env={"CAMLAB88_CONFIG_DIR": str(config)})
    assert done.returncode == 0, done.stderr
    chains, points = _chains(done.stdout)
    assert chains >= 1 and points >= 3, done.stdout
    # no test bed now: the tablet does not exist, and the replay must not need it
    replayed = _camlab88(["replay", "g.rec", "--check"], tmp_path,
                         {"CAMLAB88_CONFIG_DIR": str(tmp_path / "empty")})
    assert replayed.returncode == 0, replayed.stdout + replayed.stderr
    assert "screen hashes agree" in replayed.stdout, replayed.stdout  # the same strokes shown


@pytest.mark.skipif(skip_reason() is not None, reason=skip_reason() or "")
def test_a_program_keeps_running_through_an_unplug_and_its_replay_agrees(
        tmp_path: Path) -> None:
    """umockdev removes the tablet mid-session and adds it again: kas edit carries on, says
    so both times, takes the tablet back; the recording (loss and return on the tape)
    replays with --check."""
    reports = [r for r in load_dump(DIGIMEND / "Gaomon_M106K/dumps/pen_cords.txt")
               if r[0] == 0x0A]
    scenario = dict(gaomon_m106k(reports[:40]), first_after=0.3, unplug_after=40,
                    replug_after=0.5, reports_after_replug=[r.hex() for r in reports[40:]])
    (tmp_path / "s.txt").write_text("5.5 key f2\n6.5 wait\n")
    env = {"CAMLAB88_CONFIG_DIR": str(tmp_path / "config")}
    done = run_in_bed(tmp_path, scenario, [
        "kas", "edit", "u.kas", "--tablet", "hid:256c:006d", "--headless", "--script",
        "s.txt", "--record", "u.rec"], env=env)
    assert done.returncode == 0, done.stderr
    assert "hid:256c:006d: lost (" in done.stdout and "using the mouse" in done.stdout
    assert "hid:256c:006d: back; using the tablet again" in done.stdout
    rec = read(tmp_path / "u.rec")
    kinds = [entry[1] for _t, d, data in rec.wire if d == "T" for entry in json.loads(data)]
    assert kinds.count("open") == 2 and kinds.count("lost") == 1
    replayed = _camlab88(["replay", "u.rec", "--check"], tmp_path, env)
    assert replayed.returncode == 0, replayed.stdout + replayed.stderr


@pytest.mark.skipif(skip_reason() is not None, reason=skip_reason() or "")
def test_rainbow_run_with_a_hidraw_tablet_records_and_replays_without_it(
        tmp_path: Path) -> None:
    reports = [r for r in load_dump(DIGIMEND / "Gaomon_M106K/dumps/pen_cords.txt")
               if r[0] == 0x0A]
    done = run_in_bed(tmp_path, dict(gaomon_m106k(reports), first_after=0.3), [
        "rainbow", "run", "--tablet", "hid:256c:006d", "--headless", "--stop-after", "60",
        "--record", "rb.rec"], timeout=120)
    assert done.returncode == 0, done.stderr
    rec = read(tmp_path / "rb.rec")
    kinds = [entry[1] for _t, d, data in rec.wire if d == "T" for entry in json.loads(data)]
    assert kinds[0] == "open" and kinds.count("raw") > 10
    replayed = _camlab88(["replay", "rb.rec", "--check"], tmp_path)
    assert replayed.returncode == 0, replayed.stdout + replayed.stderr


@pytest.mark.parametrize("tape", [
    b'[[0,"calibration",{"device":"emulated:summa-mm"}]]',  # corners missing
    b'[[0,"calibration",{"device":5,"top_left":[0,0],"bottom_right":[1,1]}]]',
    b'{"poll":0}',  # a record that is not a list of entries
    b"not json",
    b'[[1e400,"raw","00"]]',
    # the bomb trial's four: a raw payload that is a number or null, an idle level 9, a tape
    # nested 100,000 deep (TypeError, IndexError and RecursionError before)
    b'[[0,"raw",5]]',
    b'[[0,"raw",null]]',
    b'[[0,"idle",9]]',
    b"[" * 100000 + b"]" * 100000,
])
def test_a_damaged_tablet_tape_is_refused_in_one_line(tmp_path: Path, tape: bytes) -> None:
    """A recording is data: whatever its tablet tape says, the replay ends with a message
    (exit 1 or 2), never a traceback."""
    (tmp_path / "s.txt").write_text(SCRIPT)
    env = {"CAMLAB88_CONFIG_DIR": str(tmp_path / "config")}
    done = _camlab88(["kas", "edit", "k.kas", "--tablet", "emulated:summa-mm", "--headless",
                      "--script", "s.txt", "--record", "r.rec"], tmp_path, env)
    assert done.returncode == 0, done.stderr
    rec = read(tmp_path / "r.rec")
    first = next(i for i, w in enumerate(rec.wire) if w[1] == "T")
    rec.wire[first] = (rec.wire[first][0], "T", tape)
    write(tmp_path / "damaged.rec", rec)
    replayed = _camlab88(["replay", "damaged.rec", "--check"], tmp_path, env)
    said = replayed.stdout + replayed.stderr
    assert replayed.returncode in (1, 2) and "Traceback" not in said, said
