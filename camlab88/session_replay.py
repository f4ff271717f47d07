"""Running a session recording's command again in a scratch directory holding its input
files (``camlab88 replay``, and ``rainbow replay`` of a session recording).

The recorded command line is data: camlab88.replay_policy checks it against an allowlist
first. The re-run program's own messages ("saved key.kas", "recorded the line to ...") are
about the scratch directory, which is deleted: they are kept back, and shown only when the
program fails (the last lines, to say why), so a replay prints only what it does."""

from __future__ import annotations

import contextlib
import io
import os
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
    """Write each recorded input file under ``root``, where the rewritten argv finds it;
    a name that cannot be a file there is refused (ReplayRefused)."""
    from camlab88.replay_policy import ReplayRefused

    for name, data in files.items():
        target = root / (_inside(name) or name)
        leaf = name.replace("\\", "/").rstrip("/").rsplit("/", 1)[-1]
        if leaf in ("", ".", "..") or "\0" in name or root.resolve() not in \
                target.resolve().parents:
            raise ReplayRefused(f"input file name {name[:80]!r} is not a file name")
        try:
            target.parent.mkdir(parents=True, exist_ok=True)
            target.write_bytes(data)
        except OSError as exc:
            raise ReplayRefused(f"input file {name[:80]!r}: {exc.strerror or exc}") from None


def rewrite_argv(argv: list[str]) -> list[str]:
    """Every path pointing outside the scratch directory (an input or an output) moved in
    (run with the scratch directory as the working directory)."""
    out = []
    for a in argv:  # the value of --opt=value and of a Tripos KEY=value, else the word
        keyed = "=" in a and "/" not in a.split("=", 1)[0]
        opt, eq, value = a.partition("=") if keyed else ("", "", a)
        moved = _inside(value) if value else None
        if value.startswith("_out/"):  # an output the policy moved into the scratch directory
            Path(value).parent.mkdir(parents=True, exist_ok=True)
        if moved is not None:  # its directory exists there too, as it did for the original
            Path(moved).parent.mkdir(parents=True, exist_ok=True)
        out.append(a if moved is None else f"{opt}{eq}{moved}")
    return out


def rerun(ctx: Any) -> tuple[int, str]:
    """Run the recorded command line (checked: camlab88.replay_policy) under the replay
    context ``ctx``; returns its exit status and the tail of what it printed. Raises
    ReplayRefused for a command line or input file a replay will not use."""
    from camlab88 import cli
    from camlab88.emulator.harness.replay import replaying
    from camlab88.replay_policy import checked_argv

    argv = checked_argv(ctx.rec.argv)
    home = Path.cwd()
    said = _Tail()
    with tempfile.TemporaryDirectory(prefix="camlab88-replay-") as tmp:
        place_files(ctx.rec.files, Path(tmp))
        os.chdir(tmp)
        try:
            with replaying(ctx), _own_library(Path(tmp)), \
                    contextlib.redirect_stdout(said), contextlib.redirect_stderr(said):
                return _main(cli, rewrite_argv(argv), said), said.text()
        finally:
            os.chdir(home)


@contextlib.contextmanager
def _own_library(root: Path) -> Any:
    """A copy of the user's KAS library for the replay, so a program that saves into the
    library (kas path) changes the copy, never the user's."""
    import shutil

    from camlab88.apps.kas import library

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


def _main(cli: Any, argv: list[str], said: _Tail) -> int:
    try:
        return cli.main(argv)
    except SystemExit as exc:  # an argparse error or a one-line refusal
        if exc.code not in (0, None) and not isinstance(exc.code, int):
            said.write(f"{exc.code}\n")
            return 2
        return int(exc.code or 0)


class _Tail(io.TextIOBase):
    """What the re-run program prints, kept back; only the last ``KEEP`` characters (a
    program may print for hours)."""

    KEEP = 4096

    def __init__(self) -> None:
        self._text = ""

    def write(self, text: str) -> int:
        self._text = (self._text + text)[-self.KEEP:]
        return len(text)

    def text(self) -> str:
        return self._text
