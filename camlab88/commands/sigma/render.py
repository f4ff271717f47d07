"""``camlab88 sigma render --in STREAM``: the final screen, or every frame, as PNG."""

from __future__ import annotations

import argparse
import sys
from fractions import Fraction
from pathlib import Path

from camlab88.commands.sigma import MODELS
from camlab88.control_flags import add_control_options
from camlab88.runopts import frames_dir
from camlab88.traceopts import add_trace_options, open_trace

COMMAND = "camlab88 sigma render"


def _die(message: str) -> SystemExit:
    return SystemExit(f"{COMMAND}: {message}")

DESCRIPTION = """\
Feed a Sigma byte stream (raw bytes or a link recording) to an emulated terminal and write \
the final screen, 768x512 PNG, row 0 = top; or with --frames, the screen at every 1/FPS s of \
line time."""


HELP = "decode a stream and write the screen as PNG"


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("--model", default="t5684", choices=MODELS)
    p.add_argument("--in", dest="stream", type=Path, required=True, help="stream file")
    p.add_argument("--out", type=Path, help="final screen PNG")
    p.add_argument("--frames", type=frames_dir, metavar="DIR",
                   help="directory for one PNG per frame period (frame_NNNNN.png)")
    p.add_argument("--fps", default=25, type=int, help="frames per second of line time")
    p.add_argument("--baud", default=9600, type=int,
                   help="line speed that times --frames (a recording keeps its own times)")
    add_trace_options(p)
    add_control_options(p)


def run(args: argparse.Namespace) -> int:
    from camlab88.emulator.harness.sigma_batch import settle
    from camlab88.protocols.sigma.stream_file import StreamFileError, host_bytes, read_stream_file

    if args.out is None and args.frames is None and args.video is None \
            and args.inspect_out is None:
        raise _die("give --out PNG and/or --frames DIR (or --video FILE, --inspect-out DIR)")
    if args.fps < 1:
        raise _die("--fps must be at least 1")
    from camlab88.runopts import check_output, check_output_dir

    if args.out is not None:  # the one output rule (docs/exit_status.md), before the work
        check_output(COMMAND, Path(args.out), "write", (".png",))
    if args.frames is not None:
        check_output_dir(COMMAND, Path(args.frames))
    settings = _settings(args.baud)  # refuse a bad --baud even when no frames use it
    try:
        got = read_stream_file(args.stream)
    except StreamFileError as exc:
        raise _die(str(exc)) from None
    machine = _machine(args.model, got, settings)
    with open_trace(args, COMMAND, str(args.stream)) as trace:
        trace.stream = host_bytes(got)
        machine.trace(trace.sink, trace.strict)
        if args.video is not None or args.inspect_out is not None:
            _play(args, machine, got, settings)
        elif args.frames is not None:
            n = _write_frames(machine, got, settings, Fraction(1, args.fps), args.frames)
            print(f"wrote {n} frames to {args.frames}")
        else:
            settle(machine)
    if trace.failed:
        return 1
    if args.out is not None:
        _png(machine.frame(), args.out)
        print(f"wrote {args.out}")
    _say_skipped(machine, args.stream, host_bytes(got))
    return 0


def _machine(model: str, got, settings):
    """A terminal on a line with the stream on its way: raw bytes back to back from t = 0,
    or a recording's host-to-terminal runs each sent so that it arrives when recorded (a
    recording keeps its own line settings)."""
    from camlab88.emulator.machine import SigmaMachine

    if isinstance(got, bytes):
        machine = SigmaMachine(model, settings, xonxoff=False)
        machine.host.write(got)
        return machine
    machine = SigmaMachine(model, got.settings, xonxoff=False)
    ct = got.settings.char_time
    for t, data in got.arrivals(">"):  # the host end, writing ahead at recorded times
        machine.outside.write(data, at=max(Fraction(0), t - len(data) * ct))
    return machine


def _settings(baud: int):
    from camlab88.protocols.link import LineSettings

    try:
        return LineSettings(baud=baud)
    except ValueError as exc:
        raise _die(str(exc)) from None


def _png(frame, path: Path) -> None:
    from camlab88.base.png import write_png

    try:
        write_png(frame, path)
    except OSError as exc:
        raise _die(f"cannot write {path}: {exc.strerror or exc}") from None


def _write_frames(machine, got, settings, period: Fraction, directory: Path) -> int:
    from camlab88.base.png import frame_path
    from camlab88.emulator.harness.sigma_batch import periods
    from camlab88.protocols.link.sniff import frame_count

    try:  # a damaged recording time must not mean hours of PNGs
        frame_count(_duration(got, settings), int(1 / period), name=str(directory))
    except ValueError as exc:
        raise _die(str(exc)) from None
    count = 0
    try:  # made one level, its parent checked before the work (the one output rule)
        directory.mkdir(exist_ok=True)
    except OSError as exc:
        raise _die(f"cannot write frames to {directory}: {exc.strerror or exc}") from None
    for k in periods(machine, period):
        _png(machine.frame(), frame_path(directory, k))
        count += 1
    return count


def _play(args: argparse.Namespace, machine, got, settings) -> None:
    """The frame periods through the harness, headless and flat out unless --speed: the
    emulator controls' --video and --inspect-out, and --frames too."""
    from camlab88.control_flags import controls_from_args
    from camlab88.emulator.harness import RunOptions, run
    from camlab88.emulator.harness.sigma import PeriodTarget
    from camlab88.emulator.harness.sigma_batch import periods
    from camlab88.protocols.link.sniff import frame_count

    try:  # a damaged recording time must not mean hours of frames
        frame_count(_duration(got, settings), args.fps, name=str(args.stream))
    except ValueError as exc:
        raise _die(str(exc)) from None
    opts = RunOptions(headless=True, command=COMMAND, frames=args.frames,
                      controls=controls_from_args(args, COMMAND, headless=True))
    target = PeriodTarget(machine, periods(machine, Fraction(1, args.fps)), args.fps,
                          f"{COMMAND} {args.stream}")
    run(target, opts)


def _duration(got, settings) -> Fraction:
    """Line time the frames must cover: raw bytes back to back, or the recording's last time."""
    if isinstance(got, bytes):
        return Fraction(len(got)) * settings.char_time
    return Fraction(got.duration)


def _say_skipped(machine, stream: Path, data: bytes) -> None:
    from camlab88.protocols.sigma.orders import GRAPHICS_FLAG

    s = machine.stats
    if s["unknown"] or s["malformed"] or s["errors"]:
        print(f"skipped: {s['unknown']} unknown, {s['malformed']} malformed, "
              f"{s['errors']} impossible orders", file=sys.stderr)
    if data and GRAPHICS_FLAG not in data:  # text only: it went to the alpha screen
        print(f"{COMMAND}: {stream} drew nothing: is it a Sigma stream? (it never sends "
              f"the graphics flag {GRAPHICS_FLAG.decode('latin-1')})", file=sys.stderr)
