"""`camlab88 snooker ...`: the snooker motion-development program (thesis ch. 6).

Actions:
  play [SESSION]          the interactive program on the emulated Rainbow (§6.2.1-§6.2.2)
  simulate  headless: set a ball moving (or play the break-off), simulate until every ball
            has stopped, write the checkpoint file (and optionally the session).
  replay CHECKPOINT       play a checkpoint file on the Rainbow at 25 frames/s
"""

from __future__ import annotations

import argparse
from collections.abc import Callable

HELP = ("snooker motion development (thesis chapter 6): `camlab88 snooker [SESSION]` runs the "
        "interactive program (= `snooker play`); simulate shots; replay checkpoint files")


def register(subparsers: argparse._SubParsersAction) -> None:  # type: ignore[type-arg]
    p = subparsers.add_parser("snooker", help=HELP, description=HELP)
    actions = p.add_subparsers(dest="snooker_action", metavar="ACTION")
    for add in ACTIONS:
        add(actions)
    p.set_defaults(handler=lambda args: _no_action(p))


ACTION_NAMES = ("play", "simulate", "replay")


def normalise_argv(argv: list[str]) -> list[str]:
    """``camlab88 snooker [SESSION] [options]`` is the interactive program (issue 6): with no
    action named, insert ``play`` so the session file and options reach it."""
    if argv[:1] == ["snooker"]:
        rest = argv[1:]
        if not rest or rest[0] not in (*ACTION_NAMES, "-h", "--help"):
            return ["snooker", "play", *rest]
    return argv


def _no_action(p: argparse.ArgumentParser) -> int:
    p.print_help()
    return 2


def _table_option(value: str) -> tuple[str, str]:
    if "=" not in value:
        raise argparse.ArgumentTypeError(f"expected NAME=VALUE, got {value!r}")
    k, v = value.split("=", 1)
    return k.strip(), v.strip()


def _add_simulate(actions: argparse._SubParsersAction) -> None:  # type: ignore[type-arg]
    s = actions.add_parser(
        "simulate",
        help="simulate a shot headlessly until every ball stops; write a checkpoint",
        description="Simulate until all balls have stopped and write the §6.2.2 checkpoint "
        "file (4096 units per foot). ANGLE_DEG is measured anticlockwise from straight up "
        "the table (from the baulk end towards the black); SPIN is m/s along the shot "
        "(+ top spin, - back spin).",
    )
    s.add_argument("--from", dest="source", metavar="SESSION|CHECKPOINT",
                   help="start from a saved session (JSON) or the last frame of a checkpoint")
    how = s.add_mutually_exclusive_group(required=True)
    how.add_argument("--break", dest="break_speed", type=float, metavar="SPEED_M_S",
                     help="the opening position, cue ball in the D struck at the pack")
    how.add_argument("--shot", nargs="+", metavar="ARG",
                     help="BALL SPEED_M_S ANGLE_DEG [SPIN_M_S]; BALL is 1..22 or a name "
                     "(cue, yellow, ..., black, red1..red15)")
    s.add_argument("--out", required=True, metavar="CHECKPOINT", help="checkpoint file to write")
    s.add_argument("--save-session", metavar="SESSION", help="also save the session file")
    s.add_argument("--first", type=int, default=0, help="first time frame to write (default 0)")
    s.add_argument("--last", type=int, help="last time frame to write (default: the last)")
    s.add_argument("--table", action="append", type=_table_option, default=[],
                   metavar="NAME=VALUE",
                   help="change a table constant, e.g. cushion_restitution=1.2 "
                   "ball_diameter_m=0.2 (new games only)")
    s.add_argument("--max-seconds", type=float, default=600.0,
                   help="give up if balls are still moving after this long (default 600)")
    s.set_defaults(handler=_simulate)


