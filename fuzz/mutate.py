"""A small, seeded, deterministic mutator for when atheris is not installed (and for CI):
the same seed gives the same inputs, so a finding can be reproduced from its number."""

from __future__ import annotations

import random

# values that have broken parsers before: huge and negative numbers, bad UTF-8, a BOM,
# deep nesting, separators, control characters
INTERESTING = (b"-1", b"0", b"99999999999999999999", b"1" + b"0" * 400, b"\xff", b"\xef\xbb\xbf",
               b"[" * 200, b"{" * 200, b"\x00", b"\r\n", b"\n", b" ", b",", b":", b"!", b"$",
               b"\x1b", b"NaN", b"1e999", b"-0", b"4294967296", b"2147483648", b"\xc3\x28",
               b"\x7f\xff\xff\xff", b"\xff\xff\xff\xff", b"\x80", b"#", b"|", b"end")


def _flip(rng: random.Random, b: bytearray) -> None:
    if b:
        i = rng.randrange(len(b))
        b[i] ^= 1 << rng.randrange(8)


def _byte(rng: random.Random, b: bytearray) -> None:
    if b:
        b[rng.randrange(len(b))] = rng.randrange(256)


def _insert(rng: random.Random, b: bytearray) -> None:
    i = rng.randrange(len(b) + 1)
    b[i:i] = rng.choice(INTERESTING)


def _delete(rng: random.Random, b: bytearray) -> None:
    if b:
        i = rng.randrange(len(b))
        del b[i: i + rng.randrange(1, 64)]


def _duplicate(rng: random.Random, b: bytearray) -> None:
    if b:
        i = rng.randrange(len(b))
        chunk = b[i: i + rng.randrange(1, 256)]
        j = rng.randrange(len(b) + 1)
        b[j:j] = chunk * rng.randrange(1, 8)


def _number(rng: random.Random, b: bytearray) -> None:
    """Replace a run of digits by an interesting number (what most bounds are about)."""
    digits = [i for i, c in enumerate(b) if 0x30 <= c <= 0x39]
    if not digits:
        _insert(rng, b)
        return
    i = rng.choice(digits)
    j = i
    while j < len(b) and 0x30 <= b[j] <= 0x39:
        j += 1
    b[i:j] = rng.choice(INTERESTING[:5] + (b"4294967296", b"65536", b"2147483648"))


def _truncate(rng: random.Random, b: bytearray) -> None:
    if b:
        del b[rng.randrange(len(b)):]


MUTATIONS = (_flip, _byte, _insert, _delete, _duplicate, _number, _number, _truncate)


def mutate(data: bytes, rng: random.Random, limit: int = 1 << 20) -> bytes:
    """One to four mutations of ``data``, kept under ``limit`` bytes."""
    b = bytearray(data)
    for _ in range(rng.randrange(1, 5)):
        rng.choice(MUTATIONS)(rng, b)
    return bytes(b[:limit])
