"""``camlab88 sigma render|run``: the Sigma terminals headless (to PNG) or in a window."""

from __future__ import annotations

import argparse
import sys
from fractions import Fraction
from pathlib import Path
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    import numpy as np

MODELS = ("t5684", "t5688")


def register(subparsers: argparse._SubParsersAction) -> None:
    p = subparsers.add_parser("sigma", help="the Sigma T5684/T5688 terminals",
                              description="Emulated Sigma T5684 / T5688 graphics terminals.")
    sub = p.add_subparsers(dest="sigma_command", metavar="SUBCOMMAND")
    sub.required = True

    r = sub.add_parser("render", help="decode a stream and write the screen as PNG",
                       description="Feed a Sigma byte stream (raw bytes or a link recording) "
                       "to an emulated terminal and write the final screen, 768x512 PNG, row 0 "
                       "= top; or with --frames, the screen at every 1/FPS s of line time.")
    r.add_argument("--model", choices=MODELS, default="t5684")
    r.add_argument("--in", dest="stream", required=True, type=Path, help="stream file")
    r.add_argument("--out", type=Path, help="final screen PNG")
    r.add_argument("--frames", type=Path, help="directory for one PNG per frame period")
    r.add_argument("--fps", type=int, default=25, help="frames per second of line time")
    r.add_argument("--baud", type=int, default=9600,
                   help="line speed that times --frames (a recording keeps its own times)")
    r.set_defaults(handler=render_command)

    u = sub.add_parser("run", help="an interactive terminal in a window",
                       description="Run an emulated terminal in a window, its line on a "
                       "pseudo-terminal (--pty) or a TCP port on 127.0.0.1 (--listen). Keys "
                       "typed into the window go up the line; cursor keys move the crosshair, "
                       "the mouse is the tablet.")
    u.add_argument("--model", choices=MODELS, default="t5684")
    g = u.add_mutually_exclusive_group()
    g.add_argument("--pty", action="store_true", help="open a pseudo-terminal (the default)")
    g.add_argument("--listen", type=int, metavar="PORT", help="listen on 127.0.0.1:PORT")
    g.add_argument("--serial", metavar="URL", help="any pyserial URL, e.g. /dev/ttyUSB0")
    u.add_argument("--baud", type=int,
                   help="line speed (default 9600, or that of an --in recording)")
    u.add_argument("--scale", type=int, default=1)
    u.add_argument("--headless", action="store_true", help="no window (line only)")
    u.add_argument("--in", dest="stream", type=Path,
                   help="also play this stream down the line: raw bytes back to back from "
                   "the start, a recording at its recorded times")
    u.add_argument("--screenshot", type=Path,
                   help="save the screen to PNG and exit: at --seconds, else once the --in "
                   "stream has arrived")
    u.add_argument("--seconds", type=float, help="exit after this many seconds of line time")
    u.add_argument("--record", type=Path, help="record the line (both directions) to a file")
    u.set_defaults(handler=run_command)


# ---------------------------------------------------------------------- helpers
def write_png_atomic(frame: np.ndarray, path: Path) -> None:
    """Write an (h, w, 3) uint8 frame as PNG: temp file in the same directory, fsync, replace."""
    from PIL import Image

    from protocols.atomicfile import atomic_output

    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    with atomic_output(path) as f:
        Image.fromarray(frame).save(f, format="PNG")


def _write_png(frame: np.ndarray, path: Path, command: str) -> None:
    """write_png_atomic, a failure being a one-line error naming the file."""
    try:
        write_png_atomic(frame, path)
    except OSError as exc:
        raise SystemExit(f"camlab88 sigma {command}: cannot write {path}: "
                         f"{exc.strerror or exc}") from None


def read_input(path: Path):  # noqa: ANN201 - bytes or a protocols.link Recording
    """A link recording (by its first line) or raw bytes; a bad recording names file and line."""
    from protocols.link import recording

    try:
        data = path.read_bytes()
    except OSError as exc:
        raise SystemExit(f"camlab88 sigma: cannot read {path}: {exc.strerror}") from None
    if data.startswith(recording.MAGIC.encode("ascii")):
        try:
            return recording.read_recording(path)
        except ValueError as exc:
            raise SystemExit(f"camlab88 sigma: {exc}") from None
    return data


