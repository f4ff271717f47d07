"""An independent, byte-at-a-time model of the line, used to check SerialLine's schedule."""

from __future__ import annotations

from fractions import Fraction

XON, XOFF = 0x11, 0x13


def simulate(
    ct: Fraction, writes: list[tuple[Fraction, str, bytes]], xonxoff: bool = True
) -> dict[str, list[tuple[Fraction, int]]]:
    """Arrival times of every delivered byte per direction (">" and "<"), one byte per step."""
    queues: dict[str, list[tuple[Fraction, int]]] = {">": [], "<": []}
    for t, d, data in sorted(writes, key=lambda w: w[0]):
        queues[d].extend((t, b) for b in data)
    free = {">": Fraction(0), "<": Fraction(0)}
    # flow events that control a direction's transmitter: (arrival, is_xoff)
    control: dict[str, list[tuple[Fraction, bool]]] = {">": [], "<": []}
    out: dict[str, list[tuple[Fraction, int]]] = {">": [], "<": []}
    other = {">": "<", "<": ">"}
    # when each direction's last byte (data or flow) arrived, or None if bytes are stuck
    drained: dict[str, Fraction | None] = {">": Fraction(0), "<": Fraction(0)}

    def next_start(d: str) -> Fraction | None:
        if not queues[d]:
            return None
        earliest, byte = queues[d][0]
        s = max(free[d], earliest)
        if not xonxoff or byte in (XON, XOFF):
            return s
        paused = False
        for when, xoff in control[d]:
            if when <= s:
                paused = xoff
        if not paused:
            return s
        resumes = [w for w, xoff in control[d] if w > s and not xoff]
        return min(resumes) if resumes else None

    while True:
        starts = {d: next_start(d) for d in (">", "<")}
        live = [(s, d) for d, s in starts.items() if s is not None]
        if not live:
            for d in (">", "<"):
                if queues[d]:
                    drained[d] = None
            out["drained"] = drained
            return out
        s, d = min(live)
        _, byte = queues[d].pop(0)
        free[d] = s + ct
        drained[d] = s + ct
        if xonxoff and byte in (XON, XOFF):
            control[other[d]].append((s + ct, byte == XOFF))
        else:
            out[d].append((s + ct, byte))
