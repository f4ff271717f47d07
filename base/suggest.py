"""'did you mean ...?' for a misspelt name: one wording everywhere (the command line's
subcommands, KAS and CA library names)."""

from __future__ import annotations

from collections.abc import Iterable


def close_names(word: str, choices: Iterable[str], n: int = 3) -> list[str]:
    """The known names nearest ``word`` (difflib's ratio, at least 0.6), nearest first."""
    import difflib  # only on a miss: not a cost of every start

    return difflib.get_close_matches(word, sorted(set(choices)), n=n, cutoff=0.6)


def did_you_mean(word: str, choices: Iterable[str]) -> str:
    """``"; did you mean 'walk_a'?"`` (or ``'walk_a' or 'walk_b'``) for a near miss, else ''."""
    close = close_names(word, choices)
    if not close:
        return ""
    return "; did you mean " + " or ".join(repr(c) for c in close) + "?"
