"""A serial line's state as JSON-able values: both transmitters with their queued bytes, the
flow-control events in flight, the bytes delivered but not yet read, all in UART ticks.

The clock is not part of it (a machine saves its clock itself); neither is a recorder.
``load`` checks everything before it changes anything.
"""

from __future__ import annotations

from collections import deque
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from camlab88.protocols.link.line import SerialLine, _Direction

VERSION = 1
_INTS = ("pending_flows", "tx_free", "tail", "sent", "flow_sent")


def save(line: SerialLine) -> dict[str, Any]:
    return {"version": VERSION, "settings": str(line.settings), "xonxoff": line.xonxoff,
            ">": _save_dir(line._h2d), "<": _save_dir(line._d2h)}


def _save_dir(d: _Direction) -> dict[str, Any]:
    out: dict[str, Any] = {k: getattr(d, k) for k in _INTS}
    out["base_paused"], out["tail_stale"] = d.base_paused, d.tail_stale
    out["pending"] = [[s.earliest, s.data.hex(), s.pos, s.flows] for s in d.pending]
    out["control"] = [[t, x] for t, x in d.control]
    out["delivered"] = [[first, data.hex(), off] for first, data, off in d.delivered]
    return out


def load(line: SerialLine, state: object) -> None:
    """Put back save()'s dict; ValueError naming the first bad entry."""
    if not isinstance(state, dict) or state.get("version") != VERSION:
        raise ValueError(f"line state version {_get(state, 'version')!r} is not {VERSION}")
    if state.get("settings") != str(line.settings) or state.get("xonxoff") != line.xonxoff:
        raise ValueError(f"line state is for a {state.get('settings')} line "
                         f"(xonxoff {state.get('xonxoff')}), this line is {line.settings} "
                         f"(xonxoff {line.xonxoff})")
    parsed = {name: _parse_dir(state.get(name), name) for name in (">", "<")}
    for name, d in ((">", line._h2d), ("<", line._d2h)):
        _apply(d, parsed[name])


def _get(state: object, key: str) -> object:
    return state.get(key) if isinstance(state, dict) else None


def _int(v: object, what: str) -> int:
    if type(v) is not int or v < 0:
        raise ValueError(f"line state {what}={v!r} is not a count")
    return v


def _parse_dir(d: object, name: str) -> dict[str, Any]:
    from camlab88.protocols.link.line import _Segment

    if not isinstance(d, dict):
        raise ValueError(f"line state direction {name!r} is missing")
    try:
        out: dict[str, Any] = {k: _int(d[k], f"{name}.{k}") for k in _INTS}
        out["base_paused"], out["tail_stale"] = bool(d["base_paused"]), bool(d["tail_stale"])
        pending = deque()
        for earliest, data, pos, flows in d["pending"]:
            seg = _Segment(_int(earliest, f"{name}.pending"), bytes.fromhex(data),
                           _int(flows, f"{name}.pending"))
            seg.pos = _int(pos, f"{name}.pending")
            if seg.pos >= len(seg.data):
                raise ValueError(f"line state {name}.pending segment is already sent")
            pending.append(seg)
        out["pending"] = pending
        out["control"] = deque((_int(t, f"{name}.control"), bool(x)) for t, x in d["control"])
        out["delivered"] = deque([_int(f, f"{name}.delivered"), bytes.fromhex(h),
                                  _int(o, f"{name}.delivered")] for f, h, o in d["delivered"])
    except (KeyError, TypeError, ValueError) as exc:
        raise ValueError(f"line state direction {name!r} is corrupt: {exc}") from None
    return out


def _apply(d: _Direction, values: dict[str, Any]) -> None:
    for k, v in values.items():
        setattr(d, k, v)
