"""A real tablet beside a program on the emulated Rainbow (``--tablet SOURCE`` of
``rainbow run`` and ``ca actors``): opened on a tape, so a recording replays it without the
device; its reports go to the Rainbow's tablet input; a lost tablet is dropped, not fatal."""

from __future__ import annotations

import argparse
import sys
from typing import TYPE_CHECKING, Any

from camlab88.replay_policy import TAPE

if TYPE_CHECKING:
    from camlab88.emulator.harness import RunOptions

SOURCE_FORMS = "hid:VID:PID, serial:PORT?protocol=P, or a pyserial URL?protocol=P"


def add_tablet_option(p: argparse.ArgumentParser, what: str, where: str) -> None:
    """``--tablet SOURCE``; the help reads "also WHAT a real tablet (the source forms) WHERE"."""
    tablet = p.add_argument("--tablet", metavar="SOURCE",
                            help=f"also {what} a real tablet ({SOURCE_FORMS}){where}")
    # a replay decodes the recorded tape; not in a save state's identity: the state holds
    # the tablet's input and its protocol (emulator.harness.input_log)
    tablet.replay, tablet.run_only = TAPE, True


def open_tablet(command: str, text: str | None, opts: RunOptions) -> Any:
    """The --tablet source (on a tape with --record; from the recording's tape in a replay,
    where the device is never opened); None without one. A live stylus moves on the wall
    clock, so its run is paced live."""
    if not text:
        return None
    from camlab88.emulator.tablet_input.taped import TapedTablet
    from camlab88.protocols.tablets.sources import SourceError

    try:
        tablet = TapedTablet.open(text, opts.record is not None)
    except (SourceError, OSError) as exc:
        raise SystemExit(f"{command}: --tablet {text}: {exc}") from None
    if tablet.live:
        opts.live = True
    return tablet


def feed_tablet(command: str, tablet: Any, machine: Any) -> None:
    """The tablet's new reports to the tablet input of ``machine`` (a RainbowMachine); a
    lost tablet is reported once and closed (not read again: its tape keeps what it said)."""
    from camlab88.emulator.rainbow.host_input import tablet_event
    from camlab88.protocols.tablets.sources import SourceLost

    try:
        for ev in tablet.read(0.0):
            machine.post(tablet_event(ev))
    except (SourceLost, OSError) as exc:
        print(f"{command}: tablet lost ({exc}); carrying on without it", file=sys.stderr)
        tablet.close()
