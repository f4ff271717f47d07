"""``camlab88 rainbow serve``: a Rainbow for a program over a local TCP socket."""

from __future__ import annotations

import argparse

from camlab88.runopts import fail

COMMAND = "camlab88 rainbow serve"


def register(actions: argparse._SubParsersAction) -> None:  # type: ignore[type-arg]
    v = actions.add_parser("serve", help="serve a Rainbow to a program over a local TCP socket",
                           description="Listen on 127.0.0.1:PORT for a program using "
                           "protocols.rainbow.SocketTransport; show its frames in the window "
                           "(no display: headless, serving only).")
    v.add_argument("--port", type=int, default=4711, help="TCP port on 127.0.0.1 (0 = any)")
    v.add_argument("--headless", action="store_true", help="no window")
    v.add_argument("--connections", type=int, default=None,
                   help="stop after serving this many programs (default: for ever)")
    v.add_argument("--scale", type=int, default=1, help="window scale factor")
    v.add_argument("--strict", action="store_true",
                   help="the relic's video memory (64K 16-bit words)")
    v.set_defaults(handler=serve)


def serve(args: argparse.Namespace) -> int:
    from emulator.harness import choose_headless
    from emulator.rainbow import Rainbow
    from emulator.rainbow.executor import Executor
    from emulator.rainbow.server import listen
    from emulator.rainbow.server import serve as serve_on

    device = Rainbow(strict=args.strict)
    headless = choose_headless(COMMAND, args.headless, "serving without showing the frames")
    window = None if headless else _window(args.scale)
    try:
        sock = listen(args.port)
    except OSError as exc:
        return fail(COMMAND, f"port {args.port}: {exc.strerror}")  # cannot start: 2
    print(f"{COMMAND}: listening on 127.0.0.1:{sock.getsockname()[1]}", flush=True)
    try:
        serve_on(Executor(device, _on_frame(window, device)), sock, args.connections)
    finally:
        sock.close()
        if window is not None:
            window.close()
    return 0


def _window(scale: int):  # noqa: ANN202
    import sys

    from emulator.window import Window

    print(f"{COMMAND}: window open; close it to stop serving", file=sys.stderr)
    return Window("camlab88 Rainbow (serving)", (768, 576), scale=scale)


def _on_frame(window, device):  # noqa: ANN001, ANN202
    """Each frame the served program makes: shown, and window input sent to the device."""
    from emulator.host_input import Quit
    from emulator.rainbow.host_input import RainbowHostInput

    host = RainbowHostInput()

    def on_frame(frame) -> None:  # noqa: ANN001
        if window is None:
            return
        window.show(frame)
        for ev in window.poll():
            if isinstance(ev, Quit):
                raise KeyboardInterrupt
            dev = host.convert(ev)
            if dev is not None:
                device.post_event(dev)
    return on_frame
