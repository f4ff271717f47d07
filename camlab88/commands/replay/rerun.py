"""Running a recording's command again in a scratch directory holding its input files."""

from __future__ import annotations

import contextlib
import io
import os
import sys
import tempfile
from pathlib import Path, PurePosixPath
from typing import Any


def place_files(files: dict[str, bytes], root: Path) -> dict[str, str]:
    """Write each recorded input file under ``root``; returns {recorded name: new path} for
    names that must change (absolute paths, or paths climbing out with ``..``)."""
    renamed: dict[str, str] = {}
    for name, data in files.items():
        parts = [p for p in PurePosixPath(name.replace("\\", "/")).parts if p not in ("/", "")]
        safe = os.path.isabs(name) or ".." in parts
        rel = Path("_inputs", *[p for p in parts if p != ".."]) if safe else Path(*parts)
        target = root / rel
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_bytes(data)
        if safe:
            renamed[name] = str(rel)
    return renamed


def rewrite_argv(argv: list[str], renamed: dict[str, str]) -> list[str]:
    out = []
    for a in argv:
        if a in renamed:
            a = renamed[a]
        elif a.startswith("--") and "=" in a and a.split("=", 1)[1] in renamed:
            opt, value = a.split("=", 1)
            a = f"{opt}={renamed[value]}"
        out.append(a)
    return out


def rerun(ctx: Any) -> int:
    """Run ``ctx.rec.argv`` under the replay context ``ctx``; the command's own output goes
    to stderr (stdout keeps the verdict); returns its exit status."""
    from camlab88 import cli
    from emulator.harness.replay import replaying

    home = Path.cwd()
    with tempfile.TemporaryDirectory(prefix="camlab88-replay-") as tmp:
        argv = rewrite_argv(ctx.rec.argv, place_files(ctx.rec.files, Path(tmp)))
        os.chdir(tmp)
        try:
            with replaying(ctx), contextlib.redirect_stdout(_Err()):
                return _main(cli, argv)
        finally:
            os.chdir(home)


def _main(cli: Any, argv: list[str]) -> int:
    try:
        return cli.main(argv)
    except SystemExit as exc:  # an argparse error or a one-line refusal
        if exc.code not in (0, None) and not isinstance(exc.code, int):
            print(exc.code, file=sys.stderr)
            return 2
        return int(exc.code or 0)


class _Err(io.TextIOBase):
    """stdout of the re-run command, sent to stderr."""

    def write(self, text: str) -> int:
        return sys.stderr.write(text)

    def flush(self) -> None:
        sys.stderr.flush()
