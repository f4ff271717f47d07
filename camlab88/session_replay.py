"""Running a session recording's command again in a scratch directory holding its input
files (``camlab88 replay``, and ``rainbow replay`` of a session recording)."""

from __future__ import annotations

import contextlib
import io
import os
import sys
import tempfile
from pathlib import Path, PurePosixPath
from typing import Any


def _inside(name: str) -> str | None:
    """The scratch-directory path for a name that points outside it (absolute, or climbing
    out with ``..``), else None: a replay never reads or writes outside its directory."""
    parts = [p for p in PurePosixPath(name.replace("\\", "/")).parts if p not in ("/", "")]
    if not (os.path.isabs(name) or ".." in parts):
        return None
    return str(Path("_outside", *[p for p in parts if p != ".."]))


def place_files(files: dict[str, bytes], root: Path) -> None:
    """Write each recorded input file under ``root``, where the rewritten argv finds it."""
    for name, data in files.items():
        target = root / (_inside(name) or name)
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_bytes(data)


def rewrite_argv(argv: list[str]) -> list[str]:
    """Every path pointing outside the scratch directory (an input or an output) moved in
    (run with the scratch directory as the working directory)."""
    out = []
    for a in argv:
        opt, eq, value = a.partition("=") if a.startswith("--") else ("", "", a)
        moved = _inside(value) if value else None
        if moved is not None:  # its directory exists there too, as it did for the original
            Path(moved).parent.mkdir(parents=True, exist_ok=True)
        out.append(a if moved is None else f"{opt}{eq}{moved}")
    return out


def rerun(ctx: Any) -> int:
    """Run ``ctx.rec.argv`` under the replay context ``ctx``; the command's own output goes
    to stderr (stdout keeps the verdict); returns its exit status."""
    from camlab88 import cli
    from emulator.harness.replay import replaying

    home = Path.cwd()
    with tempfile.TemporaryDirectory(prefix="camlab88-replay-") as tmp:
        place_files(ctx.rec.files, Path(tmp))
        os.chdir(tmp)
        try:
            with replaying(ctx), _own_library(Path(tmp)), contextlib.redirect_stdout(_Err()):
                return _main(cli, rewrite_argv(ctx.rec.argv))
        finally:
            os.chdir(home)


@contextlib.contextmanager
def _own_library(root: Path) -> Any:
    """A copy of the user's KAS library for the replay, so a program that saves into the
    library (kas path) changes the copy, never the user's."""
    import shutil

    from apps.kas import library

    copy = root / "_kas_library"
    if library.user_dir().is_dir():
        shutil.copytree(library.user_dir(), copy)
    old = os.environ.get(library.ENV)
    os.environ[library.ENV] = str(copy)
    try:
        yield
    finally:
        if old is None:
            os.environ.pop(library.ENV, None)
        else:
            os.environ[library.ENV] = old


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
