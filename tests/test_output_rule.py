"""One output rule for every command that writes a file (docs/exit_status.md), tested per
command as a user meets it (``python -m camlab88``, one process each): before the work,
status 2 and one line —

- a directory that does not exist: "no such directory D" (it is never created);
- a file where a directory should be: "F is a file in the way, not a directory";
- an extension that names no format the command writes (``--out x.jpg`` for a PNG): the
  extensions it does write are named.

A write fault after the start is the work failing (status 1): tested for ``kas export``,
``snooker film`` and ``ca film`` (which said 2) by a writer that fails mid-run; and an
output FIFO nobody reads gives up after ``CAMLAB88_FIFO_WAIT`` seconds with one line."""

from __future__ import annotations

import errno
import os
import subprocess
import sys
from pathlib import Path

import pytest

from camlab88.cli import main

ROOT = Path(__file__).resolve().parents[1]
STREAM = str(ROOT / "examples" / "sigma" / "pgplot_goc.sig")
SCENE = str(ROOT / "examples" / "rainbow" / "scene.json")
CHECKPOINT = str(ROOT / "tests" / "data" / "snooker_camera" / "pink_shot.checkpoint")
CCL = str(ROOT / "tests" / "data" / "snooker_camera" / "thesis_example.ccl")
RECORDING = str(ROOT / "examples" / "figures" / "fig-3.1.session")
LINE_REC = "camlab88-link-recording 1\nline 9600 8N1\nxonxoff on\n0.010000 > 48\nend 1\n"

# command: (argv writing {OUT}, an extension it writes, one that names no format it writes
# (None: the format is the command's own text whatever the name), a directory output?)
OUTPUTS: dict[str, tuple[list[str], str, str | None, bool]] = {
    "sigma render --out": (["sigma", "render", "--in", STREAM, "--out", "{OUT}"], ".png",
                           ".jpg", False),
    "sigma render --frames": (["sigma", "render", "--in", STREAM, "--frames", "{OUT}"], "",
                              None, True),
    "sigma run --screenshot": (["sigma", "run", "--headless", "--seconds", "0.1",
                                "--screenshot", "{OUT}"], ".png", ".jpg", False),
    "sigma run --frames": (["sigma", "run", "--headless", "--seconds", "0.1", "--frames",
                            "{OUT}"], "", None, True),
    "rainbow render": (["rainbow", "render", SCENE, "--out", "{OUT}"], ".png", ".bmp", False),
    "link stream": (["link", "stream", "line.rec", "--out", "{OUT}"], ".bin", None, False),
    "kas inbetween": (["kas", "inbetween", "sun_a", "sun_b", "--frames", "3", "--out",
                       "{OUT}"], ".kas", None, False),
    "kas export": (["kas", "export", "sun.kas", "{OUT}"], ".gif", ".jpg", False),
    "snooker simulate": (["snooker", "simulate", "--break", "1", "--out", "{OUT}"], ".cp",
                         None, False),
    "snooker ccl": (["snooker", "ccl", CCL, CHECKPOINT, "--out", "{OUT}"], ".views", None,
                    False),
    "snooker render": (["snooker", "render", CHECKPOINT, "e.views", "--frames", "{OUT}"], "",
                       None, True),
    "snooker film": (["snooker", "film", CHECKPOINT, CCL, "--out", "{OUT}"], ".mp4", ".avi",
                     False),
    "ca run --png": (["ca", "run", "--rules", "life", "--pattern", "glider", "--generations",
                      "1", "--png", "{OUT}"], ".png", ".jpg", False),
    "ca convert": (["ca", "convert", "glider", "{OUT}"], ".rle", ".txt", False),
    "ca film": (["ca", "film", "life", "glider", "--generations", "1", "--size", "16x16",
                 "--out", "{OUT}"], ".gif", ".avi", False),
    "demo --out": (["demo", "--headless", "--only", "ca", "--out", "{OUT}"], "", None, True),
    "kas plot --pdf": (["kas", "plot", "sun.kas", "--pdf", "{OUT}"], "", None, True),
    "kas plot --svg": (["kas", "plot", "sun.kas", "--svg", "{OUT}"], "", None, True),
    "replay --frames": (["replay", RECORDING, "--headless", "--frames", "{OUT}"], "", None,
                        True),
    "rainbow replay --screenshot": (["rainbow", "replay", "empty.rbrec", "--headless",
                                     "--screenshot", "{OUT}"], ".png", ".jpg", False),
    "replay --html DIR": (["replay", RECORDING, "--html", "{OUT}"], "", None, True),
    "figures --html": (["figures", "--html", "{OUT}", "3.1"], "", None, True),
    "replay --screenshot": (["replay", RECORDING, "--headless", "--screenshot", "{OUT}"],
                            ".png", ".jpg", False),
}


