"""Loaded into every Dask worker process that ``--dask local`` starts (its ``preload``):
Ctrl-C in the terminal reaches the whole process group, and only the command should answer
it (with one line); a worker that took it would print a KeyboardInterrupt traceback. The
command stops its workers itself, and the warnings a worker logs when its frames are
cancelled at that stop are not news: a worker here logs errors only."""

from __future__ import annotations

import logging
import signal
import threading
from typing import Any


def dask_setup(worker: Any) -> None:  # the preload interface
    if threading.current_thread() is threading.main_thread():
        signal.signal(signal.SIGINT, signal.SIG_IGN)
    logging.getLogger("distributed").setLevel(logging.ERROR)
