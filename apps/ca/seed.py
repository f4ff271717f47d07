"""The range of a run's seed: the engine hashes it as an int64 (apps/ca/kernels.py), so a
seed beyond it cannot be the seed of any run. Its own module so that ``ca run`` checks
``--seed`` without loading the log reader (apps/ca/log.py)."""

from __future__ import annotations

SEED_MIN, SEED_MAX = -(1 << 63), (1 << 63) - 1


def check_seed(seed: int, name: str = "--seed", error: type[ValueError] = ValueError) -> int:
    """``seed`` if the engine's kernels can take it, else ``error`` naming it."""
    if not SEED_MIN <= seed <= SEED_MAX:
        raise error(f"{name}: {seed} is outside {SEED_MIN}..{SEED_MAX}")
    return seed
