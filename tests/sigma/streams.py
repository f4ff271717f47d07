"""Streams formed exactly as PGPLOT's GOC driver and the RAL GKS Sigmex driver form them."""

from __future__ import annotations

import math

from camlab88.protocols.sigma.drivers import PgplotGoc, RalGks


def pgplot_session() -> tuple[bytes, bytes, bytes]:
    """(the graph, the cursor prompt PGPLOT sends to read the cursor, what it sends after)."""
    g = PgplotGoc()
    g.init()
    g.erase()
    g.colour(1)
    g.frame(80, 60, 700, 480, xticks=11, tick=10)
    curve = [(80 + i * 4, 270 + int(180 * math.sin(i / 12.0))) for i in range(156)]
    g.polyline(curve)
    for i in range(0, 156, 13):
        g.dot(*curve[i])
    g.colour(0)
    g.line(80, 270, 700, 270)  # erase a line through the curve
    g.colour(1)
    g.flush()
    plot = bytes(g.out)
    prompt = g.cursor_prompt(300, 300)
    g.after_cursor()
    return plot, prompt, g.finish()[len(plot) + len(prompt):]


def pgplot_plot() -> bytes:
    """A PGPLOT-style graph: frame, ticks, a sine curve, markers as dots, erase colour (the
    cursor read left out: the golden images are of the drawing)."""
    plot, _prompt, after = pgplot_session()
    return plot + after


def gks_plot(high_res: bool = False) -> bytes:
    """A GKS-style picture: colour table, polylines of each linetype, a cell array, a dot."""
    g = RalGks(high_res=high_res)
    colours = [(0, 0, 0), (1, 1, 1), (1, 0, 0), (0, 1, 0), (0, 0, 1), (1, 1, 0), (1, 0, 1),
               (0, 1, 1), (0.5, 0.5, 0.5), (1, 0.5, 0), (0.5, 0, 1), (0, 0.5, 0.2),
               (0.3, 0.3, 0.6), (0.9, 0.7, 0.6), (0.2, 0.6, 0.9), (0.7, 0.7, 0.7)]
    g.open(colours)
    g.clear()
    s = 2 if high_res else 1
    for lt in range(1, 6):
        g.linetype(lt)
        g.colour(lt + 1)
        y = (60 + 60 * lt) * s
        g.polyline([(40 * s, y), (200 * s, y + 40 * s), (360 * s, y), (520 * s, y + 40 * s)])
    g.linetype(1)
    g.colour(7)
    star = [(600 * s + int(120 * s * math.cos(4 * math.pi * k / 5)),
             300 * s + int(120 * s * math.sin(4 * math.pi * k / 5))) for k in range(6)]
    g.polyline(star)
    long_line = [(20 * s + i * 2 * s, 20 * s + int(15 * s * math.sin(i / 5))) for i in range(300)]
    g.polyline(long_line)  # long enough to be split over several buffers
    for row in range(24):
        g.cell_row(560 * s, (30 + row) * s, [(row + col) % 16 for col in range(48)])
    g.polyline([(700 * s, 450 * s), (700 * s, 450 * s)])  # a dot
    g.message("GKS MESSAGE")
    g.request_locator(384 * s, 256 * s)
    return g.finish()
