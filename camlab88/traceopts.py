"""``--trace FILE`` and ``--strict``, shared by the commands that decode a device protocol:
a JSON Lines trace of every order, and a stop at the first protocol error naming where."""

from __future__ import annotations

import argparse
import sys
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import Any

from camlab88.replay_policy import KEEP, SCRATCH


def add_trace_options(p: argparse.ArgumentParser, strict: str = "--strict") -> None:
    """``strict`` is the flag's name (the Rainbow commands' --strict already means the
    relic's memory, so theirs is --strict-protocol)."""
    p.add_argument("--trace", metavar="FILE",
                   help="write every decoded order as JSON Lines: byte offset, virtual time, "
                   "order, its arguments, any warning").replay = SCRATCH
    p.add_argument(strict, dest="strict_protocol", action="store_true",
                   help="exit 1 at the first unknown, malformed or out-of-range order, naming "
                   "its byte offset, time, the bytes before it and what was expected",
                   ).replay = KEEP


class TraceRun:
    """What a command traces into: ``sink`` (None when neither option is given)."""

    def __init__(self, args: argparse.Namespace, command: str, source: str) -> None:
        from camlab88.emulator.protocol_trace import TraceFile

        self.command, self.source = command, source
        self.strict = bool(getattr(args, "strict_protocol", False))
        self.file = None
        if args.trace:
            try:
                self.file = TraceFile(args.trace)
            except OSError as exc:
                raise SystemExit(f"{command}: cannot write --trace {args.trace}: "
                                 f"{exc.strerror or exc}") from None
        self.problems = 0
        self.failed = False
        self.stream: bytes | None = None  # the whole input, when known: strict shows after
        self.sink: Callable[[Any], None] | None = (
            self._sink if self.file is not None or self.strict else None)

    def _sink(self, ev: Any) -> None:
        if self.file is not None:
            self.file(ev)
        if ev.warning is not None:
            self.problems += 1


@contextmanager
def open_trace(args: argparse.Namespace, command: str, source: str) -> Iterator[TraceRun]:
    """The trace file is written (atomically) however the block ends; a ProtocolError
    (strict) becomes one line on stderr and ``failed``."""
    from camlab88.emulator.protocol_trace import ProtocolError

    run = TraceRun(args, command, source)
    try:
        yield run
    except ProtocolError as exc:
        run.failed = True
        after = ""
        if run.stream is not None:
            off = exc.event.offset
            after = f"; bytes from it on: {run.stream[off:off + 12]!r}"
        print(f"{command}: {source}: {exc}{after}", file=sys.stderr, flush=True)
    finally:
        if run.file is not None:
            run.file.close()
            print(f"{command}: traced {run.file.count} orders to {run.file.path}",
                  file=sys.stderr, flush=True)