def _simulate(args: argparse.Namespace) -> int:
    import dataclasses
    import sys
    from pathlib import Path

    from apps.snooker.checkpoint import CheckpointError
    from apps.snooker.layout import break_off_direction
    from apps.snooker.physics import SimulationError
    from apps.snooker.session import Session, SessionError
    from apps.snooker.table import BALL_NAMES, CUE, Table, ball_index

    def fail(msg: str) -> int:
        print(f"camlab88 snooker simulate: {msg}", file=sys.stderr)
        return 2

    try:
        fields = {f.name: f.type for f in dataclasses.fields(Table)}
        changes: dict[str, object] = {}
        for k, v in args.table:
            if k not in fields:
                return fail(f"unknown table constant {k!r}; known: {', '.join(fields)}")
            cast = {"int": int, "str": str}.get(str(fields[k]), float)
            changes[k] = cast(v)
        table = Table(**changes)  # type: ignore[arg-type]
    except ValueError as exc:
        return fail(str(exc))
    try:
        if args.break_speed is not None:
            if args.source:
                return fail("--break plays the opening position; it cannot be used with --from")
            if not args.break_speed > 0:
                return fail("the break speed must be positive")
            session = Session.new_game(table)
            ux, uy = break_off_direction(table, session.balls)
            session.set_velocity(CUE, ux * args.break_speed, uy * args.break_speed)
        else:
            if len(args.shot) not in (3, 4):
                return fail("--shot takes BALL SPEED_M_S ANGLE_DEG [SPIN_M_S]")
            ball = ball_index(args.shot[0])
            try:
                speed, angle, *rest = (float(x) for x in args.shot[1:])
            except ValueError:
                return fail(f"--shot: not numbers: {' '.join(args.shot[1:])}")
            if speed < 0:
                return fail("the speed must not be negative")
            if args.source:
                src = Path(args.source)
                head = src.read_bytes()[:64].lstrip() if src.exists() else b""
                if head.startswith(b"{"):
                    session = Session.load(src)
                    session.cursor = session.timeline.head
                else:
                    session = Session.from_checkpoint(src, table)
            else:
                session = Session.new_game(table)
            session.strike(ball, speed, angle, rest[0] if rest else 0.0)
        session.simulate_to_rest(args.max_seconds)
        cp = session.checkpoint(args.first, args.last)
        cp.write(args.out)
        if args.save_session:
            session.save(args.save_session)
    except (CheckpointError, SessionError, SimulationError, ValueError, OSError) as exc:
        return fail(str(exc))
    st = session.status()
    tl = session.timeline
    print(f"{len(tl.time_frames)} time frames ({tl.time_frames[-1].balls.t:.2f} s), "
          f"{st['collision']} collisions; wrote frames {args.first}..{args.first + cp.n_frames - 1}"
          f" to {args.out}")
    potted = [BALL_NAMES[i] for i in range(22) if not session.balls.on_table[i]]
    print(f"off the table: {', '.join(potted) or 'none'}; scores {st['scores'][0]}-"  # type: ignore[index]
          f"{st['scores'][1]}; {st['message']}")  # type: ignore[index]
    return 0


def _window_options(p: argparse.ArgumentParser, events: bool = True) -> None:
    p.add_argument("--headless", action="store_true", help="no window (virtual time)")
    if events:
        p.add_argument("--events", metavar="FILE",
                       help="scripted mouse/keyboard input (apps/snooker/program/"
                       "script_events.py: move, glide, press, release, key, type, wait)")
        p.add_argument("--save", metavar="SESSION",
                       help="where 'Exit from the program' saves (default: SESSION; "
                       "with neither, Exit asks for a file name)")
    p.add_argument("--frames", type=int, metavar="N", help="stop after N display frames")
    p.add_argument("--screenshot", metavar="PNG", help="save the screen at the end and exit")
    p.add_argument("--scale", type=int, default=1, help="window scale (default 1)")


def _add_play(actions: argparse._SubParsersAction) -> None:  # type: ignore[type-arg]
    s = actions.add_parser(
        "play", help="the interactive motion-development program on the emulated Rainbow",
        description="The interactive program (thesis §6.2.1-§6.2.2) on the emulated Rainbow. "
        "Middle button: menus and everything else; right: restart simulation; left held: "
        "mouse movement x4. With SESSION you are asked: new game (n) or restore (r).")
    s.add_argument("session", nargs="?", metavar="SESSION",
                   help="a saved session file to offer for restoring (and to save to)")
    _window_options(s)
    s.set_defaults(handler=_play)


def _add_replay(actions: argparse._SubParsersAction) -> None:  # type: ignore[type-arg]
    s = actions.add_parser("replay", help="play a checkpoint file on the Rainbow at 25 fps",
                           description="Play a §6.2.2 checkpoint file on the emulated Rainbow "
                           "at 25 frames/s (real time in a window, virtual time headless).")
    s.add_argument("checkpoint", metavar="CHECKPOINT")
    s.add_argument("--first", type=int, default=0, help="first frame (default 0)")
    s.add_argument("--last", type=int, help="last frame (default: the last)")
    _window_options(s, events=False)
    s.set_defaults(handler=_replay)


