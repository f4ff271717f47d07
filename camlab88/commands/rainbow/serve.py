"""``camlab88 rainbow serve``: a Rainbow for a program over a local TCP socket."""

from __future__ import annotations

import argparse

from camlab88.commands.rainbow import add_relic_memory_options
from camlab88.runopts import fail
from camlab88.traceopts import add_trace_options, open_trace

COMMAND = "camlab88 rainbow serve"


def _seconds(text: str) -> float:
    import re

    if not re.fullmatch(r"[0-9]{1,5}(\.[0-9]{1,6})?", text) or not 0 < float(text) <= 86400:
        raise argparse.ArgumentTypeError(f"{text[:40]!r} is not a number of seconds in "
                                         "(0, 86400]")
    return float(text)

DESCRIPTION = """\
Listen on 127.0.0.1:PORT for a program using protocols.rainbow.SocketTransport; show its \
frames in the window (no display: headless, serving only)."""


HELP = "serve a Rainbow to a program over a local TCP socket"


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("--port", default=4711, type=int, help="TCP port on 127.0.0.1 (0 = any)")
    p.add_argument("--headless", action="store_true", help="no window")
    p.add_argument("--connections", type=int,
                   help="stop after serving this many programs (default: for ever)")
    p.add_argument("--scale", default=1, type=int, help="window scale factor")
    add_relic_memory_options(p)
    p.add_argument("--frame-timeout", default=10.0, type=_seconds, metavar="S",
                   help="hang up on a program whose frame is unfinished S seconds after "
                        "its first byte (default 10)")
    p.add_argument("--idle-timeout", default=60.0, type=_seconds, metavar="S",
                   help="a program silent for S seconds gives way to one waiting (default "
                        "60)")
    p.add_argument("--session-time", default=180.0, type=_seconds, metavar="S",
                   help="a program connected for S seconds gives way to one waiting, however "
                        "steadily it sends (default 180)")
    add_trace_options(p, strict="--strict-protocol")


def run(args: argparse.Namespace) -> int:
    from camlab88.emulator.harness import choose_headless
    from camlab88.emulator.machine import RainbowMachine

    headless = choose_headless(COMMAND, args.headless, "serving without showing the frames")
    window = None if headless else _window(args.scale)
    try:
        sock = RainbowMachine.listen(args.port)
    except OSError as exc:
        return fail(COMMAND, f"port {args.port}: {exc.strerror}")  # cannot start: 2
    print(f"{COMMAND}: listening on 127.0.0.1:{sock.getsockname()[1]}", flush=True)
    machine = RainbowMachine(strict_memory=args.strict)
    machine.show_frames(_on_frame(window, machine))
    try:
        with open_trace(args, COMMAND, "the command stream") as trace:
            if trace.sink is not None:
                machine.trace(trace.sink, trace.strict)
            machine.serve(sock, args.connections, frame_timeout=args.frame_timeout,
                          idle_timeout=args.idle_timeout, session_time=args.session_time)
    finally:
        sock.close()
        if window is not None:
            window.close()
    return 1 if trace.failed else 0


def _window(scale: int):
    import sys

    from camlab88.emulator.window import Window

    print(f"{COMMAND}: window open; close it to stop serving", file=sys.stderr)
    return Window("camlab88 Rainbow (serving)", (768, 576), scale=scale)


def _on_frame(window, machine):
    """Each frame the served program makes: shown, and window input sent to the machine."""
    from camlab88.emulator.host_input import Quit
    from camlab88.emulator.rainbow.host_input import RainbowHostInput

    host = RainbowHostInput()

    def on_frame(frame) -> None:
        if window is None:
            return
        window.show(frame)
        for ev in window.poll():
            if isinstance(ev, Quit):
                raise KeyboardInterrupt
            dev = host.convert(ev)
            if dev is not None:
                machine.post(dev)
    return on_frame
