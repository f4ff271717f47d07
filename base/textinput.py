"""Reading an input file: the one place that turns a path into bytes, text or JSON.

Every reader of a file format outside camlab88/ goes through here, so that bad input gets one
kind of answer everywhere (docs/reliability.md): an error naming the file and, for a bad
byte, its line and column; a directory, a missing file or a file too large for the format
refused before any work; numbers in JSON bounded to the digits a format can mean; nesting
bounded before Python's recursion limit is reached; quoted input shortened so that an error
about a 1 MB line does not print the line.
"""

from __future__ import annotations

import json
import os
import re
from pathlib import Path
from typing import Any

import numpy as np

# No format of ours needs a larger file; the biggest legitimate ones (a 4000x4000 RLE, long
# link recordings) are a few MB.
MAX_FILE_BYTES = 256 * 1024 * 1024
# JSON formats of ours nest a few levels deep; 64 is generous and far below the recursion limit
MAX_JSON_DEPTH = 64
# an int64 has 19 digits; a 20th digit is never a meaningful coordinate, count or time
MAX_NUMBER_DIGITS = 20
QUOTE_CHARS = 60
_OPEN = np.array([ord("["), ord("{")], np.uint32)
_CLOSE = np.array([ord("]"), ord("}")], np.uint32)


class InputError(ValueError):
    """Bad input: the message starts with ``file:line:column:`` (as much of it as is known);
    ``name``, ``line``, ``column`` and ``reason`` hold the parts, so a format can re-raise it
    as its own error class."""

    def __init__(self, message: str, name: str = "", line: int = 0, column: int = 0,
                 reason: str = "") -> None:
        super().__init__(message)
        self.name, self.line, self.column = name, line, column
        self.reason = reason or message


def _error(error: type[ValueError], name: str, reason: str, line: int | None = None,
           column: int | None = None) -> ValueError:
    message = f"{where(name, line, column)}: {reason}"
    if issubclass(error, InputError):
        return error(message, str(name), line or 0, column or 0, reason)
    return error(message)


def where(name: str, line: int | None = None, column: int | None = None) -> str:
    """``name``, ``name:line`` or ``name:line:column`` — the prefix of every input error."""
    out = str(name)
    if line is not None:
        out += f":{line}"
        if column is not None:
            out += f":{column}"
    return out


def quote(text: object, limit: int = QUOTE_CHARS) -> str:
    """repr() of ``text`` cut to about ``limit`` characters, saying how much was cut (any
    other value — a number or list from JSON — is shown by its repr, cut the same way)."""
    if not isinstance(text, (str, bytes)):
        shown = repr(text)
        return shown if len(shown) <= limit else f"{shown[:limit]}... ({len(shown)} characters)"
    if len(text) <= limit:
        return repr(text)
    return f"{text[:limit]!r}... ({len(text)} characters)"


def read_bytes(path: str | os.PathLike[str], limit: int = MAX_FILE_BYTES,
               error: type[ValueError] = InputError) -> bytes:
    """The file's bytes; a directory, a missing file or one over ``limit`` bytes raises
    ``error`` naming the file (never IsADirectoryError or a MemoryError)."""
    p = Path(path)
    try:
        with open(p, "rb") as fh:
            size = os.fstat(fh.fileno()).st_size
            if size > limit:
                raise _error(error, str(p), f"{size} bytes is larger than this format allows "
                                            f"({limit})")
            data = fh.read(limit + 1)
    except IsADirectoryError:
        raise _error(error, str(p), "is a directory, not a file") from None
    except OSError as exc:
        raise _error(error, str(p), f"cannot read: {exc.strerror or exc}") from None
    if len(data) > limit:  # a pipe or a growing file: fstat said less
        raise _error(error, str(p), f"larger than this format allows ({limit} bytes)")
    return data


def line_column(data: bytes, offset: int) -> tuple[int, int]:
    """1-based line and column (in bytes) of byte ``offset``."""
    line_start = data.rfind(b"\n", 0, offset) + 1
    return data.count(b"\n", 0, offset) + 1, offset - line_start + 1


def decode_utf8(data: bytes, name: str, error: type[ValueError] = InputError,
                bom: bool = False) -> str:
    """UTF-8 text of ``data``. A bad byte raises ``error`` at ``name:line:column``. A byte-order
    mark is dropped when ``bom`` (editors on Windows write one) and refused otherwise, because
    in a format whose first line is a magic word it would silently change the meaning."""
    if data.startswith(b"\xef\xbb\xbf"):
        if not bom:
            raise _error(error, name, "starts with a UTF-8 byte-order mark; save the file "
                                      "without one", 1, 1)
        data = data[3:]
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError as exc:
        line, col = line_column(data, exc.start)
        raise _error(error, name, f"byte 0x{data[exc.start]:02x} is not UTF-8 text", line,
                     col) from None


