"""A program's declared state: plain values checked against a small schema the program
declares in its own code (the way PyBoy asks each chip for its fields under a
``STATE_VERSION`` and MAME registers each field with ``save_item``).

A schema is a tree of kinds: :class:`Int`, :class:`Float`, :class:`Bool`, :class:`Str`,
:class:`Frac` (a Fraction as ``[numerator, denominator]``, each at most ``DIGITS`` digits),
:class:`Opt`, :class:`ListOf`, :class:`Tuple`, :class:`Record` (a mapping with exactly the
declared keys), :class:`Choice` (one of a fixed set of strings) and :class:`Array` (a numpy
array of one declared dtype and number of dimensions, its bytes in a binary part beside the
JSON; its shape x itemsize is checked against the part before anything is allocated).

``encode(schema, value, parts)`` gives the JSON value (arrays go into ``parts``);
``decode(schema, json, parts, where)`` gives the Python value back or raises StateValueError
naming where in the state it is wrong. Nothing in a state is ever used as code, a class, an
attribute name or a path: values only, and only where the schema says so.
``describe(schema)`` is the schema as text (the schema snapshot test keeps one per program).
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass
from fractions import Fraction
from typing import Any

import numpy as np

DIGITS = 200  # decimal digits of a Fraction's numerator or denominator
ALLOWED_DTYPES = ("|u1", "|i1", "<u2", "<i2", "<u4", "<i4", "<u8", "<i8", "<f4", "<f8", "|b1")


class StateValueError(ValueError):
    """A state value that does not fit its declared kind (one line: where, and why)."""


def _refuse(where: str, why: str) -> StateValueError:
    return StateValueError(f"{where}: {why}")


def _show(value: Any) -> str:
    text = repr(value)
    return text if len(text) <= 40 else text[:37] + "..."


class Kind:
    def encode(self, value: Any, parts: dict[str, bytes]) -> Any:
        return value

    def decode(self, value: Any, parts: dict[str, bytes], where: str) -> Any:
        raise NotImplementedError

    def describe(self) -> str:
        raise NotImplementedError


@dataclass(frozen=True)
class Int(Kind):
    lo: int | None = None
    hi: int | None = None

    def encode(self, value: Any, parts: dict[str, bytes]) -> Any:
        return int(value)

    def decode(self, value: Any, parts: dict[str, bytes], where: str) -> int:
        if type(value) is not int:
            raise _refuse(where, f"{_show(value)} is not a whole number")
        if (self.lo is not None and value < self.lo) or (self.hi is not None and
                                                         value > self.hi):
            raise _refuse(where, f"{_show(value)} is outside {self.lo}..{self.hi}")
        return value

    def describe(self) -> str:
        return f"int[{self.lo}..{self.hi}]"


@dataclass(frozen=True)
class Float(Kind):
    def encode(self, value: Any, parts: dict[str, bytes]) -> Any:
        return float(value)

    def decode(self, value: Any, parts: dict[str, bytes], where: str) -> float:
        if type(value) not in (int, float) or not math.isfinite(value):
            raise _refuse(where, f"{_show(value)} is not a finite number")
        return float(value)

    def describe(self) -> str:
        return "float"


@dataclass(frozen=True)
class Bool(Kind):
    def decode(self, value: Any, parts: dict[str, bytes], where: str) -> bool:
        if type(value) is not bool:
            raise _refuse(where, f"{_show(value)} is not true or false")
        return value

    def describe(self) -> str:
        return "bool"


@dataclass(frozen=True)
class Str(Kind):
    max_len: int = 4096

    def decode(self, value: Any, parts: dict[str, bytes], where: str) -> str:
        if type(value) is not str or len(value) > self.max_len:
            raise _refuse(where, f"{_show(value)} is not a text of at most "
                          f"{self.max_len} characters")
        return value

    def describe(self) -> str:
        return f"str[{self.max_len}]"


@dataclass(frozen=True)
class Choice(Kind):
    values: tuple[str, ...]

    def decode(self, value: Any, parts: dict[str, bytes], where: str) -> str:
        if value not in self.values or type(value) is not str:
            raise _refuse(where, f"{_show(value)} is not one of {list(self.values)}")
        return value

    def describe(self) -> str:
        return f"choice{list(self.values)}"


@dataclass(frozen=True)
class Frac(Kind):
    nonnegative: bool = False

    def encode(self, value: Any, parts: dict[str, bytes]) -> Any:
        f = Fraction(value)
        return [f.numerator, f.denominator]

    def decode(self, value: Any, parts: dict[str, bytes], where: str) -> Fraction:
        if not (isinstance(value, list) and len(value) == 2 and
                all(type(v) is int for v in value)):
            raise _refuse(where, f"{_show(value)} is not [numerator, denominator]")
        n, d = value
        if d <= 0 or max(abs(n), d).bit_length() > DIGITS * 10 // 3 + 1:
            raise _refuse(where, f"{_show(value)} is not a fraction of at most {DIGITS} "
                          "digits with a positive denominator")
        if self.nonnegative and n < 0:
            raise _refuse(where, f"{_show(value)} is negative")
        return Fraction(n, d)

    def describe(self) -> str:
        return "fraction>=0" if self.nonnegative else "fraction"


@dataclass(frozen=True)
class Opt(Kind):
    kind: Kind

    def encode(self, value: Any, parts: dict[str, bytes]) -> Any:
        return None if value is None else self.kind.encode(value, parts)

    def decode(self, value: Any, parts: dict[str, bytes], where: str) -> Any:
        return None if value is None else self.kind.decode(value, parts, where)

    def describe(self) -> str:
        return f"optional {self.kind.describe()}"


@dataclass(frozen=True)
class ListOf(Kind):
    kind: Kind
    max_len: int = 100_000

    def encode(self, value: Any, parts: dict[str, bytes]) -> Any:
        return [self.kind.encode(v, parts) for v in value]

    def decode(self, value: Any, parts: dict[str, bytes], where: str) -> list[Any]:
        if not isinstance(value, list) or len(value) > self.max_len:
            raise _refuse(where, f"not a list of at most {self.max_len}")
        return [self.kind.decode(v, parts, f"{where}[{i}]") for i, v in enumerate(value)]

    def describe(self) -> str:
        return f"list[{self.max_len}] of {self.kind.describe()}"


@dataclass(frozen=True)
class Tuple(Kind):
    kinds: tuple[Kind, ...]

    def encode(self, value: Any, parts: dict[str, bytes]) -> Any:
        return [k.encode(v, parts) for k, v in zip(self.kinds, value, strict=True)]

    def decode(self, value: Any, parts: dict[str, bytes], where: str) -> tuple[Any, ...]:
        if not isinstance(value, list) or len(value) != len(self.kinds):
            raise _refuse(where, f"not a list of {len(self.kinds)} values")
        return tuple(k.decode(v, parts, f"{where}[{i}]")
                     for i, (k, v) in enumerate(zip(self.kinds, value, strict=True)))

    def describe(self) -> str:
        return f"({', '.join(k.describe() for k in self.kinds)})"


class Record(Kind):
    """A mapping with exactly the declared keys (in code), each of its declared kind."""

    def __init__(self, **fields: Kind) -> None:
        self.fields = fields

    def encode(self, value: Any, parts: dict[str, bytes]) -> Any:
        return {name: kind.encode(value[name], parts) for name, kind in self.fields.items()}

    def decode(self, value: Any, parts: dict[str, bytes], where: str) -> dict[str, Any]:
        if not isinstance(value, dict):
            raise _refuse(where, "not a mapping")
        if set(value) != set(self.fields):
            odd = sorted(set(value) ^ set(self.fields), key=str)[:3]
            raise _refuse(where, f"its fields are not the declared ones (e.g. {_show(odd)})")
        return {name: kind.decode(value[name], parts, f"{where}.{name}")
                for name, kind in self.fields.items()}

    def describe(self) -> str:
        return "{" + ", ".join(f"{n}: {k.describe()}" for n, k in sorted(self.fields.items())) \
            + "}"


@dataclass(frozen=True)
class Array(Kind):
    """A numpy array of ``dtype`` with ``ndim`` dimensions, at most ``max_items`` items: in
    the JSON ``[part name, [shape]]``; the part holds its bytes (C order)."""

    dtype: str
    ndim: int
    max_items: int = 1 << 24

    def __post_init__(self) -> None:
        if np.dtype(self.dtype).str not in ALLOWED_DTYPES:
            raise TypeError(f"dtype {self.dtype} is not one a state may hold")

    def encode(self, value: Any, parts: dict[str, bytes]) -> Any:
        a = np.ascontiguousarray(value, dtype=np.dtype(self.dtype))
        name = f"a{len(parts)}"
        parts[name] = a.tobytes()
        return [name, list(a.shape)]

    def decode(self, value: Any, parts: dict[str, bytes], where: str) -> np.ndarray:
        if not (isinstance(value, list) and len(value) == 2 and isinstance(value[0], str)
                and isinstance(value[1], list) and len(value[1]) == self.ndim
                and all(type(n) is int and 0 <= n <= self.max_items for n in value[1])):
            raise _refuse(where, f"not an array reference [part, shape of {self.ndim}]")
        name, shape = value
        items = math.prod(shape)
        dt = np.dtype(self.dtype)
        if items > self.max_items:
            raise _refuse(where, f"shape {shape} holds more than {self.max_items} items")
        data = parts.get(name)
        if data is None or len(data) != items * dt.itemsize:
            raise _refuse(where, f"shape {shape} of {dt} needs {items * dt.itemsize} bytes; "
                          f"part {_show(name)} has {None if data is None else len(data)}")
        return np.frombuffer(data, dtype=dt).reshape(shape).copy()

    def describe(self) -> str:
        return f"array {np.dtype(self.dtype).str} {self.ndim}-d <= {self.max_items}"


def encode(schema: Kind, value: Any, parts: dict[str, bytes]) -> Any:
    return schema.encode(value, parts)


def decode(schema: Kind, value: Any, parts: dict[str, bytes], where: str = "state") -> Any:
    return schema.decode(value, parts, where)


def describe(schema: Kind) -> str:
    return schema.describe()


@dataclass(frozen=True)
class Blob(Kind):
    """Bytes (e.g. a machine's own versioned state), at most ``max_len``, in a binary part:
    in the JSON the part's name."""

    max_len: int = 64 << 20

    def encode(self, value: Any, parts: dict[str, bytes]) -> Any:
        name = f"b{len(parts)}"
        parts[name] = bytes(value)
        return name

    def decode(self, value: Any, parts: dict[str, bytes], where: str) -> bytes:
        data = parts.get(value) if isinstance(value, str) else None
        if data is None or len(data) > self.max_len:
            raise _refuse(where, f"{_show(value)} names no binary part of at most "
                          f"{self.max_len} bytes")
        return data

    def describe(self) -> str:
        return f"bytes[{self.max_len}]"


def depth(text: bytes) -> int:
    """The deepest nesting of ``[`` / ``{`` in a JSON text (strings skipped), counted
    without parsing, so text nested too deep is refused before json runs."""
    deepest = level = 0
    in_string = escaped = False
    for ch in text.translate(None, _OTHER_BYTES):  # brackets, quotes, backslashes
        if in_string:
            if escaped:
                escaped = False
            elif ch == 0x5C:
                escaped = True
            elif ch == 0x22:
                in_string = False
        elif ch == 0x22:
            in_string = True
        elif ch in (0x5B, 0x7B):
            level += 1
            deepest = max(deepest, level)
        elif ch in (0x5D, 0x7D):
            level -= 1
    return deepest


_OTHER_BYTES = bytes(c for c in range(256) if c not in b'[]{}"\\')  # translate deletes


@dataclass(frozen=True)
class JsonText(Kind):
    """A JSON document a program's own versioned reader checks (e.g. a snooker session
    file's contents), at most ``max_len`` bytes and ``max_depth`` deep, in a binary part."""

    max_len: int = 32 << 20
    max_depth: int = 16

    def encode(self, value: Any, parts: dict[str, bytes]) -> Any:
        return Blob(self.max_len).encode(json.dumps(value, separators=(",", ":")).encode(),
                                         parts)

    def decode(self, value: Any, parts: dict[str, bytes], where: str) -> Any:
        data = Blob(self.max_len).decode(value, parts, where)
        if depth(data) > self.max_depth:
            raise _refuse(where, f"JSON nested deeper than {self.max_depth}")
        try:
            return json.loads(data.decode("utf-8"))
        except (UnicodeDecodeError, ValueError) as exc:
            raise _refuse(where, f"not JSON: {str(exc).splitlines()[0][:80]}") from None

    def describe(self) -> str:
        return f"json[{self.max_len}, depth {self.max_depth}]"
