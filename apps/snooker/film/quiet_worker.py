"""Loaded into every Dask worker process that ``--dask local`` starts (its ``preload``):
Ctrl-C in the terminal reaches the whole process group, and only the command should answer
it (with one line); a worker that took it would print a KeyboardInterrupt traceback. The
command stops its workers itself, and the warnings a worker logs when its frames are
cancelled at that stop are not news: a worker here logs errors only. Nor is a heartbeat
that finds the scheduler gone: the scheduler lives in the command's own process, so it is
gone only when the command is stopping (a worker whose heartbeat raced the stop printed a
traceback of it after Ctrl-C's one line)."""

from __future__ import annotations

import logging
import signal
import threading
from typing import Any

HEARTBEAT_LOST = "Failed to communicate with scheduler during heartbeat"


class _NoLostHeartbeat(logging.Filter):
    def filter(self, record: logging.LogRecord) -> bool:
        return not str(record.msg).startswith(HEARTBEAT_LOST)


def dask_setup(worker: Any) -> None:  # the preload interface
    if threading.current_thread() is threading.main_thread():
        signal.signal(signal.SIGINT, signal.SIG_IGN)
    logging.getLogger("distributed").setLevel(logging.ERROR)
    logging.getLogger("distributed.worker").addFilter(_NoLostHeartbeat())
