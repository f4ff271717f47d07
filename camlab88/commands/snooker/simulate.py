"""``camlab88 snooker simulate``: a shot simulated headless until every ball stops."""

from __future__ import annotations

import argparse

from camlab88.runopts import fail

COMMAND = "camlab88 snooker simulate"


def _table_option(value: str) -> tuple[str, str]:
    if "=" not in value:
        raise argparse.ArgumentTypeError(f"expected NAME=VALUE, got {value!r}")
    k, v = value.split("=", 1)
    return k.strip(), v.strip()

DESCRIPTION = """\
Simulate until all balls have stopped and write the §6.2.2 checkpoint file (4096 units per \
foot). ANGLE_DEG is measured anticlockwise from straight up the table (from the baulk end \
towards the black); SPIN is m/s along the shot (+ top spin, - back spin)."""


HELP = "simulate a shot headlessly until every ball stops; write a checkpoint"


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("--from", dest="source", metavar="SESSION|CHECKPOINT",
                   help="start from a saved session (JSON) or the last frame of a "
                        "checkpoint")
    either = p.add_mutually_exclusive_group(required=True)
    either.add_argument("--break", dest="break_speed", type=float, metavar="SPEED_M_S",
                        help="the opening position, cue ball in the D struck at the pack")
    either.add_argument("--shot", nargs="+", metavar="ARG",
                        help="BALL SPEED_M_S ANGLE_DEG [SPIN_M_S]; BALL is 1..22 or a name "
                             "(cue, yellow, ..., black, red1..red15)")
    p.add_argument("--out", required=True, metavar="CHECKPOINT", help="checkpoint file to write")
    p.add_argument("--save-session", metavar="SESSION", help="also save the session file")
    p.add_argument("--first", default=0, type=int, help="first time frame to write (default 0)")
    p.add_argument("--last", type=int, help="last time frame to write (default: the last)")
    p.add_argument("--table", action="append", default=[], type=_table_option,
                   metavar="NAME=VALUE",
                   help="change a table constant, e.g. cushion_restitution=1.2 "
                        "ball_diameter_m=0.2 (new games only)")
    p.add_argument("--max-seconds", default=600.0, type=float,
                   help="give up if balls are still moving after this long (default 600)")


def run(args: argparse.Namespace) -> int:
    from camlab88.apps.snooker.checkpoint import CheckpointError
    from camlab88.apps.snooker.physics import SimulationError
    from camlab88.apps.snooker.session import SessionError

    try:
        session = _start(args)
        if isinstance(session, str):
            return fail(COMMAND, session)
        session.simulate_to_rest(args.max_seconds)
        cp = session.checkpoint(args.first, args.last)
        cp.write(args.out)
        if args.save_session:
            session.save(args.save_session)
    except (CheckpointError, SessionError, SimulationError, ValueError, OSError) as exc:
        return fail(COMMAND, exc)
    _report(session, cp, args)
    return 0


def _start(args: argparse.Namespace):  # a Session, or a message (str)
    from camlab88.apps.snooker.layout import break_off_direction
    from camlab88.apps.snooker.program.setup import start_from, table_with
    from camlab88.apps.snooker.session import Session
    from camlab88.apps.snooker.table import CUE, ball_index

    table = table_with(args.table)
    if args.break_speed is not None:
        if args.source:
            return "--break plays the opening position; it cannot be used with --from"
        if not args.break_speed > 0:
            return "the break speed must be positive"
        session = Session.new_game(table)
        ux, uy = break_off_direction(table, session.balls)
        session.set_velocity(CUE, ux * args.break_speed, uy * args.break_speed)
        return session
    if len(args.shot) not in (3, 4):
        return "--shot takes BALL SPEED_M_S ANGLE_DEG [SPIN_M_S]"
    ball = ball_index(args.shot[0])
    try:
        speed, angle, *rest = (float(x) for x in args.shot[1:])
    except ValueError:
        return f"--shot: not numbers: {' '.join(args.shot[1:])}"
    if speed < 0:
        return "the speed must not be negative"
    session = start_from(args.source, table) if args.source else Session.new_game(table)
    session.strike(ball, speed, angle, rest[0] if rest else 0.0)
    return session


def _report(session, cp, args: argparse.Namespace) -> None:
    from camlab88.apps.snooker.table import BALL_NAMES

    st = session.status()
    tl = session.timeline
    print(f"{len(tl.time_frames)} time frames ({tl.time_frames[-1].balls.t:.2f} s), "
          f"{st['collision']} collisions; wrote frames {args.first}..{args.first + cp.n_frames - 1}"
          f" to {args.out}")
    potted = [BALL_NAMES[i] for i in range(22) if not session.balls.on_table[i]]
    print(f"off the table: {', '.join(potted) or 'none'}; scores {st['scores'][0]}-"
          f"{st['scores'][1]}; {st['message']}")
    if args.save_session:
        print(f"saved the session to {args.save_session}")
