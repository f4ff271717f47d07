"""The error of a file read as text, at a place in it: ``path:line:col: what``."""

from __future__ import annotations


class FilePlaceError(ValueError):
    """A bad file; the message begins ``path:line:col:`` (``where``, when given, instead:
    the file as a whole, say). ``path``, ``line`` and ``col`` are kept for callers."""

    def __init__(self, path: str, line: int, col: int, message: str,
                 where: str | None = None) -> None:
        super().__init__(f"{where or f'{path}:{line}:{col}'}: {message}")
        self.path, self.line, self.col = path, line, col
