"""PGPLOT 5.2.2's real /GOC streams and /GIF pages (tests/data/sigma/pgplot/SOURCES.md):
loading, splitting into pages, and the README's recall/precision within 1 px."""

from __future__ import annotations

import gzip
import re
from pathlib import Path

import numpy as np
from PIL import Image

DATA = Path(__file__).resolve().parents[1] / "data" / "sigma" / "pgplot"
STREAMS = ("goctest", "pgdemo2", "pgdemo7", "pgdemo8", "pgdemo10", "pgdemo11", "pgdemo12",
           "pgdemo15", "pgdemo16")
INIT = b"\r\n+-*/DD000CBGAAAHE999CK1GHBH"
PAGE_START = re.compile(re.escape(INIT) + rb"\+-\*/GJDA")
GOC_PX_PER_INCH, GIF_PX_PER_INCH = 76.8, 85.0
INCH_PAGES = ("pgdemo12",)  # PGPAP sets the view surface in inches (README: Coordinates)


def stream(name: str) -> bytes:
    with gzip.open(DATA / f"{name}.goc.gz") as f:
        return f.read()


def pages(name: str) -> list[bytes]:
    """Split just before the initialisation that precedes each DA, the first page from
    byte 0 (so it keeps the driver's opening alpha erase)."""
    data = stream(name)
    cuts = [0] + [m.start() for m in PAGE_START.finditer(data)][1:]
    return [data[a:b] for a, b in zip(cuts, cuts[1:] + [len(data)])]


def gif_page(name: str, k: int) -> np.ndarray:
    """PGPLOT's own picture of page k (1-based) as a lit mask, row 0 = top."""
    with Image.open(DATA / f"{name}_{k}.png") as im:
        return np.asarray(im) != 0  # palette index 0 is the background


def _dilate(mask: np.ndarray) -> np.ndarray:
    out = mask.copy()
    h, w = mask.shape
    for dy in (-1, 0, 1):
        for dx in (-1, 0, 1):
            src = mask[max(dy, 0):h + min(dy, 0), max(dx, 0):w + min(dx, 0)]
            out[max(-dy, 0):h + min(-dy, 0), max(-dx, 0):w + min(-dx, 0)] |= src
    return out


def _hits(points_rc: np.ndarray, mask: np.ndarray) -> np.ndarray:
    r, c = points_rc[:, 0], points_rc[:, 1]
    inside = (r >= 0) & (r < mask.shape[0]) & (c >= 0) & (c < mask.shape[1])
    hit = np.zeros(len(points_rc), dtype=bool)
    hit[inside] = mask[r[inside], c[inside]]
    return hit


def recall_precision(name: str, gif: np.ndarray, lit: np.ndarray) -> tuple[float, float]:
    """README mapping: x_goc = x_gif * 768/767, y_goc = y_gif (both y up, row = 511 - y);
    PGPAP pages scale by 76.8/85 from the GIF's bottom left. Within 1 px either way."""
    gh = gif.shape[0]
    if name in INCH_PAGES:
        sx = sy = GOC_PX_PER_INCH / GIF_PX_PER_INCH
    else:
        sx, sy = 768 / 767, 1.0
    gr, gc = np.nonzero(gif)
    to_goc = np.stack([511 - np.rint((gh - 1 - gr) * sy), np.rint(gc * sx)], 1).astype(int)
    recall = _hits(to_goc, _dilate(lit)).mean()
    lr, lc = np.nonzero(lit)
    to_gif = np.stack([gh - 1 - np.rint((511 - lr) / sy), np.rint(lc / sx)], 1).astype(int)
    precision = _hits(to_gif, _dilate(gif)).mean()
    return float(recall), float(precision)
