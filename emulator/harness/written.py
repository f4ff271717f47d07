"""How the harness's writers (--frames, --screenshot, --video, --inspect-out, --save-state,
F12) name a file or directory they wrote: one line on stderr, as the command. A replay keeps
its program's own output back, so there the line is also kept for `camlab88 replay` to
print as its own."""

from __future__ import annotations

import sys
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from camlab88.emulator.harness.loop import Harness


def tell_written(harness: Harness, text: str) -> None:
    print(f"{harness.options.command}: {text}", file=sys.stderr, flush=True)
    from camlab88.emulator.harness.replay import active

    replay = active()
    if replay is not None:
        replay.wrote.append(text)
