"""Restoring a decoder's partial state (Decoder.get_state's dict) with every value checked.

A state file may be damaged or hand-edited, so each entry is validated against what the
decoder itself can produce (types, ranges, bounded lengths); anything else is a ValueError
naming the entry, never a TypeError or a decoder that later misbehaves.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from protocols.sigma import abbreviated
from protocols.sigma.commands import DecoderStats
from protocols.sigma.orders import BY_CODE, GRAPHICS_FLAG, Mode

if TYPE_CHECKING:
    from protocols.sigma.decoder import Decoder

KEYS = ("mode", "coord_digits", "gh", "line_start", "flag_k", "letter", "spec", "field_i",
        "digits_left", "value", "args", "pair", "ags", "ags_first", "esc", "text", "text_over",
        "dots_hold", "stats")
STATS_KEYS = ("unknown", "malformed", "bytes_in", "commands", "unknown_codes")


def _int(state: dict, key: str, lo: int, hi: int) -> int:
    v = state[key]
    if type(v) is not int or not lo <= v <= hi:
        raise ValueError(f"decoder state {key!r}={v!r} is not an integer in {lo}..{hi}")
    return v


def _bool(state: dict, key: str) -> bool:
    v = state[key]
    if type(v) is not bool:
        raise ValueError(f"decoder state {key!r}={v!r} is not true/false")
    return v


def _ints(state: dict, key: str, lo: int, hi: int, most: int) -> list[int]:
    v = state[key]
    if not isinstance(v, list) or len(v) > most or any(
            type(x) is not int or not lo <= x <= hi for x in v):
        raise ValueError(f"decoder state {key!r} is not a list of at most {most} integers "
                         f"in {lo}..{hi}")
    return list(v)


def restore(dec: Decoder, state: dict[str, object]) -> None:
    if not isinstance(state, dict):
        raise ValueError("decoder state is not a mapping")
    for key in state:
        if key not in KEYS:
            raise ValueError(f"unknown decoder state entry {key!r}")
    for key in KEYS:
        if key not in state:
            raise ValueError(f"decoder state entry {key!r} is missing")
    try:
        mode = Mode(state["mode"])
    except ValueError:
        raise ValueError(f"decoder state 'mode'={state['mode']!r} is not a mode") from None
    digits = _int(state, "coord_digits", 3, 4)
    spec_code = state["spec"]
    spec = None
    if spec_code is not None:
        spec = BY_CODE.get(spec_code.encode("ascii")) if isinstance(spec_code, str) else None
        if spec is None or not spec.fields:
            raise ValueError(f"decoder state 'spec'={spec_code!r} is not an order with fields")
    # between orders these keep the last order's leftovers, harmless but bounded
    field_i = _int(state, "field_i", 0, len(spec.fields) - 1 if spec else 8)
    width = spec.fields[field_i].width if spec else 4
    digits_left = _int(state, "digits_left", 1 if spec else 0, width)
    value = _int(state, "value", 0, 16 ** width)
    args = _ints(state, "args", 0, 16 ** 4, field_i if spec else 8)
    pair = _ints(state, "pair", 0, 9, 2 * digits - 1)
    ags = _ints(state, "ags", -(1 << 31), (1 << 31) - 1, 6)
    if len(ags) != 6:
        raise ValueError("decoder state 'ags' must hold 6 registers")
    esc = state["esc"]
    if esc is not None:
        esc = _ints(state, "esc", 0x20, 0x7E, 3)
    text = state["text"]
    if not isinstance(text, str) or len(text) > dec.MAX_TEXT:
        raise ValueError(f"decoder state 'text' is not a string of at most {dec.MAX_TEXT}")
    try:
        text_bytes = bytearray(text.encode("latin-1"))
    except UnicodeEncodeError:
        raise ValueError("decoder state 'text' has characters outside latin-1") from None
    letter = _int(state, "letter", -1, 0x7F)
    hold = _int(state, "dots_hold", -1, 0x7F)
    stats = state["stats"]
    if not isinstance(stats, dict) or set(stats) != set(STATS_KEYS):
        raise ValueError(f"decoder state 'stats' must have exactly {', '.join(STATS_KEYS)}")
    counts = {k: _int(stats, k, 0, 1 << 62) for k in STATS_KEYS[:-1]}
    codes = stats["unknown_codes"]
    if not isinstance(codes, dict) or len(codes) > 64 or any(
            not isinstance(k, str) or type(v) is not int or v < 0 for k, v in codes.items()):
        raise ValueError("decoder state 'stats.unknown_codes' is not a small code -> count map")

    dec._clear_partial()
    dec.mode = mode
    dec.coord_digits = digits
    dec.gh = _bool(state, "gh")
    dec._line_start = _bool(state, "line_start")
    dec._flag_k = _int(state, "flag_k", 0, len(GRAPHICS_FLAG) - 1)
    dec._letter = letter
    dec._spec = spec
    dec._field_i = field_i
    dec._digits_left = digits_left
    dec._value = value
    dec._args = args
    dec._pair = pair
    dec._ags_state = np.array(ags, dtype=np.int32)
    dec._ags_state[abbreviated.PENDING] = max(int(dec._ags_state[abbreviated.PENDING]), 0)
    dec._ags_first = _bool(state, "ags_first")
    dec._esc = esc
    dec._text = text_bytes
    dec._text_over = _bool(state, "text_over")
    dec._dots_hold = hold
    dec.stats = DecoderStats(unknown_codes=dict(codes), **counts)
