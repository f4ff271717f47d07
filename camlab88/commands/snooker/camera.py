"""``camlab88 snooker camera SCRIPT CHECKPOINT``: the camera script beside the live view,
re-interpreted on every edit (thesis §6.5's interactive system)."""

from __future__ import annotations

import argparse
import sys

from camlab88.base.plainstate import Record, Str
from camlab88.runopts import add_run_options, fail, unattended
from camlab88.scriptopts import (
    HEADLESS_NEEDS_EVENTS,
    add_events_option,
    events_player,
    scripted_run_options,
)

COMMAND = "camlab88 snooker camera"
KEYS = """\
type to edit the script (it is re-interpreted at once; saving it from another editor works \
too); ctrl-s saves, ctrl-r reloads; tab play/pause; page up/down step; left button on the \
time line scrubs; escape quits"""

DESCRIPTION = f"""\
The camera script beside the live perspective view on the emulated Rainbow: every edit, typed \
here or saved to SCRIPT from any text editor, is re-interpreted and the view updates at once; \
errors are marked at their lines while the preview goes on. Keys: {KEYS}. \
{HEADLESS_NEEDS_EVENTS}"""


HELP = "edit a camera script with the live view beside it (§6.5)"


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("script", metavar="SCRIPT", help="the camera script (created if missing)")
    p.add_argument("motion", metavar="CHECKPOINT|SESSION")
    add_events_option(p)
    add_run_options(p)


def run(args: argparse.Namespace) -> int:
    from camlab88.apps.snooker.camera import motion
    from camlab88.apps.snooker.checkpoint import CheckpointError
    from camlab88.apps.snooker.session import SessionError
    from camlab88.protocols.rainbow.script import ScriptError

    try:
        shot = motion.load(args.motion)
        player = events_player(args.events)
    except (CheckpointError, SessionError, ScriptError, OSError) as exc:
        return fail(COMMAND, exc)
    opts = scripted_run_options(args, COMMAND, player)
    h, tool = _run(shot, args.script, player, opts)
    r = tool.result
    n = len(r.errors) if r is not None else 0
    print(f"{COMMAND}: {h.frames_shown} frames shown; script interpreted "
          f"{tool.interpretations} times; {n} error{'' if n == 1 else 's'} now"
          + ("; unsaved edits" if tool.modified else ""), file=sys.stderr)
    return 0


def _run(shot, script, player, opts, plugins=()):
    from camlab88.apps.snooker.camera_tool.tool import CameraTool
    from camlab88.emulator.harness import run
    from camlab88.emulator.harness.rainbow import RainbowTarget
    from camlab88.emulator.machine import RainbowMachine

    class Target(RainbowTarget):
        """The script as read from disk during the run is outside input: recorded, and fed
        back by `camlab88 replay`."""

        def wire(self) -> list[tuple[str, bytes]]:
            out = [("+", t.encode("utf-8")) for t in tool.outside]
            tool.outside.clear()
            return super().wire() + out

        def put_wire(self, data: bytes) -> None:
            tool.feed(data.decode("utf-8"))

    rb = RainbowMachine(record=opts.record is not None)
    tool = CameraTool(rb.client, shot, script)

    def step() -> bool:
        read = len(tool.outside)
        alive = tool.step()
        for text in tool.outside[read:]:  # SCRIPT as read from disk: in a save state too
            target.log.read(text)
        return alive

    target = Target(rb, step, COMMAND, KEYS, player, unattended(opts))
    target.escape_is_a_key = True  # the tool's own Esc: done
    target.keep_input(_start_state(tool, script), _rebuilding(tool), tool.feed)
    return run(target, opts, list(plugins)), tool


# the script's text when the tool started, in its save state: ctrl-s rewrites SCRIPT, so a
# load starts from the state's text and SCRIPT is only where ctrl-s saves (its content is
# left out of the state's identity)
START = Record(text=Str(1 << 22), status=Str(4096))


def _start_state(tool, script):
    from camlab88.apps.snooker.camera_tool.editor import TextBuffer
    from camlab88.emulator.harness.input_log import StartState

    start = {"text": tool.buf.text, "status": tool.status}

    def load(kept: dict) -> None:
        tool.buf = TextBuffer(kept["text"])
        tool.status = kept["status"]

    return StartState(START, lambda: start, load, (str(script),))


def _rebuilding(tool):
    def rebuilding(on: bool) -> None:
        """While a load runs the session again: no writes, the disk's texts from the log."""
        tool.writes = not on
        tool.fed = [] if on else None
    return rebuilding
