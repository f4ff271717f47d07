"""Command-line tools for the link: ``python -m camlab88.protocols.link`` (or ``camlab88 link``).

* ``dump REC``: a recording in readable form.
* ``stream REC --out FILE``: the bytes one end received, as a raw stream file.
* ``echo --pty | --listen PORT | --url URL``: an echoing device on a paced line, to check a
  program's or a cable's connection (and recording) before the real devices are attached.
"""

from __future__ import annotations

import argparse
import contextlib
import signal
import sys
import threading
from collections.abc import Iterator
from fractions import Fraction
from typing import Any

from camlab88.base.atomicfile import write_atomic
from camlab88.protocols.link.cli_args import (
    ECHO_HELP,
    STREAM_HELP,
    add_echo_arguments,
    add_stream_arguments,
)
from camlab88.protocols.link.line import SerialLine
from camlab88.protocols.link.recording import Recorder, RecordingError, read_recording
from camlab88.protocols.link.settings import LineSettings
from camlab88.protocols.link.throttle import Throttle

_PRINTABLE = {i: chr(i) for i in range(0x20, 0x7F) if chr(i) != "\\"}


def printable(data: bytes) -> str:
    """Bytes as readable text: ASCII as is, the rest as \\xNN (and \\r, \\n)."""
    out = []
    for b in data:
        if b in _PRINTABLE:
            out.append(_PRINTABLE[b])
        elif b == 0x0D:
            out.append("\\r")
        elif b == 0x0A:
            out.append("\\n")
        else:
            out.append(f"\\x{b:02x}")
    return "".join(out)


def dump(path: str, out: Any = sys.stdout) -> int:
    try:
        rec = read_recording(path)
    except RecordingError as exc:  # names the file and line
        print(f"error: {exc}", file=sys.stderr)
        return 2  # an unusable input (camlab88's exit status rule)
    print(f"# {path}: {rec.settings}, xonxoff {'on' if rec.xonxoff else 'off'}, "
          f"{len(rec.exact_entries)} chunks, {float(rec.duration):.6f} s", file=out)
    for e in rec.exact_entries:
        print(f"{float(e.t):12.6f} {e.direction} {printable(e.data)}", file=out)
    for d, name in ((">", "host to device"), ("<", "device to host")):
        print(f"# {name}: {len(rec.stream(d, raw=True))} bytes", file=out)
    return 0


def write_stream(path: str, out_path: str, direction: str) -> int:
    try:
        data = read_recording(path).stream(direction)
    except RecordingError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2  # an unusable input (camlab88's exit status rule)
    try:
        write_atomic(out_path, data)
    except OSError as exc:
        print(f"error: cannot write {out_path}: {exc.strerror or exc}", file=sys.stderr)
        return 2
    print(f"{len(data)} bytes written to {out_path}")
    return 0


def run_echo(
    bridge: Any,
    line: SerialLine,
    *,
    seconds: float | None = None,
    speed: float | None = 1.0,
    stop: threading.Event | None = None,
    fps: int = 100,
    log: Any = None,
) -> int:
    """Poll ``bridge`` (attached to line.host) on a fixed virtual grid; the device end echoes.

    Returns the number of bytes echoed. Stops after ``seconds`` of line time or when ``stop``
    is set."""
    throttle = Throttle(speed)
    step = Fraction(1, fps)
    echoed = 0
    k = 0
    while (seconds is None or k * step < seconds) and not (stop and stop.is_set()):
        line.clock.advance_to(k * step)
        result = bridge.poll(timeout=0.0)
        for event in result.events:
            if log:
                print(f"{float(line.clock.exact):.3f} s: {event.kind} {event.detail}", file=log)
        data = line.device.read()
        if data:
            line.device.write(data)
            echoed += len(data)
        throttle.pace(k * step)
        k += 1
    return echoed


@contextlib.contextmanager
def _sigterm_as_interrupt() -> Iterator[None]:
    """SIGTERM (kill, a service manager stopping us) ends the echo like Ctrl-C does, so the
    recording is finished and written; the old handler comes back after."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return

    def interrupt(signum: int, frame: object) -> None:
        raise KeyboardInterrupt

    old = signal.signal(signal.SIGTERM, interrupt)
    try:
        yield
    finally:
        signal.signal(signal.SIGTERM, old)


def echo_command(args: argparse.Namespace) -> int:
    """The echo device with the options of :func:`add_echo_arguments`, until Ctrl-C/SIGTERM or
    ``--seconds`` of line time."""
    from camlab88.protocols.link.transports import (
        IDLE_TIMEOUT,
        SESSION_TIME,
        PtyBridge,
        SerialUrlBridge,
        TcpBridge,
    )

    settings = LineSettings.parse(f"{args.baud} {args.framing}")
    recorder = Recorder(args.record, settings, xonxoff=not args.no_xonxoff) if args.record else None
    line = SerialLine(settings, xonxoff=not args.no_xonxoff, recorder=recorder)
    bridge: Any
    if args.listen is not None:
        bridge = TcpBridge(args.listen, endpoint=line.host, idle_timeout=IDLE_TIMEOUT,
                           session_time=SESSION_TIME)
        print(f"echo device on a {settings} line: connect to 127.0.0.1:{bridge.port}", flush=True)
    elif args.url:
        bridge = SerialUrlBridge(args.url, settings, endpoint=line.host)
        print(f"echo device on a {settings} line via {args.url}", flush=True)
    else:
        bridge = PtyBridge(endpoint=line.host)
        print(f"echo device on a {settings} line: open {bridge.slave_path} as a serial port",
              flush=True)
    try:
        with _sigterm_as_interrupt():
            n = run_echo(bridge, line, seconds=args.seconds, speed=args.speed or None,
                         log=sys.stdout)
    except KeyboardInterrupt:
        n = -1
    finally:
        bridge.close()
        line.close()
    if n >= 0:
        print(f"{n} bytes echoed")
    if args.record:
        print(f"recording written to {args.record}")
    return 0


def add_tools(link: argparse.ArgumentParser) -> None:
    sub = link.add_subparsers(dest="link_command", metavar="TOOL")
    sub.required = True
    p = sub.add_parser("dump", help="print a link recording readably")
    p.add_argument("recording")
    p.set_defaults(handler=lambda a: dump(a.recording))
    p = sub.add_parser("stream", help=STREAM_HELP)
    add_stream_arguments(p)
    p.set_defaults(handler=lambda a: write_stream(a.recording, a.out, a.direction))
    p = sub.add_parser("echo", help=ECHO_HELP)
    add_echo_arguments(p)
    p.set_defaults(handler=echo_command)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        prog="python -m camlab88.protocols.link",
        description="Tools for the emulated serial line (see docs/link.md).",
    )
    add_tools(parser)
    args = parser.parse_args(argv)
    return int(args.handler(args) or 0)
