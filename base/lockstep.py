"""The frames of a program that shows them through a callback, as a generator, in lockstep:
``lockstep(run)`` runs ``run(show)`` in a thread that waits after each ``show(frame)`` until
the next frame is wanted. So the program's state (its device) is the one that made the frame
just taken — an inspector reading it sees what made the picture — nothing is computed ahead,
and the order of work is the program's own (deterministic)."""

from __future__ import annotations

import queue
import threading
from collections.abc import Callable, Iterator
from typing import Any


class _Stopped(Exception):
    """The frames are no longer wanted (the generator was closed)."""


def lockstep(run: Callable[[Callable[[Any], None]], object]) -> Iterator[Any]:
    handed: queue.Queue[tuple[str, Any]] = queue.Queue(maxsize=1)
    wanted = threading.Semaphore(0)
    stop = threading.Event()

    def show(frame: Any) -> None:
        handed.put(("frame", frame.copy()))
        wanted.acquire()
        if stop.is_set():
            raise _Stopped

    threading.Thread(target=_body, args=(run, show, handed), name="camlab88 lockstep",
                     daemon=True).start()
    try:
        while True:
            kind, item = handed.get()
            if kind == "error":
                raise item
            if kind == "done":
                return
            yield item
            wanted.release()
    finally:  # closed early, or done: the program's thread ends
        stop.set()
        wanted.release()


def _body(run: Callable[[Callable[[Any], None]], object], show: Callable[[Any], None],
          handed: queue.Queue[tuple[str, Any]]) -> None:
    try:
        run(show)
    except _Stopped:
        return
    except BaseException as exc:  # raised in the generator's caller
        handed.put(("error", exc))
        return
    handed.put(("done", None))
