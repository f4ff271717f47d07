"""``camlab88 figures --html DIR``: every thesis figure's session as its own replay page
(``fig-N.html``, self-contained), each page headed by the figure's number, section, the
thesis's caption and where ours differs (camlab88.figure_catalogue, the one place those
live), and ``index.html``: the gallery, with a thumbnail of each figure's last screen.
Everything opens offline, from file:// or any web server."""

from __future__ import annotations

import html
import sys
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from camlab88.replay_page import asset, fill, head

THUMB_STEP = 2  # thumbnails at half size
TITLE = "The thesis's screen figures, replayed: camlab88"  # as HTML


@dataclass
class Entry:
    figure: Any            # camlab88.figure_catalogue.Figure
    page: Path | None      # None: not made (no recording, or its replay failed)
    thumb: Path | None
    why: str = ""          # why there is no page


def figure_html(fig: Any) -> str:
    """The figure's number, section, caption and verdict, for the top of its page."""
    e = html.escape
    out = (f'<p class="figure"><strong>Figure {e(fig.number)}</strong> '
           f"({e(fig.section_label)}): &ldquo;{e(fig.caption)}&rdquo;</p>\n"
           f'  <p class="figure">Ours: {e(fig.shows)}</p>\n')
    if fig.differs:
        out += f'  <p class="figure"><strong>{e(fig.verdict)}</strong>: {e(fig.differs)}</p>\n'
    else:
        out += f'  <p class="figure">Verdict: {e(fig.verdict)}.</p>\n'
    return out


def _card(en: Entry) -> str:
    e, f = html.escape, en.figure
    head = f"Figure {e(f.number)} <span class=\"sec\">{e(f.section_label)}</span>"
    if en.page is not None:
        thumb = (f'<img src="{e(en.thumb.name)}" alt="the last screen of figure '
                 f'{e(f.number)}\'s session">' if en.thumb else "")
        head = f'<a href="{e(en.page.name)}">{thumb}{head}</a>'
    else:
        head = f"{head} <em>({e(en.why)})</em>"
    verdict = (f"<p><strong>{e(f.verdict)}</strong>: {e(f.differs)}</p>" if f.differs
               else f"<p>{e(f.verdict)}</p>")
    return (f'<li class="card"><h2>{head}</h2>\n<p class="caption">&ldquo;{e(f.caption)}'
            f"&rdquo;</p>\n<p>{e(f.shows)}</p>\n{verdict}</li>")


def index_html(entries: list[Entry], version: str) -> str:
    made = sum(en.page is not None for en in entries)
    return fill("gallery.html", {
        "@HEAD@": head(TITLE, html.escape(version), asset("gallery.css")),
        "@VERSION@": html.escape(version),
        "@COUNT@": f"{made} of {len(entries)}", "@CARDS@": "\n".join(map(_card, entries))})


def build(out: Path, figures: list[Any], recording: Any, codec: str = "h264") -> list[Entry]:
    """Pages for ``figures`` (``recording(number)``: its session file) into ``out``, then
    index.html. A figure whose recording is missing or whose replay fails is listed without
    a page, saying why; the others are made."""
    from camlab88 import __version__
    from camlab88.base.atomicfile import write_atomic
    from camlab88.base.png import write_png
    from camlab88.protocols.session import SessionFileError, read
    from camlab88.replay_page.make import make_page
    from camlab88.replay_policy import ReplayRefused

    out.mkdir(exist_ok=True)  # one level: its parent was checked (the one output rule)
    entries = []
    for fig in figures:
        path = recording(fig.number)
        if not path.is_file():
            entries.append(Entry(fig, None, None, "not recorded yet"))
            continue
        page = out / f"fig-{fig.number}.html"
        try:
            made = make_page(read(path), path, page, codec,
                             title=f"Figure {fig.number} ({fig.section_label}): {fig.short}",
                             extra=figure_html(fig),
                             replay_as=f"examples/figures/{path.name}")
        except (SessionFileError, ReplayRefused) as exc:
            entries.append(Entry(fig, None, None, f"not replayed: {exc}"))
            continue
        if not made.files:
            entries.append(Entry(fig, None, None, f"its replay ended with exit status "
                                 f"{made.status}"))
            continue
        thumb = None
        if made.capture.last is not None:
            thumb = out / f"fig-{fig.number}.png"
            write_png(made.capture.last[::THUMB_STEP, ::THUMB_STEP], thumb)
        entries.append(Entry(fig, page, thumb))
        print(f"  figure {fig.number}: {page.name} ({page.stat().st_size / 1e6:.2f} MB, "
              f"{len(made.capture.frames)} frames)", file=sys.stderr, flush=True)
    write_atomic(out / "index.html", index_html(entries, __version__).encode("utf-8"))
    return entries
