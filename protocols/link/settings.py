"""Line settings of an asynchronous serial line: baud rate and character framing."""

from __future__ import annotations

import re
from dataclasses import dataclass
from fractions import Fraction

_PARITIES = {"N": "none", "E": "even", "O": "odd", "M": "mark", "S": "space"}
_STOP_BITS = (Fraction(1), Fraction(3, 2), Fraction(2))
_FRAMING = re.compile(r"^\s*(\d+)\s+([5-8])([NEOMS])(1|1\.5|2)\s*$", re.IGNORECASE)


@dataclass(frozen=True)
class LineSettings:
    """Baud rate and framing; 9600 8N1 (960 characters per second) by default.

    A character on the wire is 1 start bit, ``data_bits`` data bits, an optional parity bit
    and ``stop_bits`` stop bits, so its duration is exact: ``char_time`` (a Fraction).
    """

    baud: int = 9600
    data_bits: int = 8
    parity: str = "N"
    stop_bits: float = 1

    def __post_init__(self) -> None:
        if not isinstance(self.baud, int) or isinstance(self.baud, bool) or self.baud <= 0:
            raise ValueError(f"baud must be a positive integer, not {self.baud!r}")
        if self.data_bits not in (5, 6, 7, 8):
            raise ValueError(f"data_bits must be 5, 6, 7 or 8, not {self.data_bits!r}")
        parity = str(self.parity).upper()[:1]
        if parity not in _PARITIES or len(str(self.parity)) != 1:
            raise ValueError(f"parity must be one of N, E, O, M, S, not {self.parity!r}")
        object.__setattr__(self, "parity", parity)
        if Fraction(self.stop_bits) not in _STOP_BITS:
            raise ValueError(f"stop_bits must be 1, 1.5 or 2, not {self.stop_bits!r}")

    # Exact values (use these for arithmetic) -------------------------------------------
    @property
    def bits_exact(self) -> Fraction:
        """Bits per character, exactly: start + data + parity + stop."""
        return 1 + self.data_bits + (0 if self.parity == "N" else 1) + Fraction(self.stop_bits)

    @property
    def char_time(self) -> Fraction:
        """Seconds per character, exactly (9600 8N1: 1/960)."""
        return self.bits_exact / self.baud

    # Float views (the interface contract) ------------------------------------------------
    @property
    def bits_per_char(self) -> float:
        return float(self.bits_exact)

    @property
    def char_seconds(self) -> float:
        return float(self.char_time)

    @property
    def chars_per_second(self) -> float:
        return float(1 / self.char_time)

    @property
    def data_mask(self) -> int:
        """Bits of a byte that survive the trip: a 7-bit line drops the top bit."""
        return (1 << self.data_bits) - 1

    @property
    def framing(self) -> str:
        """The usual short form, e.g. ``8N1``, ``7E2``, ``8N1.5``."""
        stop = Fraction(self.stop_bits)
        stop_text = str(stop.numerator) if stop.denominator == 1 else "1.5"
        return f"{self.data_bits}{self.parity}{stop_text}"

    def __str__(self) -> str:
        return f"{self.baud} {self.framing}"

    @classmethod
    def parse(cls, text: str) -> LineSettings:
        """Parse ``"9600 8N1"`` / ``"1200 7E2"`` (the form ``str()`` writes)."""
        match = _FRAMING.match(text)
        if not match:
            raise ValueError(f"bad line settings {text!r}: expected e.g. '9600 8N1'")
        baud, data, parity, stop = match.groups()
        stop_bits: float = 1.5 if stop == "1.5" else int(stop)
        return cls(int(baud), int(data), parity.upper(), stop_bits)

    def pyserial_kwargs(self) -> dict[str, object]:
        """Keyword arguments for ``serial.Serial`` / ``serial.serial_for_url``."""
        return {
            "baudrate": self.baud,
            "bytesize": self.data_bits,
            "parity": self.parity,  # pyserial's PARITY_* constants are these letters
            "stopbits": float(self.stop_bits) if self.stop_bits == 1.5 else int(self.stop_bits),
        }
