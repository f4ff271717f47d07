"""Parsers fed arbitrary text: they either read it or refuse it naming the file, nothing else."""

from __future__ import annotations

from collections.abc import Callable
from typing import TypeVar

E = TypeVar("E", bound=Exception)


def refusal_of(parse: Callable[[str, str], object], text: str, name: str,
               error: type[E]) -> E | None:
    """Parse ``text`` as the file ``name``: None if it is read, else the ``error`` raised, whose
    message must begin ``name:``. Any other exception propagates and fails the test."""
    try:
        parse(text, name)
    except error as exc:
        assert str(exc).startswith(f"{name}:"), exc
        return exc
    return None