def read_text(path: str | os.PathLike[str], limit: int = MAX_FILE_BYTES,
              error: type[ValueError] = InputError, bom: bool = True) -> str:
    """``read_bytes`` then ``decode_utf8``: the file's text, or ``error`` naming where."""
    return decode_utf8(read_bytes(path, limit, error), str(path), error, bom)


_DIGITS = re.compile(r"-?[0-9]+")


_JSON_STRING = re.compile(r'"[^"\\]*(?:\\.[^"\\]*)*"')


def _json_depth_error(text: str, max_depth: int) -> int | None:
    """Offset of the first bracket nested deeper than ``max_depth`` outside strings (strings
    blanked to equal length so offsets still point into ``text``; numpy keeps it fast)."""
    bare = _JSON_STRING.sub(lambda m: " " * len(m.group()), text)
    codes = np.frombuffer(bare.encode("utf-32-le"), np.uint32)
    step = (np.isin(codes, _OPEN).astype(np.int32) - np.isin(codes, _CLOSE))
    deep = np.flatnonzero(np.cumsum(step) > max_depth)
    return int(deep[0]) if deep.size else None


def _bounded_int(text: str, digits: int, error: type[ValueError]) -> int:
    if len(text.lstrip("-")) > digits:
        raise error(f"a number of {len(text.lstrip('-'))} digits ({quote(text, 24)}); "
                    f"this format's numbers have at most {digits}")
    return int(text)


def _finite_float(text: str, digits: int, error: type[ValueError]) -> float:
    if len(text) > 4 * digits:
        raise error(f"a number written in {len(text)} characters ({quote(text, 24)})")
    value = float(text)
    if value != value or value in (float("inf"), float("-inf")):
        raise error(f"{quote(text, 24)} is too large for a number")
    return value


def _no_constant(text: str) -> Any:
    raise InputError(f"{text} is not a number JSON allows")


def loads_json(text: str, name: str, error: type[ValueError] = InputError,
               max_depth: int = MAX_JSON_DEPTH, digits: int = MAX_NUMBER_DIGITS) -> Any:
    """JSON with bounds: nesting deeper than ``max_depth``, a number of more than ``digits``
    digits, NaN or Infinity raise ``error`` naming ``name`` (and the line:column when JSON
    knows it) — not RecursionError, ValueError from int(), or OverflowError later."""
    deep = _json_depth_error(text, max_depth) if text.count("[") + text.count("{") > max_depth \
        else None  # the scan costs a little: skip it when there are too few brackets to matter
    if deep is not None:
        line = text.count("\n", 0, deep) + 1
        col = deep - text.rfind("\n", 0, deep)
        raise error(f"{where(name, line, col)}: nested deeper than {max_depth} levels")
    try:
        return json.loads(text, parse_int=lambda s: _bounded_int(s, digits, InputError),
                          parse_float=lambda s: _finite_float(s, digits, InputError),
                          parse_constant=_no_constant)
    except json.JSONDecodeError as exc:
        raise error(f"{where(name, exc.lineno, exc.colno)}: not JSON ({exc.msg})") from None
    except InputError as exc:
        raise error(f"{name}: {exc}") from None
    except RecursionError:  # unreachable after the depth scan; kept so no input can crash
        raise error(f"{name}: nested too deeply") from None


def read_json(path: str | os.PathLike[str], error: type[ValueError] = InputError,
              limit: int = MAX_FILE_BYTES, max_depth: int = MAX_JSON_DEPTH,
              digits: int = MAX_NUMBER_DIGITS) -> Any:
    """``read_text`` then ``loads_json``."""
    return loads_json(read_text(path, limit, error), str(path), error, max_depth, digits)


def parse_int(text: str, name: str, lo: int, hi: int,
              error: type[ValueError] = InputError, what: str = "number") -> int:
    """A decimal (ASCII digits, optional sign) in ``lo..hi``; anything else raises ``error``
    saying what was expected — never int()'s own message, never a number the format
    cannot hold."""
    if not _DIGITS.fullmatch(text.strip()):
        raise error(f"{name}: bad {what} {quote(text, 24)} (a whole number is expected)")
    stripped = text.strip()
    if len(stripped.lstrip("-")) > max(len(str(lo)), len(str(hi))) + 1:
        raise error(f"{name}: {what} {quote(stripped, 24)} is outside {lo}..{hi}")
    value = int(stripped)
    if not lo <= value <= hi:
        raise error(f"{name}: {what} {value} is outside {lo}..{hi}")
    return value
