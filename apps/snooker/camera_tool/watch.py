"""Noticing that the script file changed on disk (saved from any text editor): its
modification time and size, polled, and then its text compared with what we hold."""

from __future__ import annotations

import os
from pathlib import Path


class FileWatch:
    def __init__(self, path: str | os.PathLike[str]) -> None:
        self.path = Path(path)
        self.stamp = self._stamp()

    def _stamp(self) -> tuple[int, int] | None:
        try:
            st = self.path.stat()
        except OSError:
            return None
        return st.st_mtime_ns, st.st_size

    def changed(self) -> bool:
        """True once after each change of the file's mtime or size."""
        s = self._stamp()
        if s == self.stamp:
            return False
        self.stamp = s
        return s is not None

    def seen(self) -> None:
        """We wrote the file ourselves: do not report it as changed."""
        self.stamp = self._stamp()
