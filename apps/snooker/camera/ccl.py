"""Camera script + ball motion -> viewing parameters for every frame (thesis §6.3.1), the
whole pipeline: lex, parse, interpret, with every error of the script collected."""

from __future__ import annotations

import os
from pathlib import Path

from camlab88.apps.snooker.camera.errors import CclError, CclErrors
from camlab88.apps.snooker.camera.interpreter import Interpretation, interpret
from camlab88.apps.snooker.camera.motion import Motion
from camlab88.apps.snooker.camera.parser import parse


def run(text: str, motion: Motion) -> Interpretation:
    """Interpret as much as can be: syntax errors drop only their own sub-commands, so the
    result is still a full view sequence (the interactive tool previews it); check
    ``.errors`` before writing it out."""
    commands, errors = parse(text)
    result = interpret(commands, motion)
    result.errors = sorted(errors + result.errors)
    return result


def compile_script(text: str, motion: Motion, path: str = "<script>") -> Interpretation:
    """Like `run`, but a script with any error raises CclErrors listing all of them."""
    result = run(text, motion)
    if result.errors:
        raise CclErrors(result.errors, path)
    return result


def read_script(path: str | os.PathLike[str]) -> str:
    """The script's text; a byte that is not UTF-8 is an error at its line and column."""
    raw = Path(path).read_bytes()
    try:
        return raw.decode("utf-8")
    except UnicodeDecodeError as exc:
        before = raw[: exc.start]
        line = before.count(b"\n") + 1
        col = exc.start - (before.rfind(b"\n") + 1) + 1
        raise CclErrors([CclError(line, col, "this byte is not UTF-8 text")], str(path)) from None
