"""``camlab88 link dump REC``: a link recording in readable form."""

from __future__ import annotations

import argparse
import sys

SESSION_NOTE = ("is a session recording, not a link recording: `sigma run --record FILE` "
                "now writes a session recording (play it with `camlab88 replay FILE`); "
                "`sigma run --record-line FILE` writes the link recording that `link dump` reads")

DESCRIPTION = """\
Print a link recording (sigma run --record-line FILE, link record ...) readably: one timed \
chunk a line."""


HELP = "print a link recording readably"


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("recording")
    p.add_argument("--decode", action="store_true",
                   help="show the host-to-terminal bytes as decoded Sigma orders (byte "
                        "offset, arrival time, order, arguments, warnings) and the replies as "
                        "text")
    p.add_argument("--model", default="t5684", choices=["t5684", "t5688"],
                   help="the terminal that decodes them (with --decode)")


def run(args: argparse.Namespace) -> int:
    from camlab88.protocols.link.cli import dump as dump_recording

    if _is_session_recording(args.recording):
        print(f"error: {args.recording} {SESSION_NOTE}", file=sys.stderr)
        return 2
    if args.decode:
        return _decode(args)
    return dump_recording(args.recording)


def _decode(args: argparse.Namespace) -> int:
    """Every order at its arrival time, replies (``<``) interleaved by time."""
    import json

    from camlab88.emulator.sigma import Terminal
    from camlab88.emulator.sigma.trace_stream import StreamTracer
    from camlab88.protocols.link.recording import RecordingError, read_recording

    try:
        rec = read_recording(args.recording)
    except (RecordingError, OSError) as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 1
    lines: list[tuple[float, int, str]] = []

    def show(ev) -> None:
        text = f"{ev.time:12.6f} > {ev.offset:8d} {ev.order:<10} {json.dumps(ev.args)}"
        if ev.warning is not None:
            text += f"  !! {ev.kind}: {ev.warning}; expected {ev.expected}"
        lines.append((ev.time, len(lines), text))

    tracer = StreamTracer(Terminal(args.model), rec, rec.settings.char_time, show)
    tracer.feed(rec.stream(">"))
    for t, data in rec.arrivals("<"):
        lines.append((float(t), len(lines), f"{float(t):12.6f} < {data!r}"))
    for _t, _k, text in sorted(lines):
        print(text)
    print(f"# {tracer.tracer.warnings} protocol warnings")
    return 0


def _is_session_recording(path: str) -> bool:
    """True when the file's first line is a session recording's header (protocols.session)."""
    import json

    from camlab88.protocols.session import FORMAT

    try:
        with open(path, "rb") as f:
            first = f.readline(4096)
        obj = json.loads(first)
    except (OSError, ValueError):
        return False  # unreadable or not JSON: the link reader gives its own error
    return isinstance(obj, dict) and obj.get("format") == FORMAT
