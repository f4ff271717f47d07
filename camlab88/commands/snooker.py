"""`camlab88 snooker ...`: the snooker motion-development program (thesis ch. 6).

Actions so far:
  simulate  headless: set a ball moving (or play the break-off), simulate until every ball
            has stopped, write the checkpoint file (and optionally the session).
The interactive Rainbow program and `replay` register further actions on the same parser
(see `ACTIONS`).
"""

from __future__ import annotations

import argparse
from collections.abc import Callable

HELP = "snooker motion development (thesis chapter 6): simulate shots, checkpoint files"


def register(subparsers: argparse._SubParsersAction) -> None:  # type: ignore[type-arg]
    p = subparsers.add_parser("snooker", help=HELP, description=HELP)
    actions = p.add_subparsers(dest="snooker_action", metavar="ACTION")
    for add in ACTIONS:
        add(actions)
    p.set_defaults(handler=lambda args: _no_action(p))


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


ACTIONS: list[Callable[[argparse._SubParsersAction], None]] = [_add_simulate]  # type: ignore[type-arg]
