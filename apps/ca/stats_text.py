"""A CA run's statistics as the commands print them: one line, or JSON with --json."""

from __future__ import annotations

import json
from typing import Any


def stats_text(stats: dict[str, Any], as_json: bool) -> str:
    """``generation G  population P  by type {...}  bbox (...)``, or sorted JSON."""
    if as_json:
        return json.dumps(stats, sort_keys=True)
    box = stats["bbox"]
    kinds = ", ".join(f"{k}: {v}" for k, v in stats["by_type"].items()) or "none"
    return (f"generation {stats['generation']}  population {stats['population']}  "
            f"by type {{{kinds}}}  bbox {'empty' if box is None else tuple(box)}")
