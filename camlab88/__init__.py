"""camlab88: the command-line entry point and the glue that wires programs to devices.

Public API (docs/api.md): ``from camlab88 import Sigma, Rainbow`` — emulated devices for
testing host software — ``ProtocolError`` / ``TraceEvent`` of their protocol traces, and
``RainbowRefused``, what a refused pad-library call raises.
They load on first use, so ``import camlab88`` (and ``camlab88 --help``) stays fast.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

__version__ = "0.1.0"
__all__ = ["ProtocolError", "Rainbow", "RainbowRefused", "Sigma", "TraceEvent"]

_HOMES = {
    "Sigma": "camlab88.bench.sigma",
    "Rainbow": "camlab88.bench.rainbow",
    "ProtocolError": "camlab88.emulator.protocol_trace",
    "TraceEvent": "camlab88.emulator.protocol_trace",
    "RainbowRefused": "camlab88.protocols.rainbow.client",
}

if TYPE_CHECKING:
    from camlab88.bench.rainbow import Rainbow
    from camlab88.bench.sigma import Sigma
    from camlab88.emulator.protocol_trace import ProtocolError, TraceEvent
    from camlab88.protocols.rainbow.client import RainbowRefused


def __getattr__(name: str) -> Any:
    home = _HOMES.get(name)
    if home is None:
        raise AttributeError(f"module 'camlab88' has no attribute {name!r}")
    import importlib

    value = getattr(importlib.import_module(home), name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted([*globals(), *__all__])
