"""``camlab88 snooker play [SESSION]``: the interactive program on the emulated Rainbow."""

from __future__ import annotations

import argparse

from camlab88.replay_policy import SCRATCH
from camlab88.runopts import add_run_options, fail, unattended
from camlab88.scriptopts import (
    HEADLESS_NEEDS_EVENTS,
    add_events_option,
    events_player,
    scripted_run_options,
)

COMMAND = "camlab88 snooker"
KEYS = """\
middle button: menus; right: restart simulation; left held: mouse x4; Esc: leave (y saves, n \
does not, Esc stays); close the window to quit"""

DESCRIPTION = f"""\
The interactive program (thesis §6.2.1-§6.2.2) on the emulated Rainbow. Middle button: menus \
and everything else; right: restart simulation; left held: mouse movement x4. With SESSION \
you are asked: new game (n) or restore (r). {HEADLESS_NEEDS_EVENTS}"""


HELP = "the interactive motion-development program on the emulated Rainbow"


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("session", nargs="?", metavar="SESSION",
                   help="a saved session file to offer for restoring (and to save to)")
    add_events_option(p)
    p.add_argument("--save", metavar="SESSION",
                   help="where 'Exit from the program' saves (default: SESSION; with "
                        "neither, Exit asks for a file name)").replay = SCRATCH
    add_run_options(p)


def run(args: argparse.Namespace) -> int:
    from camlab88.apps.snooker.session import Session, SessionError
    from camlab88.protocols.rainbow.script import ScriptError

    try:
        restore = Session.load(args.session) if _exists(args.session) else None
        player = events_player(args.events)
    except (SessionError, ScriptError) as exc:
        return fail(COMMAND, exc)
    opts = scripted_run_options(args, COMMAND, player)
    try:
        program, h = _run(args, opts, restore, player)
    except SessionError as exc:
        return fail(COMMAND, exc)
    _report(program, h.frames_shown)
    return 0


def _exists(path: str | None) -> bool:
    from pathlib import Path

    return bool(path) and Path(path).exists()


def _run(args: argparse.Namespace, opts, restore, player):
    from camlab88.apps.snooker.program.program import Program
    from camlab88.emulator.harness import run
    from camlab88.emulator.harness.rainbow import RainbowTarget
    from camlab88.emulator.machine import RainbowMachine

    rb = RainbowMachine(record=opts.record is not None)
    program = Program(rb.client, restore=restore, save_to=args.save or args.session,
                      restore_name=str(args.session))

    def step() -> bool:
        program.step()
        return not program.done

    target = RainbowTarget(rb, step, "camlab88 snooker", KEYS, player, unattended(opts),
                           program=program)
    target.escape_is_a_key = True  # Esc cancels, or asks y/n/Esc before leaving
    return program, run(target, opts)


def _report(program, frames: int) -> None:
    st = program.session.status()
    saved = f"; saved {', '.join(map(str, program.saved))}" if program.saved else ""
    print(f"camlab88 snooker: {frames} display frames; at frame {st['frame']} "
          f"({len(program.session.timeline.time_frames)} time frames), scores "
          f"{st['scores'][0]}-{st['scores'][1]}{saved}")
