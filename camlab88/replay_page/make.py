"""A recording replayed headless into its web page (``replay --html``, ``figures --html``)."""

from __future__ import annotations

import tempfile
from dataclasses import dataclass, field
from datetime import UTC, datetime
from pathlib import Path
from typing import Any

from camlab88.replay_page import PageText, single_file, write

CODECS = {"h264": ".mp4", "vp9": ".webm"}
DEVICE_OF = {"kas": "Sigma T5684", "sigma": "Sigma", "snooker": "Rainbow workstation",
             "ca": "Rainbow workstation", "rainbow": "Rainbow workstation"}


@dataclass
class Made:
    """What a page's replay did: the run's status and context, the files written."""

    status: int
    said: str
    ctx: Any
    capture: Any = None
    files: list[Path] = field(default_factory=list)


def recorded_on(path: Path) -> str:
    """The recording's date: its file's (a recording, format 1, holds no date of its own)."""
    stamp = datetime.fromtimestamp(path.stat().st_mtime, UTC)
    return f"{stamp:%Y-%m-%d %H:%M} UTC (the recording file's date)"


def make_page(rec: Any, recording: Path, out: Path, codec: str = "h264", check: bool = False,
              title: str | None = None, extra: str = "", replay_as: str | None = None) -> Made:
    """Replay ``rec`` (read from ``recording``) headless, gathering the page's video and
    data, and write the page to ``out`` when the program ran to its end (``replay_as``: the
    recording's name in the page's "camlab88 replay NAME", else its file name). Raises
    ReplayRefused as ``rerun`` does."""
    from camlab88 import __version__
    from camlab88.emulator.harness.replay import Replay
    from camlab88.emulator.harness.web_capture import WebCapture
    from camlab88.session_replay import rerun

    with tempfile.TemporaryDirectory(prefix="camlab88-page-") as tmp:
        video = Path(tmp) / f"session{CODECS[codec]}"
        capture = WebCapture(video)
        ctx = Replay(rec, headless=True, check=check, capture=capture)
        status, said = rerun(ctx)
        made = Made(status, said, ctx, capture.data)
        if (status != 0 or ctx.runs == 0 or ctx.mismatch is not None or ctx.fault is not None
                or not video.is_file()):
            return made
        program = " ".join(rec.argv)
        device = capture.data.device or DEVICE_OF.get(rec.argv[0], "?")
        text = PageText(title=title or f"{' '.join(rec.argv[:2])} on the {device}: "
                        f"{recording.name}", recording=replay_as or recording.name, program=program,
                        device=device, recorded=recorded_on(recording), version=__version__,
                        extra=extra)
        made.files = write(out, capture.data, text, video)
    return made


def form_of(out: Path) -> str:
    """What ``out`` gets, and why, for the command's message."""
    if single_file(out):
        return "one self-contained file, the video inside it (OUT ends in .html: a page " \
               "to send or put anywhere)"
    return "a directory: index.html beside the video file (OUT is not a .html name: a " \
           "third smaller, streamed by a web server)"
