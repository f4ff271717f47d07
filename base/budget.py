"""The memory budget: what an input will cost, worked out before the work, against one limit.

Every reader and renderer whose input can ask for more memory than its file's size (a dense
grid in a few bytes of macrocell, a recording of millions of records, an actor of many
lathes at a film's size) computes what it would need and calls :func:`check` before it
allocates. One limit governs them all: ``camlab88 --budget SIZE ...`` or the environment
variable ``CAMLAB88_BUDGET`` (``1500M``, ``4G``, a number of bytes); the default fits a
2 GB machine with room for the interpreter and the window (docs/reliability.md, "Budget").
"""

from __future__ import annotations

import os
import re

ENV = "CAMLAB88_BUDGET"
DEFAULT = 1 << 30  # 1 GiB: a 2 GB machine keeps the other half for the system and us
_SIZE = re.compile(r"\s*([0-9]{1,15})(?:\.([0-9]{1,3}))?\s*([kKmMgGtT]?)(?:i?[bB])?\s*")
_UNIT = {"": 1, "k": 1 << 10, "m": 1 << 20, "g": 1 << 30, "t": 1 << 40}


class OverBudget(ValueError):
    """An input that would need more memory than the budget allows (one line, the input
    named by whoever raises it)."""


def parse_size(text: str) -> int:
    """``1500M``, ``4G``, ``2.5G`` or plain bytes; ValueError in words otherwise."""
    m = _SIZE.fullmatch(text)
    if m is None:
        raise ValueError(f"a memory size is a number with an optional K, M, G or T "
                         f"(1500M, 4G), not {text[:40]!r}")
    whole, frac, unit = m[1], m[2] or "", m[3].lower()
    size = (int(whole) * 1000 + int((frac + "000")[:3])) * _UNIT[unit] // 1000
    if size < 1 << 20:
        raise ValueError(f"a memory budget below 1M leaves nothing to work in ({text!r})")
    return size


def limit() -> int:
    """The budget in bytes: ``CAMLAB88_BUDGET`` if set (a bad value is an error naming
    it), else DEFAULT."""
    text = os.environ.get(ENV)
    if text is None or not text.strip():
        return DEFAULT
    try:
        return parse_size(text)
    except ValueError as exc:
        raise OverBudget(f"{ENV}={text[:40]!r}: {exc}") from None


def size_text(n: float) -> str:
    """Bytes as a person reads them: 812 MB, 4.1 GB (powers of 1024)."""
    for unit in ("B", "KB", "MB", "GB", "TB"):
        if n < 1024 or unit == "TB":
            return f"{n:.0f} {unit}" if unit in ("B", "KB", "MB") or n >= 100 else \
                f"{n:.1f} {unit}"
        n /= 1024
    return f"{n:.0f} TB"  # not reached


def check(source: str, need: int, what: str) -> None:
    """Refuse ``source`` when ``what`` would need ``need`` bytes, more than the budget:
    ``OverBudget('big.mc: an 8192 x 8192 grid would need 4.0 GB; the memory budget is
    1.0 GB (raise it with camlab88 --budget SIZE or CAMLAB88_BUDGET=SIZE)')``."""
    have = limit()
    if need > have:
        raise OverBudget(f"{source}: {what} would need {size_text(need)}; the memory budget "
                         f"is {size_text(have)} (raise it with camlab88 --budget SIZE or "
                         f"{ENV}=SIZE)")
