"""Errors of a camera script, for a non-expert (thesis §6.3.1: "it was considered important
that the language should provide a flexible syntax and good error messages"): each names
its line and column; a script's errors are all collected and reported together."""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import dataclass

from camlab88.base.suggest import close_names


@dataclass(frozen=True, order=True)
class CclError:
    line: int
    col: int
    message: str

    def format(self, path: str = "<script>") -> str:
        return f"{path}:{self.line}:{self.col}: {self.message}"


class CclErrors(ValueError):
    """Every error of one script, in order of position."""

    def __init__(self, errors: Sequence[CclError], path: str = "<script>") -> None:
        self.errors = sorted(errors)
        self.path = path
        super().__init__("\n".join(e.format(path) for e in self.errors))


def did_you_mean(word: str, candidates: Iterable[str]) -> str:
    """' (did you mean VIEWPOINT?)' for a near miss, else ''."""
    close = close_names(word.upper(), candidates, n=1)  # keywords are shown unquoted
    return f" (did you mean {close[0]}?)" if close else ""
