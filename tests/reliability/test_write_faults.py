"""Every writer on a full disk (ENOSPC: a small tmpfs filled up), a read-only mount (EROFS)
or a directory where its file should go: one line naming the user's path (never a temporary
file, never a traceback), a non-zero exit, the old file intact; a long run (sigma run's
--record / --record-line, ca run's --png) refuses before it starts, not after the work."""

from __future__ import annotations

import errno
import sys
from pathlib import Path

import pytest

from camlab88.cli import main
from tests.reliability.mounts import OLD, full_disk, read_only

SCRIPT = Path(__file__).resolve().parents[1] / "data" / "kas_front" / "edit_all.txt"

WRITERS = {  # name: (the command line writing OUT, the old file's name)
    "ca run --png": (["ca", "run", "--rules", "life", "--pattern", "glider",
                      "--generations", "2", "--png", "OUT"], "x.png"),
    "sigma run --record": (["sigma", "run", "--headless", "--seconds", "0.2", "--record",
                            "OUT"], "r.session"),
    "sigma run --record-line": (["sigma", "run", "--headless", "--seconds", "0.2",
                                 "--record-line", "OUT"], "l.rec"),
    "kas export": (["kas", "export", "walk_a", "OUT", "--renderer", "raster", "--width",
                    "64"], "x.gif"),
}


def _run(argv: list[str], capsys: pytest.CaptureFixture[str]) -> tuple[int, str]:
    capsys.readouterr()
    try:
        code = main(argv)
    except SystemExit as exc:  # a refusal before the run: the interpreter prints the text
        code = exc.code if isinstance(exc.code, int) else 1
        if not isinstance(exc.code, int):
            print(exc.code, file=sys.stderr)
    return int(code or 0), capsys.readouterr().err


def _one_clean_line(err: str, path: Path) -> None:
    lines = [line for line in err.splitlines() if line.strip()]
    assert len(lines) == 1, err
    assert str(path) in lines[0] and ".tmp" not in lines[0] and "Traceback" not in err, err


@pytest.mark.parametrize("writer", sorted(WRITERS))
@pytest.mark.parametrize("fault", ["full", "read-only", "directory"])
def test_a_write_fault_is_one_line_naming_the_users_path(tmp_path: Path, capsys,
                                                         writer: str, fault: str) -> None:
    argv, name = WRITERS[writer]
    if fault == "directory":
        folder = tmp_path
        (tmp_path / name).mkdir()
        out = tmp_path / name
        code, err = _run([str(out) if a == "OUT" else a for a in argv], capsys)
        assert code != 0 and out.is_dir()
        _one_clean_line(err, out)
        return
    place = full_disk if fault == "full" else read_only
    with place(tmp_path, {name: OLD}) as folder:
        out = folder / name
        code, err = _run([str(out) if a == "OUT" else a for a in argv], capsys)
        assert code != 0
        _one_clean_line(err, out)
        assert out.read_bytes() == OLD
        assert {p.name for p in folder.iterdir()} <= {name, "filler"}  # no temporaries


def test_a_failed_headless_save_exits_non_zero_saying_why(tmp_path: Path, capsys) -> None:
    from camlab88.apps.kas import files
    from camlab88.apps.kas.editor import Editor

    files.save_keyframe(tmp_path / "k.kas", Editor(None, None, 1).drawing)
    old = (tmp_path / "k.kas").read_bytes()
    with read_only(tmp_path, {"k.kas": old}) as folder:
        code, err = _run(["kas", "edit", str(folder / "k.kas"), "--script", str(SCRIPT),
                          "--headless", "--seed", "1"], capsys)
        assert code == 1
        assert f"{folder / 'k.kas'}: NOT saved: Read-only file system" in err, err
        assert (folder / "k.kas").read_bytes() == old


def test_a_write_failing_at_the_end_of_a_run_is_one_line(tmp_path: Path, capsys,
                                                         monkeypatch) -> None:
    import camlab88.protocols.session.format as session_format

    def full(path, rec) -> None:
        raise OSError(errno.ENOSPC, "No space left on device", str(path))

    monkeypatch.setattr(session_format, "write", full)
    monkeypatch.setattr("camlab88.protocols.session.writer.SessionWriter.finish",
                        lambda self, end, ticks: full(self.path, None))
    rec = tmp_path / "r.session"
    code, err = _run(["sigma", "run", "--headless", "--seconds", "0.2", "--record", str(rec)],
                     capsys)
    assert code == 1
    assert err.strip() == f"camlab88 sigma run: {rec}: No space left on device"
    assert sorted(tmp_path.iterdir()) == []  # no recording, and no temporary file left
