"""``camlab88 rainbow ...``: render a scene file; run the emulator in a window (or headless)."""

from __future__ import annotations

import argparse
import sys


def register(subparsers: argparse._SubParsersAction) -> None:
    p = subparsers.add_parser("rainbow", help="the Rainbow workstation emulator",
                              description="The Cambridge Rainbow workstation: pads, clusters, "
                              "band structure, video processor.")
    sub = p.add_subparsers(dest="rainbow_command", metavar="ACTION")
    sub.required = True

    r = sub.add_parser("render", help="render a scene file (JSON pad graph) to a PNG",
                       description="Compile SCENE.json's pad graph to band structure and "
                       "render one 768x576 frame.")
    r.add_argument("scene", metavar="SCENE.json")
    r.add_argument("--out", required=True, metavar="PNG", help="where to write the frame")
    r.add_argument("--bands", metavar="FILE", help="also write the band structure as text")
    r.add_argument("--reference", action="store_true",
                   help="render with the per-pixel reference compositor instead")
    r.add_argument("--strict", action="store_true",
                   help="the relic's video memory (64K 16-bit words)")
    r.set_defaults(handler=_render)

    u = sub.add_parser("run", help="open the window with a demo of pads and transparency",
                       description="Run the Rainbow with the Appendix I transparency example "
                       "and moving double-buffered pads.")
    u.add_argument("--headless", action="store_true", help="no window (works everywhere)")
    u.add_argument("--frames", type=int, default=None,
                   help="stop after N frames (default: run until closed; 250 headless)")
    u.add_argument("--screenshot", metavar="PNG", help="save a frame and exit")
    u.add_argument("--screenshot-frame", type=int, default=30, metavar="N",
                   help="which frame --screenshot saves (default 30)")
    u.add_argument("--scale", type=int, default=1, help="window scale factor")
    u.add_argument("--record", metavar="FILE", help="record the command stream and input")
    u.add_argument("--strict", action="store_true",
                   help="the relic's video memory (64K 16-bit words)")
    u.add_argument("--tablet", metavar="SOURCE",
                   help="also feed a real tablet (hid:VID:PID, serial:PORT?protocol=P, or a "
                   "pyserial URL?protocol=P) to the Rainbow's tablet input")
    u.set_defaults(handler=_run)

    v = sub.add_parser("serve", help="serve a Rainbow to a program over a local TCP socket",
                       description="Listen on 127.0.0.1:PORT for a program using "
                       "protocols.rainbow.SocketTransport; show its frames in the window.")
    v.add_argument("--port", type=int, default=4711, help="TCP port on 127.0.0.1 (0 = any)")
    v.add_argument("--headless", action="store_true", help="no window")
    v.add_argument("--connections", type=int, default=None,
                   help="stop after serving this many programs (default: for ever)")
    v.add_argument("--scale", type=int, default=1, help="window scale factor")
    v.add_argument("--strict", action="store_true",
                   help="the relic's video memory (64K 16-bit words)")
    v.set_defaults(handler=_serve)

    p2 = sub.add_parser("replay", help="replay a recorded session (--record) and check it",
                        description="Feed a recording's commands and input events to a fresh "
                        "Rainbow; every reply must match the recorded one.")
    p2.add_argument("recording", metavar="FILE")
    p2.add_argument("--headless", action="store_true", help="no window")
    p2.add_argument("--screenshot", metavar="PNG", help="save the last frame")
    p2.add_argument("--scale", type=int, default=1, help="window scale factor")
    p2.add_argument("--strict", action="store_true",
                    help="replay on the relic's video memory (for recordings made with --strict)")
    p2.set_defaults(handler=_replay)


def _render(args: argparse.Namespace) -> int:
    from emulator.rainbow.errors import RainbowError
    from emulator.rainbow.files import save_png, write_atomic
    from emulator.rainbow.scene import SceneError, load_scene

    try:
        device = load_scene(args.scene, _device(args.strict))
    except (SceneError, RainbowError) as exc:
        print(f"camlab88 rainbow render: {exc}", file=sys.stderr)
        return 2
    try:  # compiling (or the reference walk) refuses graphs with too many paths
        frame = device.reference() if args.reference else device.peek()
        text = device.bands().to_text() if args.bands else None
    except RainbowError as exc:
        print(f"camlab88 rainbow render: {args.scene}: {exc}", file=sys.stderr)
        return 2
    try:
        save_png(args.out, frame)
        if text is not None:
            write_atomic(args.bands, text.encode())
    except OSError as exc:
        print(f"camlab88 rainbow render: {exc}", file=sys.stderr)
        return 1
    return 0


def _device(strict: bool):
    from emulator.rainbow import Rainbow

    return Rainbow(strict=strict)


def _run(args: argparse.Namespace) -> int:
    return run_demo(args)


def _serve(args: argparse.Namespace) -> int:
    from emulator.host_input import Quit
    from emulator.rainbow.executor import Executor
    from emulator.rainbow.server import listen, serve

    device = _device(args.strict)
    window = None
    if not args.headless:
        from emulator.window import Window

        window = Window("camlab88 Rainbow (serving)", (768, 576), scale=args.scale)
    buttons = [0]

    def on_frame(frame) -> None:
        if window is None:
            return
        window.show(frame)
        for ev in window.poll():
            if isinstance(ev, Quit):
                raise KeyboardInterrupt
            dev = host_to_rainbow_event(ev, buttons)
            if dev is not None:
                device.post_event(dev)

    try:
        sock = listen(args.port)
    except OSError as exc:
        print(f"camlab88 rainbow serve: port {args.port}: {exc.strerror}", file=sys.stderr)
        return 1
    print(f"camlab88 rainbow serve: listening on 127.0.0.1:{sock.getsockname()[1]}",
          flush=True)
    try:
        serve(Executor(device, on_frame), sock, args.connections)
    finally:
        sock.close()
        if window is not None:
            window.close()
    return 0


