"""The one display rule: window or headless.

* ``--headless`` given: headless.
* A display is available: a window.
* No display: if the command can do useful work headless it runs headless and says so on
  stderr (``can_headless`` names that work); otherwise it refuses in one line.  Never an
  invisible window.
"""

from __future__ import annotations

import os
import sys


class DisplayRefused(SystemExit):
    """No display and no useful headless work: the one-line refusal (exit status 2)."""

    def __init__(self, message: str) -> None:
        super().__init__(message)
        self.message = message


def display_available() -> bool:
    """A window can be seen (or, with SDL_VIDEODRIVER set, is deliberately off-screen)."""
    if sys.platform in ("darwin", "win32"):
        return True
    return bool(os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY")
                or os.environ.get("SDL_VIDEODRIVER"))


def choose_headless(command: str, headless: bool, can_headless: str | None,
                    refuse_hint: str = "give --headless") -> bool:
    """True to run headless.  ``can_headless``: what a headless run does (None: nothing
    useful, so without a display the command refuses, suggesting ``refuse_hint``)."""
    if headless:
        return True
    if display_available():
        return False
    if can_headless:
        print(f"{command}: no display; running headless ({can_headless})", file=sys.stderr)
        return True
    raise DisplayRefused(f"{command}: no display for a window; {refuse_hint}")