def read_stream(path: Path) -> bytes:
    """Host-to-device bytes of a file: a link recording's ">" stream, or the raw bytes."""
    got = read_input(path)
    return got if isinstance(got, bytes) else got.stream(">")


def _settings(baud: int):  # noqa: ANN202
    from protocols.link import LineSettings

    try:
        return LineSettings(baud=baud)
    except ValueError as exc:
        raise SystemExit(f"camlab88 sigma: {exc}") from None


# ---------------------------------------------------------------------- render
def _periods(got, baud: int, period: Fraction):  # noqa: ANN001, ANN202
    """(k, bytes arrived in period k): raw bytes sent back to back from t = 0 at ``baud``, or a
    recording's host-to-device bytes at their recorded arrival times."""
    from protocols.link import VirtualClock, chunks_by_period
    from protocols.link.replay import ReplayEndpoint

    if isinstance(got, bytes):
        yield from chunks_by_period(got, _settings(baud), period)
        return
    clock = VirtualClock()
    ep = ReplayEndpoint(got, ">", clock)
    k = 0
    while not ep.finished:
        clock.advance_to((k + 1) * period)
        yield k, ep.read()
        k += 1


def render_command(args: argparse.Namespace) -> int:
    from emulator.sigma import Terminal

    if args.out is None and args.frames is None:
        raise SystemExit("camlab88 sigma render: give --out PNG and/or --frames DIR")
    if args.fps < 1:
        raise SystemExit("camlab88 sigma render: --fps must be at least 1")
    _settings(args.baud)  # refuse a bad --baud even when no frames use it
    got = read_input(args.stream)
    term = Terminal(args.model)
    if args.frames is not None:
        count = 0
        for k, chunk in _periods(got, args.baud, Fraction(1, args.fps)):
            term.feed(chunk)
            _write_png(term.frame(), args.frames / f"frame_{k:05d}.png", "render")
            count += 1
        print(f"wrote {count} frames to {args.frames}")
    else:
        term.feed(got if isinstance(got, bytes) else got.stream(">"))
    if args.out is not None:
        _write_png(term.frame(), args.out, "render")
        print(f"wrote {args.out}")
    s = term.stats
    if s["unknown"] or s["malformed"] or s["errors"]:
        print(f"skipped: {s['unknown']} unknown, {s['malformed']} malformed, "
              f"{s['errors']} impossible orders", file=sys.stderr)
    return 0


# ---------------------------------------------------------------------- run
KEY_CHARS = {"return": "\r", "kp_enter": "\r", "backspace": "\b", "escape": "\x1b",
             "tab": "\t", "delete": "\x7f"}
ARROWS = {"left": (-1, 0), "right": (1, 0), "up": (0, 1), "down": (0, -1)}
TICK = Fraction(1, 100)  # virtual seconds per step of the run loop
FRAME = Fraction(1, 25)


def _open_bridge(args: argparse.Namespace, settings, line):  # noqa: ANN001, ANN202
    """The line's outside end; an unusable port or URL is a one-line error (exit 1)."""
    from protocols.link import transports as tr

    if args.listen is not None:
        try:
            bridge = tr.TcpBridge(args.listen, endpoint=line.host)
        except OSError as exc:
            raise SystemExit(f"camlab88 sigma run: cannot listen on 127.0.0.1:{args.listen}: "
                             f"{exc.strerror or exc}") from None
        print(f"camlab88 sigma: {args.model} listening on 127.0.0.1:{bridge.port}", flush=True)
    elif args.serial is not None:
        bridge = tr.SerialUrlBridge(args.serial, settings, endpoint=line.host)
        if not bridge.connected:
            why = next((e.detail for e in reversed(bridge.events) if e.kind == "error"),
                       f"cannot open {args.serial}")
            bridge.close()
            raise SystemExit(f"camlab88 sigma run: {why}")
        print(f"camlab88 sigma: {args.model} on serial port {args.serial}", flush=True)
    else:
        try:
            bridge = tr.PtyBridge(line.host)
        except OSError as exc:
            raise SystemExit(f"camlab88 sigma run: cannot open a pseudo-terminal: "
                             f"{exc.strerror or exc}") from None
        print(f"camlab88 sigma: {args.model} on pty {bridge.slave_path}", flush=True)
    return bridge


