"""The argument types of an ahead-of-time kernel, read from its numba signature and checked
before every call.

A function of an extension built by ``numba.pycc`` has exactly one signature, and its
argument conversion does not check an array's dtype or number of dimensions (numba's own
``unbox_array`` says so): an int32 array passed where int64 was compiled is read as int64,
out of bounds. The JIT dispatcher would instead have compiled another specialisation. So
each exported kernel is wrapped by a generated function that compares every array's dtype,
dimensions and (for ``[::1]`` layouts) contiguity with the signature and raises TypeError on
a mismatch; a few hundred nanoseconds per call. Scalars are checked as integer or real
numbers; booleans are taken by truth as numba does.

The signature language understood is the subset the kernel modules use, parsed without
numba (the point of the ahead-of-time path is a process that never imports it): scalar
names (``int64``, ``uint8``, ``intp``, ``float64``, ``boolean``, ...) and arrays of them
(``int64[:]``, ``uint8[:, ::1]``, ...). The return type is not read.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

_NUMBERS = {name: np.dtype(name) for name in (
    "int8", "int16", "int32", "int64", "uint8", "uint16", "uint32", "uint64", "intp",
    "float32", "float64")}
_BOOLEANS = ("boolean", "bool_")


@dataclass(frozen=True)
class Arg:
    """One argument: a scalar (ndim 0) or an array of ``dtype``."""

    text: str
    dtype: np.dtype | None  # None: boolean scalar
    ndim: int = 0
    contiguous: bool = False  # last dimension ``::1``: the array must be C-contiguous


def parse(signature: str) -> tuple[Arg, ...]:
    """The arguments of ``"ret(arg, arg, ...)"``; ValueError for anything else."""
    text = signature.strip()
    if not text.endswith(")"):
        raise ValueError(f"not a kernel signature: {signature!r}")
    depth = 0
    for i in range(len(text) - 1, -1, -1):  # the parenthesis opening the argument list
        depth += {")": 1, "(": -1}.get(text[i], 0)
        if depth == 0:
            break
    else:
        raise ValueError(f"unbalanced parentheses in {signature!r}")
    inner = text[i + 1:-1].strip()
    return tuple(_arg(part.strip(), signature) for part in _split(inner)) if inner else ()


def _split(text: str) -> list[str]:
    parts, depth, start = [], 0, 0
    for i, ch in enumerate(text):
        depth += {"[": 1, "(": 1, "]": -1, ")": -1}.get(ch, 0)
        if ch == "," and depth == 0:
            parts.append(text[start:i])
            start = i + 1
    parts.append(text[start:])
    return parts


def _arg(text: str, signature: str) -> Arg:
    name, _, dims = text.partition("[")
    name = name.strip()
    if name in _BOOLEANS and not dims:
        return Arg(text, None)
    if name not in _NUMBERS:
        raise ValueError(f"argument type {text!r} of {signature!r} is not one the "
                         "ahead-of-time path knows")
    if not dims:
        return Arg(text, _NUMBERS[name])
    axes = [a.replace(" ", "") for a in dims.rstrip("]").split(",")]
    if not dims.endswith("]") or any(a not in (":", "::1") for a in axes) or (
            "::1" in axes[:-1]):
        raise ValueError(f"array type {text!r} of {signature!r}: only [:, ..., :] or "
                         "[:, ..., ::1] layouts")
    return Arg(text, _NUMBERS[name], len(axes), axes[-1] == "::1")


def describe(value: Any) -> str:
    """A value's type in the signature language, for error messages."""
    if isinstance(value, np.ndarray):
        layout = "::1" if value.flags.c_contiguous else ":"
        return f"{value.dtype}[{', '.join([':'] * (value.ndim - 1) + [layout])}]"
    return type(value).__name__


def checked(fn: Callable[..., Any], name: str, signature: str) -> Callable[..., Any]:
    """``fn`` behind a check of its arguments against ``signature`` (see the module doc)."""
    args = parse(signature)
    names = [f"a{i}" for i in range(len(args))]
    env: dict[str, Any] = {"_f": fn, "_INT": (int, np.integer),
                           "_REAL": (int, float, np.integer, np.floating)}
    tests = []
    for i, (a, arg) in enumerate(zip(names, args)):
        if arg.ndim:
            env[f"_d{i}"] = arg.dtype
            # (an array numba made has an equal dtype object, not numpy's own one)
            tests.append(f"({a}.dtype is not _d{i} and {a}.dtype != _d{i}) "
                         f"or {a}.ndim != {arg.ndim}")
            if arg.contiguous:
                tests.append(f"not {a}.flags.c_contiguous")
        elif arg.dtype is not None:
            tests.append(f"not isinstance({a}, {'_REAL' if arg.dtype.kind == 'f' else '_INT'})")
    params = ", ".join(names)
    env["_refuse"] = lambda *values: _refuse(name, signature, args, values)
    body = (f"    if {' or '.join(tests)}:\n        _refuse({params})\n" if tests else "")
    source = f"def {name}({params}):\n{body}    return _f({params})\n"
    exec(compile(source, f"<ahead-of-time kernel {name}>", "exec"), env)
    wrapper = env[name]
    wrapper.__doc__ = getattr(fn, "__doc__", None)
    wrapper.__wrapped__ = fn
    return wrapper


def _refuse(name: str, signature: str, args: tuple[Arg, ...], values: tuple) -> None:
    wrong = [f"argument {i + 1} is {describe(v)}, compiled for {a.text}"
             for i, (a, v) in enumerate(zip(args, values)) if not _fits(a, v)]
    raise TypeError(f"ahead-of-time kernel {name} ({signature}): "
                    + ("; ".join(wrong) or "arguments differ from the compiled types"))


def _fits(arg: Arg, value: Any) -> bool:
    if arg.ndim:
        return (isinstance(value, np.ndarray) and value.dtype == arg.dtype
                and value.ndim == arg.ndim and (value.flags.c_contiguous or not arg.contiguous))
    if arg.dtype is None:
        return True
    return isinstance(value, (int, float, np.integer, np.floating) if arg.dtype.kind == "f"
                      else (int, np.integer))
