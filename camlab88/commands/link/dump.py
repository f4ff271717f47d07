"""``camlab88 link dump REC``: a link recording in readable form."""

from __future__ import annotations

import argparse
import sys

SESSION_NOTE = ("is a session recording, not a link recording: `sigma run --record FILE` "
                "now writes a session recording (play it with `camlab88 replay FILE`); "
                "`sigma run --record-line FILE` writes the link recording that `link dump` reads")


def register(actions: argparse._SubParsersAction) -> None:  # type: ignore[type-arg]
    p = actions.add_parser("dump", help="print a link recording readably",
                           description="Print a link recording (sigma run --record-line FILE, "
                           "link record ...) readably: one timed chunk a line.")
    p.add_argument("recording")
    p.set_defaults(handler=dump)


def dump(args: argparse.Namespace) -> int:
    from protocols.link.cli import dump as dump_recording

    if _is_session_recording(args.recording):
        print(f"error: {args.recording} {SESSION_NOTE}", file=sys.stderr)
        return 2
    return dump_recording(args.recording)


def _is_session_recording(path: str) -> bool:
    """True when the file's first line is a session recording's header (protocols.session)."""
    import json

    from protocols.session import FORMAT

    try:
        with open(path, "rb") as f:
            first = f.readline(4096)
        obj = json.loads(first)
    except (OSError, ValueError):
        return False  # unreadable or not JSON: the link reader gives its own error
    return isinstance(obj, dict) and obj.get("format") == FORMAT
