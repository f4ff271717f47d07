"""Starting a snooker run from the command line's words: table constants changed by name,
and a start file that is either a saved session (JSON) or a checkpoint (§6.2.2)."""

from __future__ import annotations

import dataclasses
import os
from pathlib import Path

from camlab88.apps.snooker.session import Session, check_table
from camlab88.apps.snooker.table import Table


def table_with(changes: list[tuple[str, str]]) -> Table:
    """A Table with the named constants changed (``cushion_restitution=1.2``); an unknown
    name or a bad value raises ValueError listing what is known."""
    fields = {f.name: f.type for f in dataclasses.fields(Table)}
    values: dict[str, object] = {}
    for name, text in changes:
        if name not in fields:
            raise ValueError(f"unknown table constant {name!r}; known: {', '.join(fields)}")
        cast = {"int": int, "str": str}.get(str(fields[name]), float)
        values[name] = cast(text)
    return check_table(Table(**values))


def is_session_file(path: str | os.PathLike[str]) -> bool:
    """A saved session is JSON (starts with ``{``); anything else is read as a checkpoint."""
    p = Path(path)
    if not p.is_file():  # a directory or a missing file is read (and refused) as a checkpoint
        return False
    with p.open("rb") as f:
        return f.read(64).lstrip().startswith(b"{")


def start_from(path: str | os.PathLike[str], table: Table) -> Session:
    """The position to play on from: a saved session at its head, or a checkpoint's last
    frame."""
    if is_session_file(path):
        session = Session.load(path)
        session.cursor = session.timeline.head
        return session
    return Session.from_checkpoint(path, table)
