"""The run flags every interactive command shares, meaning one thing everywhere.

``--headless``   no window (the display rule of emulator.harness.display otherwise decides)
``--screenshot PNG``  run to the end unpaced, save the last screen, exit; writes no other file
``--frames DIR``  every frame shown as DIR/frame_NNNNN.png (always a directory)
``--stop-after N``  stop after N frames (the count that ``--frames N`` used to be)
``--record FILE``  a session recording for ``camlab88 replay``
``--scale N``    window scale
``--speed X``, ``--video FILE``, ``--inspect``, ``--inspect-out DIR``: camlab88.control_flags
``--save-state FILE``, ``--at SECONDS``, ``--load-state FILE``  save states (stateopts.py)
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path
from typing import TYPE_CHECKING

from camlab88.replay_policy import DROP, KEEP, SCRATCH

if TYPE_CHECKING:
    from camlab88.emulator.harness import RunOptions


def frames_dir(text: str) -> Path:
    """``--frames DIR``; a bare number is the old count, refused with the new spelling."""
    if text.isascii() and text.isdigit():
        raise argparse.ArgumentTypeError(
            f"--frames is a directory of frame_NNNNN.png now; for a count of {text} frames "
            f"use --stop-after {text}")
    return Path(text)


def positive(text: str) -> int:
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a whole number: {text!r}") from None
    if value < 1:
        raise argparse.ArgumentTypeError(f"must be at least 1, not {value}")
    return value


def add_run_options(p: argparse.ArgumentParser, record: bool = True,
                    stop_after: bool = True) -> None:
    """Add the shared run flags to an action's parser: each is run-only (it changes how the
    run is shown or recorded, never what the program does: a save state's identity leaves
    it out) and says what a replay does with it (camlab88.replay_policy)."""
    shown = [
        (p.add_argument("--headless", action="store_true", help="no window (virtual time)"),
         KEEP),
        (p.add_argument("--screenshot", type=Path, metavar="PNG",
                        help="run to the end unpaced, save the last screen as PNG and exit"),
         SCRATCH),
        (p.add_argument("--frames", type=frames_dir, metavar="DIR",
                        help="write every frame shown as DIR/frame_NNNNN.png"), SCRATCH)]
    if stop_after:
        shown.append((p.add_argument("--stop-after", type=positive, metavar="N",
                                     help="stop after N frames"), KEEP))
    if record:  # the session recorder: a command with it is a program a replay runs
        shown.append((p.add_argument(
            "--record", type=Path, metavar="FILE",
            help="record the session (replay it with 'camlab88 replay FILE')"), DROP))
    shown.append((p.add_argument("--scale", type=positive, default=1,
                                 help="window scale (default 1)"), KEEP))
    for action, kind in shown:
        action.replay, action.run_only = kind, True
    from camlab88.control_flags import add_control_options

    add_control_options(p, speed_flag=not any(a.dest == "speed" for a in p._actions))
    from camlab88.stateopts import add_state_options

    add_state_options(p)


def run_options(args: argparse.Namespace, command: str, can_headless: str | None,
                refuse_hint: str = "give --headless", argv: list[str] | None = None,
                ) -> RunOptions:
    """RunOptions from the shared flags; the display rule decides window or headless."""
    from camlab88.emulator.harness import RunOptions, choose_headless, replay

    active = replay.active()
    if active is not None:  # the program decides as in the recorded run; the replay's own
        headless = active.rec.headless  # --headless decides the window (Replay.adjust)
    else:
        headless = choose_headless(command, bool(args.headless), can_headless, refuse_hint)
    record = getattr(args, "record", None)
    if record is not None:
        _check_writable(command, Path(record), "record to")
    if getattr(args, "screenshot", None) is not None and active is None:
        check_output(command, Path(args.screenshot), "save the screenshot to", (".png",))
    if getattr(args, "frames", None) is not None and active is None:
        check_output_dir(command, Path(args.frames))
    from camlab88.control_flags import controls_from_args
    from camlab88.stateopts import state_options

    controls = controls_from_args(args, command, headless)
    return RunOptions(
        controls=controls, state=state_options(args, command, active),
        headless=headless, scale=getattr(args, "scale", 1),
        screenshot=getattr(args, "screenshot", None), frames=getattr(args, "frames", None),
        record=getattr(args, "record", None), stop_after=getattr(args, "stop_after", None),
        command=command, argv=list(sys.argv[1:] if argv is None else argv),
        run_only=getattr(args, "_run_only", {}))


def unattended(opts: RunOptions) -> bool:
    """A run nobody watches (headless, or one that ends in a screenshot): it ends when its
    script or input does, instead of waiting for the window to be closed."""
    return opts.headless or opts.screenshot is not None


def _check_writable(command: str, path: Path, doing: str) -> None:
    """Refuse at the start, not after the session, a file that cannot be written."""
    check_output(command, path, doing)


def _place(command: str, path: Path, doing: str) -> None:
    """The one output rule's first half (docs/exit_status.md): the directory an output
    goes in must exist (it is never created), a file in the way is named as such."""
    from camlab88.base.atomicfile import place_fault

    why = place_fault(path)
    if why is not None:
        raise SystemExit(f"{command}: cannot {doing} {path}: {why}")


def check_output(command: str, path: Path, doing: str = "write",
                 kinds: tuple[str, ...] = ()) -> None:
    """Refuse at the start, not after the work, an output that cannot be written (status
    2, one line): a name whose extension is not one of ``kinds`` (the formats the command
    writes, when the extension chooses one: ``--out x.jpg`` for a PNG writer); a directory
    at the path; a directory that is missing (never created), read-only or not ours; a file
    in the way of the directory. A device or FIFO is written into (base.atomicfile), so
    only it must be writable."""
    import os

    if kinds and path.suffix.lower() not in kinds:
        said = f"'{path.suffix}'" if path.suffix else "no extension"
        raise SystemExit(f"{command}: cannot {doing} {path}: {said} names no format it "
                         f"writes ({', '.join(kinds)})")
    if path.is_dir():
        raise SystemExit(f"{command}: cannot {doing} {path}: it is a directory")
    if path.exists() and not path.is_file():
        if not os.access(path, os.W_OK):
            raise SystemExit(f"{command}: cannot {doing} {path}: not writable")
        return
    _place(command, path, doing)
    parent = path.parent if str(path.parent) else Path(".")
    if not os.access(parent, os.W_OK):
        raise SystemExit(f"{command}: cannot {doing} {path}: its directory {parent} is "
                         "read-only")
    from camlab88.base.atomicfile import probe

    try:
        probe(path)  # a full disk shows now, not after the run
    except OSError as exc:
        raise SystemExit(f"{command}: cannot {doing} {path}: {exc.strerror}") from None


def check_output_dir(command: str, path: Path, doing: str = "write frames to") -> None:
    """The same rule for a directory of outputs (``--frames DIR``): DIR may be new (it is
    made, one level), but its parent must exist; a file at DIR or in its way is named."""
    import os

    if path.exists() and not path.is_dir():
        raise SystemExit(f"{command}: cannot {doing} {path}: it is a file in the way, not a "
                         "directory")
    _place(command, path, doing)
    where = path if path.is_dir() else (path.parent if str(path.parent) else Path("."))
    if not os.access(where, os.W_OK):
        raise SystemExit(f"{command}: cannot {doing} {path}: {where} is read-only")


def fail(command: str, message: object, status: int = 2) -> int:
    """Print ``command: message`` on stderr and return ``status``; an OS error reads
    ``file: reason`` (not Python's ``[Errno 2] No such file or directory: 'file'``)."""
    if isinstance(message, OSError) and message.filename is not None and message.strerror:
        message = f"{message.filename}: {message.strerror}"
    print(f"{command}: {message}", file=sys.stderr)
    return status


def progress(label: str):  # a callback (i, n) or None
    """A text progress bar on a terminal; nothing when stderr is a file or pipe."""
    if not sys.stderr.isatty():
        return None

    def show(i: int, n: int) -> None:
        width = 30
        done = width * i // max(n, 1)
        sys.stderr.write(f"\r{label} [{'#' * done}{'.' * (width - done)}] {i}/{n}")
        if i >= n:
            sys.stderr.write("\n")
        sys.stderr.flush()
    return show
