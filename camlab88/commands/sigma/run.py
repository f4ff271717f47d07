"""``camlab88 sigma run``: a terminal on a paced 9600-baud line, its outside end a pty, a
TCP port or a serial URL; in a window (or headless, line only) on the harness."""

from __future__ import annotations

import argparse
import contextlib
import sys
from fractions import Fraction
from pathlib import Path

from camlab88.commands.sigma import MODELS
from camlab88.replay_policy import DROP, KEEP, OUTSIDE
from camlab88.runopts import add_run_options, run_options
from camlab88.traceopts import add_trace_options, open_trace

COMMAND = "camlab88 sigma run"
FRAME = Fraction(1, 25)


def _seconds(text: str) -> Fraction:
    import re

    if not re.fullmatch(r"[0-9]{1,5}(\.[0-9]{1,6})?", text):  # no exponent: 1e999999 hangs
        raise argparse.ArgumentTypeError(f"{text[:40]!r} is not a number of seconds (N or N.M)")
    value = Fraction(text)
    if not 0 < value <= 86400:
        raise argparse.ArgumentTypeError(f"{text} s is not in (0, 86400]")
    return value


def _die(message: str) -> SystemExit:
    return SystemExit(f"{COMMAND}: {message}")

HELP = "an interactive terminal in a window"
DESCRIPTION = """\
Run an emulated terminal in a window, its line on a pseudo-terminal (--pty) or a TCP port on \
127.0.0.1 (--listen). Keys typed into the window go up the line (cursor keys move the \
crosshair during a cursor read), the mouse is the tablet. --screenshot: the screen at \
--seconds, else once the --in stream has arrived."""


HELP = HELP


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("--model", default="t5684", choices=MODELS).replay = KEEP
    outside_end = p.add_mutually_exclusive_group()
    outside_end.add_argument("--pty", action="store_true",
                             help="open a pseudo-terminal (the default)").replay = OUTSIDE
    outside_end.add_argument("--listen", type=int, metavar="PORT",
                             help="listen on 127.0.0.1:PORT").replay = OUTSIDE
    outside_end.add_argument("--serial", metavar="URL",
                             help="any pyserial URL, e.g. /dev/ttyUSB0").replay = OUTSIDE
    p.add_argument("--baud", type=int,
                   help="line speed (default 9600, or that of an --in recording)").replay = KEEP
    p.add_argument("--in", dest="stream", type=Path,
                   help="also play this stream down the line: raw bytes back to back from "
                        "the start, a recording at its recorded times").replay = KEEP
    p.add_argument("--seconds", type=float,
                   help="exit after this many seconds of line time").replay = KEEP
    p.add_argument("--until-idle", type=_seconds, metavar="S",
                   help="exit once the outside end has written nothing for S seconds of line "
                        "time and the line is quiet (a host program that has finished)")
    p.add_argument("--events", type=Path, metavar="FILE",
                   help="the terminal's user, scripted: keys, cursor moves and the stylus at "
                        "times of line time or when the host waits for a reply "
                        "(docs/host-programs.md)")
    p.add_argument("--order-timeout", default="10", type=_seconds, metavar="S",
                   help="hang up on a --listen client that leaves half an order "
                        "unfinished this many seconds of line time (default 10)").replay = KEEP
    p.add_argument("--idle-timeout", default="60", type=_seconds, metavar="S",
                   help="a --listen client silent this many seconds of line time gives "
                        "way to one that connects (default 60)").replay = KEEP
    p.add_argument("--session-time", default="180", type=_seconds, metavar="S",
                   help="a --listen client that has held the line this many seconds of line "
                        "time gives way to the next one that connects, however steadily it "
                        "sends (default 180)").replay = KEEP
    p.add_argument("--record-line", type=Path, metavar="FILE",
                   help="record the line (both directions) as a link recording").replay = DROP
    add_run_options(p, stop_after=False)
    add_trace_options(p)


def run(args: argparse.Namespace) -> int:
    from camlab88.emulator.harness import replay
    from camlab88.emulator.harness import run as run_target

    got, settings = _stream_and_settings(args)
    ends = (args.seconds is not None or args.screenshot is not None
            or args.until_idle is not None)
    script = _script(args)
    opts = run_options(args, COMMAND, "serving the line without a window"
                       + ("" if ends else " until Ctrl-C"), argv=getattr(args, "_argv", None))
    if replay.active() is None and opts.screenshot is None:
        opts.realtime = True  # an outside program's line runs at its baud rate, idle asleep
    machine, recorder = _machine(args, settings)
    target = _target(args, machine, got, script)
    # Ctrl-C, or SIGTERM (cli.main delivers it as Ctrl-C): the recording is still written
    with open_trace(args, COMMAND, "the line") as trace, contextlib.ExitStack() as done:
        done.callback(_finish, target, machine, recorder, args)
        machine.trace(trace.sink, trace.strict)
        if replay.active() is None:
            target.bridge = _open_bridge(args, settings, target.tap)
            opts.live = True  # outside bytes enter at the poll's virtual time: keep them level
        run_target(target, opts)
    if trace.failed:
        return 1
    s = machine.stats
    print(f"camlab88 sigma: {s['bytes']} bytes in, {s['unknown']} unknown and "
          f"{s['malformed']} malformed orders skipped", flush=True)
    return 0


