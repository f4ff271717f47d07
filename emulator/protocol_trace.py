"""One line of a protocol trace (either device) and the error strict mode raises."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any


@dataclass
class TraceEvent:
    """One decoded order (``warning`` None) or one problem (``warning`` says what)."""

    offset: int  # stream offset of the order's first byte
    time: float  # virtual seconds when its last byte arrived
    order: str
    args: dict[str, Any] = field(default_factory=dict)
    warning: str | None = None
    kind: str | None = None  # "unknown", "malformed", "out of range"
    expected: str | None = None
    context: bytes = b""

    def as_dict(self) -> dict[str, Any]:
        """The event as a dict of JSON types (what ``to_json`` writes)."""
        out: dict[str, Any] = {"offset": self.offset, "time": round(self.time, 9),
                               "order": self.order, "args": self.args}
        if self.warning is not None:
            out.update(warning=self.warning, kind=self.kind, expected=self.expected,
                       context=self.context.decode("latin-1"))
        return out

    def to_json(self) -> str:
        """The event as one line of JSON text (a ``--trace`` file's line)."""
        import json

        return json.dumps(self.as_dict(), ensure_ascii=False)

    def message(self) -> str:
        """One line: where, what, the bytes leading up to it, and what was expected."""
        return (f"byte {self.offset} (t={self.time:.6f} s): {self.warning}; bytes up to it: "
                f"{self.context!r}; expected {self.expected}")


class ProtocolError(Exception):
    """Strict mode: the first unknown, malformed or out-of-range order."""

    def __init__(self, event: TraceEvent) -> None:
        super().__init__(event.message())
        self.event = event


class TraceFile:
    """``--trace FILE``: one JSON object a line, written atomically when closed (a run
    stopped by --strict or Ctrl-C still leaves the whole trace up to that point)."""

    def __init__(self, path: str) -> None:
        from contextlib import ExitStack

        from camlab88.base.atomicfile import atomic_output

        self.path = path
        self._stack = ExitStack()
        self._fh = self._stack.enter_context(atomic_output(path, "w", encoding="utf-8"))
        self.count = 0

    def __call__(self, ev: TraceEvent) -> None:
        self._fh.write(ev.to_json() + "\n")
        self.count += 1

    def close(self) -> None:
        self._stack.close()
