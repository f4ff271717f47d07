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


def simulate(args: argparse.Namespace) -> int:
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