def _run(tmp_path: Path, argv: list[str], **env: str) -> subprocess.CompletedProcess[str]:
    environ = {k: v for k, v in os.environ.items() if k not in ("DISPLAY", "WAYLAND_DISPLAY")}
    environ.update(PYTHONPATH=str(ROOT), SDL_VIDEODRIVER="dummy",
                   CAMLAB88_KAS_LIBRARY=str(tmp_path / "library"), **env)
    return subprocess.run([sys.executable, "-m", "camlab88", *argv], cwd=tmp_path,
                          env=environ, capture_output=True, text=True, timeout=300,
                          stdin=subprocess.DEVNULL)


def _inputs(tmp_path: Path, name: str) -> None:
    (tmp_path / "plain").write_text("a file, not a directory\n")
    (tmp_path / "line.rec").write_text(LINE_REC)
    (tmp_path / "e.views").write_text("")
    (tmp_path / "empty.rbrec").write_text("# camlab88 rainbow recording v1\n")
    if name == "kas export":
        (tmp_path / "sun.kas").write_text(_sequence(tmp_path))


def _sequence(tmp_path: Path) -> str:
    done = _run(tmp_path, ["kas", "inbetween", "sun_a", "sun_b", "--frames", "3", "--out",
                           "seq.kas"])
    assert done.returncode == 0, done.stderr
    return (tmp_path / "seq.kas").read_text()


def _refused(done: subprocess.CompletedProcess[str], *words: str) -> str:
    lines = [ln for ln in done.stderr.splitlines()
             if ln.strip() and not ln.startswith("camlab88: compiling ")]
    assert done.returncode == 2, (done.returncode, done.stderr)
    assert len(lines) == 1 and "Traceback" not in done.stderr, done.stderr
    assert all(w in lines[0] for w in words), lines[0]
    return lines[0]


CASES = [(name, case) for name, (_a, _g, bad, _d) in OUTPUTS.items()
         for case in ("missing directory", "file in the way", "wrong extension")
         if case != "wrong extension" or bad is not None]


@pytest.mark.parametrize(("name", "case"), CASES, ids=[f"{n}: {c}" for n, c in CASES])
def test_the_output_rule(tmp_path: Path, name: str, case: str) -> None:
    argv, good, bad, _is_dir = OUTPUTS[name]
    _inputs(tmp_path, name)
    if case == "missing directory":
        out = tmp_path / "nowhere" / "deeper" / f"out{good}"
        done = _run(tmp_path, [a.replace("{OUT}", str(out)) for a in argv])
        _refused(done, "no such directory", str(out.parent))
        assert not (tmp_path / "nowhere").exists()  # never created
    elif case == "file in the way":
        out = tmp_path / "plain" / f"out{good}"
        done = _run(tmp_path, [a.replace("{OUT}", str(out)) for a in argv])
        _refused(done, f"{tmp_path / 'plain'} is a file in the way, not a directory")
    elif name.endswith("film"):  # refused by the parser (the film's type): status 2 too
        out = tmp_path / f"out{bad}"
        done = _run(tmp_path, [a.replace("{OUT}", str(out)) for a in argv])
        assert done.returncode == 2 and "Traceback" not in done.stderr, done.stderr
        assert f"out{bad}: the film is .mp4 or .gif" in done.stderr, done.stderr
        assert not out.exists()
    else:
        out = tmp_path / f"out{bad}"
        done = _run(tmp_path, [a.replace("{OUT}", str(out)) for a in argv])
        line = _refused(done, f"'{bad}' names no format it writes", good)
        assert not out.exists(), line


@pytest.mark.parametrize("name", [n for n, v in OUTPUTS.items() if v[3]])
def test_a_file_where_a_directory_output_goes_is_named(tmp_path: Path, name: str) -> None:
    argv = OUTPUTS[name][0]
    _inputs(tmp_path, name)
    done = _run(tmp_path, [a.replace("{OUT}", str(tmp_path / "plain")) for a in argv])
    _refused(done, "is a file in the way, not a directory")
    assert (tmp_path / "plain").read_text() == "a file, not a directory\n"


