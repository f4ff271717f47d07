"""Protocol names -> parser/encoder classes, with options parsed from URL query strings."""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, replace
from typing import Any

from camlab88.protocols.tablets import bitpad1, bitpad2, calcomp, summa, wacom4
from camlab88.protocols.tablets.base import TabletEncoder, TabletParser
from camlab88.protocols.tablets.line_setup import LineSetup, line_setup

PROTOCOL_NAMES = ("wacom4", "summa-mm", "bitpad1", "bitpad2", "calcomp")
ALIASES = {"summa-flair": ("summa-mm", {"flair": "1"})}


def _bool(text: str) -> bool:
    low = text.lower()
    if low in ("1", "true", "yes", "on"):
        return True
    if low in ("0", "false", "no", "off"):
        return False
    raise ValueError(f"not a yes/no value: {text!r}")


def _int(text: str) -> int:
    return int(text, 0)


def _tool(text: str) -> str:
    if text not in ("pen", "eraser", "puck"):
        raise ValueError(f"tool must be pen, eraser or puck, not {text!r}")
    return text


def _parity(text: str) -> str:
    up = text.upper()[:1]
    if up not in ("N", "E", "O"):
        raise ValueError(f"parity must be N, E or O, not {text!r}")
    return up


@dataclass(frozen=True)
class ProtocolSpec:
    name: str
    parser: Callable[..., TabletParser]
    encoder: Callable[..., TabletEncoder]
    parser_options: Mapping[str, Callable[[str], Any]]
    encoder_options: Mapping[str, Callable[[str], Any]]

    @property
    def line(self) -> LineSetup:
        return line_setup(self.name)


SPECS: dict[str, ProtocolSpec] = {
    "wacom4": ProtocolSpec(
        "wacom4", wacom4.Wacom4Parser, wacom4.Wacom4Encoder,
        {"tilt": _bool, "extra_z_bits": _int, "eraser_mask": _int},
        {"tilt": _bool, "extra_z_bits": _int, "eraser_mask": _int, "identity": str},
    ),
    "summa-mm": ProtocolSpec(
        "summa-mm", summa.SummaParser, summa.SummaEncoder,
        {"flair": _bool, "buttons": str, "tool": _tool},
        {"flair": _bool, "buttons": str, "tablet_id": _int},
    ),
    "bitpad2": ProtocolSpec(
        "bitpad2", bitpad2.Bitpad2Parser, bitpad2.Bitpad2Encoder,
        {"parity": _parity, "tool": _tool}, {"parity": _parity, "linefeed": _bool},
    ),
    "bitpad1": ProtocolSpec(
        "bitpad1", bitpad1.Bitpad1Parser, bitpad1.Bitpad1Encoder,
        {"parity": _parity, "tool": _tool}, {"parity": _parity},
    ),
    "calcomp": ProtocolSpec(
        "calcomp", calcomp.CalcompParser, calcomp.CalcompEncoder,
        {"prox_bit": _int, "tool": _tool}, {"prox_bit": _int},
    ),
}


def resolve(name: str, options: Mapping[str, str] | None = None) -> tuple[ProtocolSpec, dict]:
    """Protocol spec and merged string options for a name (aliases included)."""
    merged = dict(options or {})
    if name in ALIASES:
        name, extra = ALIASES[name]
        merged = {**extra, **merged}
    if name not in SPECS:
        known = ", ".join((*PROTOCOL_NAMES, *ALIASES))
        raise ValueError(f"unknown tablet protocol {name!r} (known: {known})")
    return SPECS[name], merged


def _convert(spec_name: str, table: Mapping[str, Callable[[str], Any]],
             options: Mapping[str, str]) -> dict[str, Any]:
    out: dict[str, Any] = {}
    for key, text in options.items():
        if key not in table:
            continue  # options for the other side or the transport
        try:
            out[key] = table[key](text)
        except ValueError as exc:
            raise ValueError(f"{spec_name}: bad option {key}={text!r}: {exc}") from None
    return out


# Any parser: the active area when the tablet is not asked (init=0) and is not the default.
SIZE_OPTIONS = {"max_x": _int, "max_y": _int}


def make_parser(name: str, options: Mapping[str, str] | None = None,
                parmrk: bool = False) -> TabletParser:
    spec, merged = resolve(name, options)
    kwargs = _convert(spec.name, spec.parser_options, merged)
    if "parity" in spec.parser_options and "parity" not in kwargs:
        kwargs["parity"] = spec.line.software_parity
    parser = spec.parser(parmrk=parmrk, **kwargs)
    size = _convert(spec.name, SIZE_OPTIONS, merged)
    if size:
        parser.model = replace(parser.model, **size)
    return parser


def make_encoder(name: str, options: Mapping[str, str] | None = None) -> TabletEncoder:
    spec, merged = resolve(name, options)
    kwargs = _convert(spec.name, spec.encoder_options, merged)
    if "parity" in spec.encoder_options and "parity" not in kwargs:
        kwargs["parity"] = spec.line.software_parity
    return spec.encoder(**kwargs)


def known_options(name: str) -> set[str]:
    spec, _ = resolve(name)
    return set(spec.parser_options) | set(spec.encoder_options) | set(SIZE_OPTIONS)