def _finish(target, machine, recorder, args: argparse.Namespace) -> None:
    if target.bridge is not None:
        target.bridge.close()
    if recorder is not None:
        machine.finish()
        recorder.close()
        print(f"{COMMAND}: recorded the line to {args.record_line}", flush=True)


def _stream_and_settings(args: argparse.Namespace):
    from camlab88.protocols.link import LineSettings
    from camlab88.protocols.sigma.stream_file import StreamFileError, read_stream_file

    try:
        got = read_stream_file(args.stream) if args.stream is not None else b""
    except StreamFileError as exc:
        raise _die(str(exc)) from None
    if not isinstance(got, bytes):  # a recording is replayed at its own speed and times
        if args.baud is not None and args.baud != got.settings.baud:
            raise _die(f"{args.stream} was recorded at {got.settings}, not --baud {args.baud}")
        return got, got.settings
    try:
        return got, LineSettings(baud=9600 if args.baud is None else args.baud)
    except ValueError as exc:
        raise _die(str(exc)) from None


def _machine(args: argparse.Namespace, settings):
    from camlab88.emulator.machine import SigmaMachine

    recorder = None
    if args.record_line is not None:
        from camlab88.protocols.link.recording import Recorder
        from camlab88.runopts import check_output

        check_output(COMMAND, args.record_line, "record to")
        try:
            recorder = Recorder(args.record_line, settings)
        except OSError as exc:
            raise _die(f"cannot record to {args.record_line}: {exc.strerror or exc}") from None
    return SigmaMachine(args.model, settings, recorder=recorder), recorder


def _script(args: argparse.Namespace) -> list:
    """The --events script (a bad line: one error naming file:line:col, exit 2)."""
    from camlab88.protocols.sigma.input_script import InputScriptError, load

    if args.events is None:
        return []
    try:
        return load(args.events)
    except InputScriptError as exc:
        raise _die(str(exc)) from None


def _target(args: argparse.Namespace, machine, got, script: list):
    from camlab88.emulator.harness.sigma_line import SigmaLineTarget
    from camlab88.protocols.link.replay import replay_into

    if isinstance(got, bytes):
        if got:
            machine.outside.write(got)
    else:
        replay_into(got, machine.outside, ">")
    until = None if args.seconds is None else Fraction(args.seconds)
    if until is None and args.screenshot is not None and args.until_idle is None:
        # once the --in stream has arrived
        until = Fraction(machine.outside.drain_time()) + FRAME
    return SigmaLineTarget(machine, None, f"camlab88 Sigma {args.model.upper()}", until,
                           _report, args.order_timeout, args.until_idle, script)


def _report(kind: str, detail: str) -> None:
    print(f"camlab88 sigma: {kind}: {detail}", file=sys.stderr, flush=True)


def _open_bridge(args: argparse.Namespace, settings, endpoint):
    """The line's outside end; an unusable port or URL is a one-line error (exit 1)."""
    from camlab88.protocols.link import transports as tr

    if args.listen is not None:
        try:
            bridge = tr.TcpBridge(args.listen, endpoint=endpoint,
                                  idle_timeout=float(args.idle_timeout),
                                  session_time=float(args.session_time))
        except OSError as exc:
            raise _die(f"cannot listen on 127.0.0.1:{args.listen}: "
                       f"{exc.strerror or exc}") from None
        print(f"camlab88 sigma: {args.model} listening on 127.0.0.1:{bridge.port}", flush=True)
        return bridge
    if args.serial is not None:
        return _serial_bridge(args, settings, endpoint)
    try:
        bridge = tr.PtyBridge(endpoint)
    except OSError as exc:
        raise _die(f"cannot open a pseudo-terminal: {exc.strerror or exc}") from None
    print(f"camlab88 sigma: {args.model} on pty {bridge.slave_path}", flush=True)
    return bridge


def _serial_bridge(args: argparse.Namespace, settings, endpoint):
    from camlab88.protocols.link import transports as tr

    bridge = tr.SerialUrlBridge(args.serial, settings, endpoint=endpoint)
    if not bridge.connected:
        why = next((e.detail for e in reversed(bridge.events) if e.kind == "error"),
                   f"cannot open {args.serial}")
        bridge.close()
        raise _die(why)
    print(f"camlab88 sigma: {args.model} on serial port {args.serial}", flush=True)
    return bridge