def run_command(args: argparse.Namespace) -> int:
    from emulator.sigma import Terminal
    from protocols.link import SerialLine, Throttle, VirtualClock
    from protocols.link.replay import replay_into

    if args.scale < 1:
        raise SystemExit("camlab88 sigma run: --scale must be at least 1")
    got = read_input(args.stream) if args.stream is not None else b""
    if isinstance(got, bytes):
        settings = _settings(9600 if args.baud is None else args.baud)
    else:  # a recording is replayed at its own speed and times
        settings = got.settings
        if args.baud is not None and args.baud != settings.baud:
            raise SystemExit(f"camlab88 sigma run: {args.stream} was recorded at {settings}, "
                             f"not --baud {args.baud}")
    clock = VirtualClock()
    recorder = None
    if args.record is not None:
        from protocols.link.recording import Recorder

        try:
            recorder = Recorder(args.record, settings)
        except OSError as exc:
            raise SystemExit(f"camlab88 sigma run: cannot record to {args.record}: "
                             f"{exc.strerror or exc}") from None
    line = SerialLine(settings, clock=clock, recorder=recorder)
    term = Terminal(args.model)
    term.on_output = line.device.write
    try:
        bridge = _open_bridge(args, settings, line)
    except BaseException:
        if recorder is not None:
            recorder.close()
        raise
    if isinstance(got, bytes):
        if got:
            line.host.write(got)
    else:
        replay_into(got, line.host, ">")
    window = None
    if not args.headless:
        from emulator.window import Window

        window = Window(f"camlab88 Sigma {args.model.upper()}", (768, 512), scale=args.scale)
    throttle = Throttle(1.0)
    shot_at = None  # line time of the screenshot: at --seconds, else once --in has arrived
    if args.screenshot is not None:
        shot_at = args.seconds if args.seconds is not None else \
            line.host.drain_time() + float(FRAME)
    next_frame = Fraction(0)
    try:
        while True:
            for ev in bridge.poll(timeout=0.0).events:
                if ev.kind in ("error", "disconnected", "refused"):
                    print(f"camlab88 sigma: {ev.kind}: {ev.detail}", file=sys.stderr, flush=True)
            term.feed(line.device.read())
            now = clock.exact
            if window is not None and now >= next_frame:
                window.show(term.frame())
                next_frame = now + FRAME
                if not _window_input(window, term):
                    break
            if shot_at is not None and now >= shot_at:
                _screenshot(window, term, args.screenshot)
                break
            if args.seconds is not None and now >= args.seconds:
                break
            clock.advance(TICK)
            throttle.pace(clock.exact)
    finally:
        bridge.close()
        if window is not None:
            window.close()
        if recorder is not None:
            line.finish()
            recorder.close()
            print(f"camlab88 sigma: recorded the line to {args.record}")
    s = term.stats
    print(f"camlab88 sigma: {s['bytes']} bytes in, {s['unknown']} unknown and "
          f"{s['malformed']} malformed orders skipped", flush=True)
    return 0


def _screenshot(window, term, path: Path) -> None:  # noqa: ANN001
    try:
        if window is not None:
            window.show(term.frame())
            window.screenshot(path)
        else:
            write_png_atomic(term.frame(), path)
    except OSError as exc:
        raise SystemExit(f"camlab88 sigma run: cannot write {path}: "
                         f"{exc.strerror or exc}") from None
    print(f"camlab88 sigma: screenshot {path}", flush=True)


def _window_input(window, term) -> bool:  # noqa: ANN001
    """Host events -> the terminal's keyboard, cursor keys and tablet; False on quit."""
    from emulator.host_input import KeyDown, PointerButton, PointerMove, Quit

    for ev in window.poll():
        if isinstance(ev, Quit):
            return False
        if isinstance(ev, KeyDown):
            if ev.key in ARROWS:
                dx, dy = ARROWS[ev.key]
                step = 8 if "shift" in ev.mods else 1
                term.cursor_keys(dx * step, dy * step)
            elif ev.char:
                term.key(ev.char)
            elif ev.key in KEY_CHARS:
                term.key(KEY_CHARS[ev.key])
        elif isinstance(ev, PointerMove):
            term.tablet(ev.x, 511 - ev.y, False)
        elif isinstance(ev, PointerButton) and ev.pressed:
            term.tablet(ev.x, 511 - ev.y, True)
    return True