class _Screen:
    """The window (or nothing, headless) a Rainbow session's frames go to."""

    def __init__(self, args: argparse.Namespace, title: str) -> None:
        self.args = args
        self.window = None
        self.quit = False
        self.buttons = [0]
        if not args.headless:
            from emulator.window import Window

            self.window = Window(title, (768, 576), scale=args.scale)

    def on_frame(self, frame) -> None:  # type: ignore[no-untyped-def]
        if self.window is not None:
            self.window.show(frame)
            self.window.wait_frame(50)

    def poll(self, session, inject: bool = True) -> None:  # type: ignore[no-untyped-def]
        """Window input to the device (not while a script drives it: only Quit counts)."""
        if self.window is None:
            return
        from camlab88.commands.rainbow import host_to_rainbow_event
        from emulator.host_input import Quit

        for ev in self.window.poll():
            if isinstance(ev, Quit):
                self.quit = True
            dev = host_to_rainbow_event(ev, self.buttons)
            if dev is not None and inject:
                session.inject(dev)

    def finish(self, session) -> None:  # type: ignore[no-untyped-def]
        from emulator.rainbow.files import save_png

        if self.args.screenshot:
            if self.window is not None:
                self.window.screenshot(self.args.screenshot)
            else:
                save_png(self.args.screenshot, session.executor.last_frame)
        if self.window is not None:
            self.window.close()


def _play(args: argparse.Namespace) -> int:
    import sys
    from pathlib import Path

    from apps.snooker.program import script_events
    from apps.snooker.program.program import Program
    from apps.snooker.session import Session, SessionError
    from emulator.rainbow.session import in_process

    def fail(msg: str) -> int:
        print(f"camlab88 snooker: {msg}", file=sys.stderr)
        return 2

    restore = None
    if args.session and Path(args.session).exists():
        try:
            restore = Session.load(args.session)
        except SessionError as exc:
            return fail(str(exc))
    try:
        player = script_events.Player(script_events.load(args.events)) if args.events else None
    except script_events.ScriptError as exc:
        return fail(str(exc))
    frames = args.frames
    if frames is None and (args.headless or args.screenshot):
        frames = (player.steps and sum(n for _, n in player.steps)) if player else 100
    screen = _Screen(args, "camlab88 snooker")
    rb = in_process(on_frame=screen.on_frame)
    program = Program(rb.client, restore=restore, save_to=args.save or args.session,
                      restore_name=str(args.session))
    n = 0
    try:
        while not program.done and not screen.quit and (frames is None or n < frames):
            if player is not None:
                for e in player.due():
                    rb.inject(e)
            screen.poll(rb, inject=player is None)
            program.step()
            n += 1
    except SessionError as exc:
        return fail(str(exc))
    finally:
        screen.finish(rb)
    st = program.session.status()
    print(f"camlab88 snooker: {n} display frames; at frame {st['frame']} "
          f"({len(program.session.timeline.time_frames)} time frames), scores "
          f"{st['scores'][0]}-{st['scores'][1]}"  # type: ignore[index]
          + (f"; saved {', '.join(map(str, program.saved))}" if program.saved else ""))
    return 0


def _replay(args: argparse.Namespace) -> int:
    import sys

    from apps.snooker.checkpoint import CheckpointError, read, to_metres
    from apps.snooker.program.program import Program
    from apps.snooker.table import Table
    from emulator.rainbow.session import in_process

    try:
        cp = read(args.checkpoint)
        last = cp.n_frames - 1 if args.last is None else args.last
        cp = cp.subset(args.first, last)
    except (CheckpointError, ValueError) as exc:
        print(f"camlab88 snooker replay: {exc}", file=sys.stderr)
        return 2
    table = Table()
    pos = [to_metres(p) for p in cp.positions]
    if args.frames is not None:
        pos = pos[: max(1, (args.frames + 1) // 2)]
    on = [[table.on_playing_area(x, y) for x, y in p] for p in pos]
    screen = _Screen(args, "camlab88 snooker replay")
    rb = in_process(on_frame=screen.on_frame)
    try:
        Program(rb.client).play_positions(pos, on)  # type: ignore[arg-type]
    finally:
        screen.finish(rb)
    print(f"camlab88 snooker replay: {len(pos)} frames at 25 frames/s "
          f"({rb.device.frame_count} display frames, {len(pos) / 25:.2f} s)")
    return 0


def rainbow_demo(on_frame=None, seconds: float = 4.0):  # type: ignore[no-untyped-def]
    """For `camlab88 demo`: a break replayed at 25 frames/s on an in-process Rainbow.
    `on_frame(frame)` receives every display frame (show it in a window, pace it, save
    it); returns the emulator session (its `executor.last_frame` is the last picture)."""
    from apps.snooker.program.demo import play_break
    from emulator.rainbow.session import in_process

    rb = in_process(on_frame=on_frame)
    play_break(rb.client, seconds)
    return rb


ACTIONS: list[Callable[[argparse._SubParsersAction], None]] = [  # type: ignore[type-arg]
    _add_play, _add_simulate, _add_replay]