def _enospc(*args: object, **kw: object) -> None:
    raise OSError(errno.ENOSPC, "No space left on device", "the-film")


@pytest.mark.parametrize("argv, writer", [
    (["kas", "export", "{DIR}/seq.kas", "{DIR}/w.gif", "--renderer", "raster", "--width",
      "32"], "camlab88.apps.kas.export.export"),
    (["ca", "film", "life", "glider", "--generations", "1", "--frames-per-generation", "1",
      "--size", "16x12", "--out", "{DIR}/f.gif"], "camlab88.apps.snooker.film.movie.write_movie"),
    (["snooker", "film", CHECKPOINT, CCL, "--size", "32x24", "--out", "{DIR}/s.gif"],
     "camlab88.apps.snooker.film.movie.write_movie"),
], ids=["kas export", "ca film", "snooker film"])
def test_a_write_fault_during_the_work_is_status_1(tmp_path: Path, capsys, monkeypatch,
                                                    argv: list[str], writer: str) -> None:
    """The output passed its checks at the start; the disk fills while the work runs."""
    if argv[1] == "export":
        assert main(["kas", "inbetween", "sun_a", "sun_b", "--frames", "3", "--out",
                     str(tmp_path / "seq.kas")]) == 0
    monkeypatch.setattr(writer, _enospc)
    code = main([a.replace("{DIR}", str(tmp_path)) for a in argv])
    err = capsys.readouterr().err
    assert code == 1, err
    assert "the-film: No space left on device" in err and "Traceback" not in err


def test_a_fifo_nobody_reads_gives_up_in_one_line(tmp_path: Path) -> None:
    fifo = tmp_path / "pipe.png"
    os.mkfifo(fifo)
    done = _run(tmp_path, ["ca", "run", "--rules", "life", "--pattern", "glider",
                           "--generations", "1", "--png", str(fifo)], CAMLAB88_FIFO_WAIT="0.3")
    lines = [ln for ln in done.stderr.splitlines()  # not the notices and progress
             if not ln.startswith(("camlab88: compiling", "generation "))]
    assert done.returncode == 1, done.stderr
    assert lines == [f"camlab88 ca run: {fifo}: no reader opened this FIFO in 0.3 s "
                     "(CAMLAB88_FIFO_WAIT)"], done.stderr


def test_a_fifo_with_a_reader_is_written(tmp_path: Path) -> None:
    fifo = tmp_path / "pipe.png"
    os.mkfifo(fifo)
    child = subprocess.Popen([sys.executable, "-m", "camlab88", "ca", "run", "--rules", "life",
                              "--pattern", "glider", "--generations", "1", "--png", str(fifo)],
                             cwd=tmp_path, env={**os.environ, "PYTHONPATH": str(ROOT)},
                             stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    with open(fifo, "rb") as reader:  # opening blocks until the writer opens: no sleep
        data = reader.read()
    _out, err = child.communicate(timeout=120)
    assert child.returncode == 0, err
    assert data.startswith(b"\x89PNG")


def test_the_png_writer_makes_no_directory(tmp_path: Path) -> None:
    """base.png.write_png made every missing directory of its path; now the rule's words."""
    import numpy as np

    from camlab88.base.png import write_png

    with pytest.raises(OSError) as refused:
        write_png(np.zeros((2, 2, 3), np.uint8), tmp_path / "nowhere" / "deeper" / "x.png")
    assert f"no such directory {tmp_path / 'nowhere' / 'deeper'}" in str(refused.value)
    assert not (tmp_path / "nowhere").exists()


def test_a_new_directory_output_is_made_one_level(tmp_path: Path, capsys) -> None:
    """What the rule allows is still done: DIR itself is made when its parent exists."""
    assert main(["kas", "inbetween", "sun_a", "sun_b", "--frames", "3", "--out",
                 str(tmp_path / "seq.kas")]) == 0
    assert main(["kas", "plot", str(tmp_path / "seq.kas"), "--pdf",
                 str(tmp_path / "plots")]) == 0
    assert (tmp_path / "plots" / "sequence.pdf").read_bytes().startswith(b"%PDF")
    done = _run(tmp_path, ["replay", RECORDING, "--headless", "--frames", "frames",
                           "--screenshot", "last.png"])
    assert done.returncode == 0, done.stderr
    assert (tmp_path / "frames" / "frame_00000.png").is_file()
    assert (tmp_path / "last.png").read_bytes().startswith(b"\x89PNG")