def _replay(args: argparse.Namespace) -> int:
    from emulator.rainbow.device import Rainbow
    from emulator.rainbow.executor import Executor
    from emulator.rainbow.files import save_png
    from protocols.rainbow.recording import Recording, RecordingError, replay

    try:
        rec = Recording.load(args.recording)
    except (OSError, RecordingError) as exc:
        print(f"camlab88 rainbow replay: {exc}", file=sys.stderr)
        return 2
    window = None
    if not args.headless:
        from emulator.window import Window

        window = Window("camlab88 Rainbow (replay)", (768, 576), scale=args.scale)

    def on_frame(frame) -> None:
        if window is not None:
            window.show(frame)
            window.poll()
            window.wait_frame(50)

    device = Rainbow(strict=getattr(args, "strict", False))
    ex = Executor(device, on_frame)
    try:
        result = replay(rec, ex.handle, device.post_event)
    finally:
        if window is not None:
            window.close()
    if args.screenshot:
        save_png(args.screenshot, device.peek())
    print(f"camlab88 rainbow replay: {result.commands} commands, {result.events} input events, "
          f"{device.frame_count} frames, {len(result.mismatches)} mismatches")
    for m in result.mismatches[:10]:
        print(f"  {m}", file=sys.stderr)
    return 1 if result.mismatches else 0


def host_to_rainbow_event(ev, buttons: list[int]):
    """Host (window) input -> a Rainbow input event, or None for what the Rainbow ignores.

    ``buttons[0]`` keeps the set of held mouse buttons (bits LEFT=1, MIDDLE=2, RIGHT=4)."""
    from emulator.host_input import KeyDown, KeyUp, PointerButton, PointerMove
    from protocols.rainbow.events import KeyEvent, MouseEvent

    if isinstance(ev, PointerMove):
        held = sum(1 << (b - 1) for b in ev.buttons if 1 <= b <= 3)
        buttons[0] = held
        return MouseEvent(0, ev.x, ev.y, held)
    if isinstance(ev, PointerButton) and 1 <= ev.button <= 3:
        bit = 1 << (ev.button - 1)
        buttons[0] = buttons[0] | bit if ev.pressed else buttons[0] & ~bit
        return MouseEvent(0, ev.x, ev.y, buttons[0], ev.button, ev.pressed)
    if isinstance(ev, KeyDown):
        return KeyEvent(0, ev.key, ev.char, True)
    if isinstance(ev, KeyUp):
        return KeyEvent(0, ev.key, "", False)
    return None


def tablet_event(ev):
    """A decoded tablet report (protocols.tablets) -> the Rainbow's tablet input event."""
    from protocols.rainbow.events import TabletEvent

    pressure = 0 if ev.pressure is None else max(0, min(int(ev.pressure), 1023))
    return TabletEvent(0, int(ev.x), int(ev.y), pressure, int(ev.buttons) & 0xFF,
                       bool(ev.proximity))


def _open_tablet(text: str | None):
    if not text:
        return None
    from protocols.tablets.sources import SourceError, open_source

    try:
        return open_source(text)
    except (SourceError, OSError) as exc:
        raise SystemExit(f"camlab88 rainbow run: --tablet {text}: {exc}") from None


def _poll_tablet(tablet, session):
    """Feed new tablet reports to the device; a lost tablet is reported once and dropped."""
    from protocols.tablets.sources import SourceLost

    try:
        for ev in tablet.read(0.0):
            session.inject(tablet_event(ev))
    except (SourceLost, OSError) as exc:
        print(f"camlab88 rainbow run: tablet lost ({exc}); carrying on without it",
              file=sys.stderr)
        tablet.close()
        return None
    return tablet


def run_demo(args: argparse.Namespace) -> int:
    from emulator.host_input import Quit
    from emulator.rainbow.files import save_png
    from emulator.rainbow.session import in_process
    from protocols.rainbow.demo import Demo

    frames = args.frames if args.frames is not None else (250 if args.headless else None)
    if args.screenshot and frames is None:
        frames = args.screenshot_frame
    window = None
    state = {"quit": False}
    shot = args.screenshot_frame if args.screenshot else None

    def on_frame(frame) -> None:
        n = session.device.frame_count
        if window is not None:
            window.show(frame)
            if shot is None:
                window.wait_frame(50)
        if shot is not None and n == shot:
            if window is not None:
                window.screenshot(args.screenshot)
            else:
                save_png(args.screenshot, frame)
            state["quit"] = True

    tablet = _open_tablet(args.tablet)
    session = in_process(_device(getattr(args, "strict", False)), record=bool(args.record),
                         on_frame=on_frame)
    if not args.headless:
        from emulator.window import Window

        window = Window("camlab88 Rainbow", (768, 576), scale=args.scale)
    buttons = [0]
    try:
        demo = Demo(session.client)
        while not state["quit"] and (frames is None or session.device.frame_count < frames):
            if window is not None:
                for ev in window.poll():
                    if isinstance(ev, Quit):
                        state["quit"] = True
                    dev = host_to_rainbow_event(ev, buttons)
                    if dev is not None:
                        session.inject(dev)
            if tablet is not None:
                tablet = _poll_tablet(tablet, session)
            demo.step()
    finally:
        if window is not None:
            window.close()
        if tablet is not None:
            tablet.close()
        if args.record:
            session.recorder.recording.save(args.record)
    print(f"camlab88 rainbow run: {session.device.frame_count} frames, "
          f"{session.device.compiler.stats.compiles} compiles")
    return 0
