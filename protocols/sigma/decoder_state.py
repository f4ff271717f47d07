"""The Sigma decoder's partial state as a value: ``DecoderState``, what a ``Decoder`` holds
between two bytes of a stream (a half-read order or coordinate pair, the abbreviated-mode
registers, a held DJ dot, BA text so far, the counters).

The Decoder itself copies its fields into one (``Decoder.capture``) and back
(``Decoder.resume``); nothing else touches its private fields (PyBoy's ``save_state`` asks
each chip for its own state). ``from_json`` checks a saved dict against what the decoder can
produce (types, ranges, bounded lengths), because a state file may be damaged or hand-edited:
anything else is a ValueError naming the entry, never a TypeError or a decoder that later
misbehaves.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from camlab88.protocols.sigma.abbreviated import PENDING
from camlab88.protocols.sigma.commands import DecoderStats
from camlab88.protocols.sigma.orders import BY_CODE, GRAPHICS_FLAG, Mode, OrderSpec

KEYS = ("mode", "coord_digits", "gh", "line_start", "flag_k", "letter", "spec", "field_i",
        "digits_left", "value", "args", "pair", "ags", "ags_first", "esc", "text", "text_over",
        "dots_hold", "stats")
STATS_KEYS = ("unknown", "malformed", "bytes_in", "commands", "unknown_codes")


def check_keys(state: dict, keys: tuple[str, ...] | list[str], what: str) -> None:
    """ValueError naming the first entry of ``state`` not in ``keys``, or the first of
    ``keys`` missing (the one key check every saved-state reader uses)."""
    for key in state:
        if key not in keys:
            raise ValueError(f"unknown {what} {key!r}")
    for key in keys:
        if key not in state:
            raise ValueError(f"{what} {key!r} is missing")


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


@dataclass
class DecoderState:
    """Everything a Decoder holds between feeds (see Decoder.capture / Decoder.resume)."""

    mode: Mode = Mode.ALPHA
    coord_digits: int = 3
    gh: bool = False
    line_start: bool = True
    flag_k: int = 0
    letter: int = -1
    spec: OrderSpec | None = None
    field_i: int = 0
    digits_left: int = 0
    value: int = 0
    args: list[int] = field(default_factory=list)
    pair: list[int] = field(default_factory=list)
    ags: list[int] = field(default_factory=lambda: [0, 0, 0, 0, 0, 0])
    ags_first: bool = True
    esc: list[int] | None = None
    text: bytes = b""
    text_over: bool = False
    dots_hold: int = -1
    stats: DecoderStats = field(default_factory=DecoderStats)

    def to_json(self) -> dict[str, object]:
        s = self.stats
        return {
            "mode": self.mode.value, "coord_digits": self.coord_digits, "gh": self.gh,
            "line_start": self.line_start, "flag_k": self.flag_k, "letter": self.letter,
            "spec": None if self.spec is None else self.spec.code,
            "field_i": self.field_i, "digits_left": self.digits_left, "value": self.value,
            "args": list(self.args), "pair": list(self.pair), "ags": list(self.ags),
            "ags_first": self.ags_first, "esc": None if self.esc is None else list(self.esc),
            "text": self.text.decode("latin-1"), "text_over": self.text_over,
            "dots_hold": self.dots_hold,
            "stats": {"unknown": s.unknown, "malformed": s.malformed, "bytes_in": s.bytes_in,
                      "commands": s.commands, "unknown_codes": dict(s.unknown_codes)},
        }

    @classmethod
    def from_v1(cls, state: object) -> DecoderState:
        """A version 1 state file kept only the mode and coordinate settings: the decoder
        starts between orders."""
        try:
            return cls(Mode(state["mode"]), int(state["coord_digits"]),
                       bool(state["gh"]), bool(state["line_start"]))
        except (KeyError, TypeError, ValueError) as exc:
            raise ValueError(f"Sigma state 'decoder' is corrupt: {exc!r}") from None

    @classmethod
    def from_json(cls, state: object, max_text: int) -> DecoderState:
        """to_json()'s dict back, every value checked (ValueError naming the entry)."""
        if not isinstance(state, dict):
            raise ValueError("decoder state is not a mapping")
        check_keys(state, KEYS, "decoder state entry")
        try:
            mode = Mode(state["mode"])
        except (ValueError, TypeError):
            raise ValueError(f"decoder state 'mode'={state['mode']!r} is not a mode") from None
        spec, field_i, digits_left, value, args = _order(state)
        digits = _int(state, "coord_digits", 3, 4)
        ags = _ints(state, "ags", -(1 << 31), (1 << 31) - 1, 6)
        if len(ags) != 6:
            raise ValueError("decoder state 'ags' must hold 6 registers")
        ags[PENDING] = max(ags[PENDING], 0)  # a count of points waiting, never negative
        esc = None if state["esc"] is None else _ints(state, "esc", 0x20, 0x7E, 3)
        return cls(mode, digits, _bool(state, "gh"), _bool(state, "line_start"),
                   _int(state, "flag_k", 0, len(GRAPHICS_FLAG) - 1),
                   _int(state, "letter", -1, 0x7F), spec, field_i, digits_left, value, args,
                   _ints(state, "pair", 0, 9, 2 * digits - 1), ags, _bool(state, "ags_first"),
                   esc, _text(state, max_text), _bool(state, "text_over"),
                   _int(state, "dots_hold", -1, 0x7F), _stats(state))


def _order(state: dict) -> tuple[OrderSpec | None, int, int, int, list[int]]:
    """The order being read: its spec, field index, digits left, value, fields so far."""
    spec_code = state["spec"]
    spec = None
    if spec_code is not None:
        spec = BY_CODE.get(spec_code.encode("ascii")) if isinstance(spec_code, str) and \
            spec_code.isascii() else None
        if spec is None or not spec.fields:
            raise ValueError(f"decoder state 'spec'={spec_code!r} is not an order with fields")
    # between orders these keep the last order's leftovers, harmless but bounded
    field_i = _int(state, "field_i", 0, len(spec.fields) - 1 if spec else 8)
    width = spec.fields[field_i].width if spec else 4
    digits_left = _int(state, "digits_left", 1 if spec else 0, width)
    value = _int(state, "value", 0, 16 ** width)
    args = _ints(state, "args", 0, 16 ** 4, field_i if spec else 8)
    return spec, field_i, digits_left, value, args


def _text(state: dict, max_text: int) -> bytes:
    text = state["text"]
    if not isinstance(text, str) or len(text) > max_text:
        raise ValueError(f"decoder state 'text' is not a string of at most {max_text}")
    try:
        return text.encode("latin-1")
    except UnicodeEncodeError:
        raise ValueError("decoder state 'text' has characters outside latin-1") from None


def _stats(state: dict) -> DecoderStats:
    stats = state["stats"]
    if not isinstance(stats, dict) or set(stats) != set(STATS_KEYS):
        raise ValueError(f"decoder state 'stats' must have exactly {', '.join(STATS_KEYS)}")
    counts = {k: _int(stats, k, 0, 1 << 62) for k in STATS_KEYS[:-1]}
    codes = stats["unknown_codes"]
    if not isinstance(codes, dict) or len(codes) > 64 or any(
            not isinstance(k, str) or type(v) is not int or v < 0 for k, v in codes.items()):
        raise ValueError("decoder state 'stats.unknown_codes' is not a small code -> count map")
    return DecoderStats(unknown_codes=dict(codes), **counts)
