"""The KAS plot's PDF opens in a real reader: poppler's pdftoppm renders every page, and the
rendered page shows the registration crosses and the frame's coloured strokes."""

from __future__ import annotations

import os
import shutil
import subprocess

import numpy as np
import pytest
from PIL import Image

from camlab88.apps.kas import demo, plot

DPI = 20


@pytest.fixture(scope="module")
def pages(tmp_path_factory: pytest.TempPathFactory) -> tuple[list[np.ndarray], plot.PlotSize]:
    if shutil.which("pdftoppm") is None:
        if os.environ.get("CI"):  # .ci/run installs poppler-utils: a missing reader is a CI fault
            pytest.fail("pdftoppm (Debian's poppler-utils) is missing on CI")
        pytest.skip("pdftoppm (Debian's poppler-utils) is not installed")
    tmp = tmp_path_factory.mktemp("pdf")
    seq = demo.build()
    seq.frames = seq.frames[:3]
    size = plot.PlotSize()
    target = plot.plot_sequence(seq, tmp, "pdf", size)[0]
    subprocess.run(["pdftoppm", "-r", str(DPI), "-png", str(target), str(tmp / "page")],
                   check=True, capture_output=True, timeout=60)
    images = sorted(tmp.glob("page-*.png"))
    return [np.asarray(Image.open(p).convert("RGB")).astype(int) for p in images], size


def test_every_frame_is_a_page_of_the_plot_size(pages) -> None:
    images, size = pages
    assert len(images) == 3
    w, h = size.page
    for img in images:
        assert img.shape[:2] == (round(h * DPI), round(w * DPI))


def test_registration_crosses_are_drawn_where_the_plot_puts_them(pages) -> None:
    images, size = pages
    w, h = size.page
    for img in images:
        dark = img.sum(axis=2) < 3 * 160
        for mark in plot.registration_marks(size)[:8]:  # the four crosses' strokes
            (x0, y0), (x1, y1) = mark[0], mark[-1]
            col = round((x0 + x1) / 2 * DPI)
            row = round((h - (y0 + y1) / 2) * DPI)
            assert dark[row - 1:row + 2, col - 1:col + 2].any(), (x0, y0)
        corner = dark[: round(0.3 * DPI), : round(0.3 * DPI)]
        assert not corner.any()  # the page's own corner stays blank paper


def test_each_stroke_is_inked_in_its_colour(pages) -> None:
    images, size = pages
    _, h = size.page
    frames = demo.build().frames[:3]
    for img, frame in zip(images, frames, strict=True):
        checked = 0
        for colour, run in plot.strokes(frame, size):
            rgb = np.array(plot.PAPER_RGB.get(colour, (0, 0, 0)))
            col, row = round(run[0, 0] * DPI), round((h - run[0, 1]) * DPI)
            near = img[max(row - 1, 0):row + 2, max(col - 1, 0):col + 2].reshape(-1, 3)
            # the nearest rendered pixel is nearer the pen's colour than white paper is
            gap = np.abs(near - rgb).sum(axis=1).min()
            assert gap < np.abs(255 - rgb).sum(), (colour, run[0])
            checked += 1
        assert checked > 0
