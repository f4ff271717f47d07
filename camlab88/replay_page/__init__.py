"""A session's replay as one web page (``camlab88 replay FILE --html OUT``): the page
(page.html with head.html, player.css, player.js: no network, no CDN) with the video of the
frames, the input events and, for a Sigma, the decoded orders as data in it.

Two forms, chosen by OUT: ``NAME.html`` is one self-contained file, the video inlined
(base64, played through a Blob URL): a file to mail or put anywhere, opened from file://
or any web server. A directory gets ``index.html`` beside ``session.mp4``: the video stays
a file of its own (a third smaller, streamed by a web server with range requests)."""

from __future__ import annotations

import base64
import html
import json
import re
from dataclasses import dataclass
from importlib import resources
from pathlib import Path
from typing import Any

MIME = {".mp4": "video/mp4", ".webm": "video/webm"}
PAGE = "index.html"


@dataclass
class PageText:
    """What the page says about the session, besides the data."""

    title: str
    recording: str          # the recording's name, for "camlab88 replay NAME"
    program: str            # the recorded command line
    device: str
    recorded: str           # the recording's date (its file's)
    version: str
    extra: str = ""         # more HTML under the title (the gallery's caption and notes)


def single_file(out: Path) -> bool:
    """True: OUT names one .html file; False: a directory for index.html and the video."""
    return out.suffix.lower() in (".html", ".htm")


def page_data(capture: Any, video_name: str) -> dict[str, Any]:
    c = capture
    return {"fps": c.fps, "frames": [[k, round(t, 6)] for k, t in c.frames],
            "videoFrames": c.video_frames, "screen": list(c.screen), "size": list(c.size),
            "panel": c.panel, "events": [[round(t, 6), s] for t, s in c.events],
            "orders": [[o, round(t, 6), s, 1] if w else [o, round(t, 6), s]
                       for o, t, s, w in c.orders],
            "droppedEvents": c.dropped_events, "droppedOrders": c.dropped_orders,
            "video": video_name}


def asset(name: str) -> str:
    return resources.files(__name__).joinpath(name).read_text(encoding="utf-8")


def _script_json(data: Any) -> str:
    """JSON safe inside <script>: no "</script>" or "<!--" can end or change it."""
    return json.dumps(data, separators=(",", ":"), ensure_ascii=False) \
        .replace("<", "\\u003c").replace(">", "\\u003e").replace("&", "\\u0026")


def fill(name: str, parts: dict[str, str]) -> str:
    """The asset ``name`` with its ``@MARKER@``s replaced, in one pass: what is put in (a
    session's text among it) is never read for markers."""
    return re.sub(r"@[A-Z_]+@", lambda m: parts.get(m.group(0), m.group(0)), asset(name))


def head(title: str, version: str, css: str) -> str:
    """The document's start up to ``</head>``, the same for the page and the gallery:
    ``title`` and ``version`` as HTML, ``css`` the style sheet (head.html, without its last
    newline: the template's ``@HEAD@`` line has one)."""
    return fill("head.html", {"@TITLE@": title, "@VERSION@": version,
                              "@CSS@": css}).removesuffix("\n")


def _video_parts(video: Path, inline: bool) -> tuple[str, str]:
    """The inlined video's script element, or the video element's ``data-src``."""
    if not inline:
        return "", f' data-src="{html.escape(video.name)}"'
    b64 = base64.b64encode(video.read_bytes()).decode("ascii")
    mime = MIME[video.suffix.lower()]
    return f'<script type="application/octet-stream" id="video-data" data-mime="{mime}">' \
           f"{b64}</script>", ""


def _meta(c: Any, text: PageText) -> str:
    e = html.escape
    return (f"{e(text.device)} &middot; program <code>{e(text.program)}</code> &middot; "
            f"recorded {e(text.recorded)} &middot; made by camlab88 {e(text.version)} &middot; "
            f"{len(c.frames)} frames at {c.fps:g} frames a second "
            f"({c.video_frames / c.fps if c.fps else 0:.1f} s)")


def _footer(c: Any, text: PageText) -> str:
    e = html.escape
    footer = (f"Replay it for real, in the emulator: <code>camlab88 replay "
              f"{e(text.recording)}</code> (add <code>--check</code> to compare every "
              f"screen hash; <code>--period</code> to play at the line's own speed). This "
              f"page was made by <code>camlab88 replay {e(text.recording)} --html</code>; "
              f"it needs no network.")
    dropped = [f"{n} later {what} not listed" for n, what in
               ((c.dropped_events, "input events"), (c.dropped_orders, "orders")) if n]
    if dropped:
        footer += " " + e("; ".join(dropped)) + " (the page lists the first 100000)."
    return footer


PANEL_NOTE = ('<p class="hint">Left: the screen; right: the inspector\'s panel at the same '
              'frame (the band structure over the screen, video memory per plane, the pad '
              'graph).</p>')


def render(capture: Any, text: PageText, video: Path, inline: bool) -> str:
    """The page's HTML; the video inlined (``inline``) or named beside it."""
    e, c = html.escape, capture
    video_data, src = _video_parts(video, inline)
    return fill("page.html", {
        "@HEAD@": head(e(text.title), e(text.version), asset("player.css")),
        "@TITLE@": e(text.title),
        "@META@": _meta(c, text), "@EXTRA@": text.extra,
        "@WIDTH@": str(c.size[0]), "@HEIGHT@": str(c.size[1]), "@SRC@": src,
        "@PANEL_NOTE@": PANEL_NOTE if c.panel else "", "@NEVENTS@": str(len(c.events)),
        "@NORDERS@": str(len(c.orders)), "@ORDERS_HIDDEN@": "" if c.orders else "hidden",
        "@FOOTER@": _footer(c, text), "@DATA@": _script_json(page_data(c, video.name)),
        "@JS@": asset("player.js"), "@VIDEO_DATA@": video_data,
    })


def write(out: Path, capture: Any, text: PageText, video: Path) -> list[Path]:
    """Write the page (atomically); returns the files written."""
    from camlab88.base.atomicfile import write_atomic

    if single_file(out):
        write_atomic(out, render(capture, text, video, inline=True).encode("utf-8"))
        return [out]
    out.mkdir(exist_ok=True)  # one level: its parent was checked (the one output rule)
    moved = out / f"session{video.suffix}"
    write_atomic(moved, video.read_bytes())
    page = out / PAGE
    write_atomic(page, render(capture, text, moved, inline=False).encode("utf-8"))
    return [page, moved]
