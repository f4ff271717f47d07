"""``camlab88 snooker play [SESSION]``: the interactive program on the emulated Rainbow."""

from __future__ import annotations

import argparse

from camlab88.commandspec import keys_of
from camlab88.runopts import fail, unattended
from camlab88.scriptopts import events_player, scripted_run_options

COMMAND = "camlab88 snooker"
KEYS = keys_of(__name__)


def play(args: argparse.Namespace) -> int:
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
    from camlab88.emulator.rainbow.session import in_process

    rb = in_process(record=opts.record is not None)
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
