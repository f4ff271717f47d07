"""Hard copy: HP-GL pens and registration marks, SVG, a hand-written PDF; GIF/MP4/PNG."""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET

import imageio.v3 as iio
import numpy as np

from camlab88.apps.kas import plot
from camlab88.apps.kas.export import export
from camlab88.apps.kas.model import AnimSequence, Chain, Drawing
from camlab88.apps.kas.raster import render


def frame() -> Drawing:
    c = Chain(np.array([(-6, -4.375), (0, 0), (6, 0)], float), np.array([2, 2, 4]))
    return Drawing([c, Chain.from_points([(100, 100), (101, 100)], 3)])  # 2nd is off-field


def test_hpgl_pens_by_colour_scale_and_marks():
    text = plot.hpgl(frame(), 7)
    assert text.startswith("IN;\nSP1;") and text.rstrip().endswith("PU;SP0;")
    assert "LBframe 7\x03;" in text
    # default size: the field corner (-6, -4.375) is the 1" margin = 1016 plotter units
    assert "SP2;\nPU1016,1016;PD7112,5461;" in text
    assert "SP4;\nPU7112,5461;PD13208,5461;" in text
    assert "SP3;" not in text  # off the field: clipped away
    # 4 crosses (2 strokes each) + 4 corner marks
    assert len(re.findall(r"^PU\d+,\d+;PD", text.split("SP2;")[0], re.M)) == 12


def test_plot_size_given_by_animator():
    size = plot.PlotSize(6, 4.375, 0.5)
    text = plot.hpgl(frame(), 1, size)
    # half size: field corner at 0.5", centre at 0.5 + 3" = 3.5" = 3556 units
    assert "PU508,508;PD3556,2731;" in text


def test_clip_polyline_runs():
    runs = plot.clip_polyline(np.array([(-10, 0), (0, 0), (10, 0), (10, 10), (0, 1)], float),
                              (-1, -1), (1, 1))
    assert [r.tolist() for r in runs] == [[[-1, 0], [0, 0], [1, 0]]]


def test_svg_is_wellformed_with_colours():
    root = ET.fromstring(plot.svg(frame(), 3))
    ns = "{http://www.w3.org/2000/svg}"
    lines = root.findall(f".//{ns}polyline")
    strokes = [pl.get("stroke") for pl in lines if pl.get("stroke")]
    assert strokes == ["#ff0000", "#0060ff"]
    assert root.get("width") == "14in" and root.get("height") == "10.75in"


def test_pdf_structure_and_xref(tmp_path):
    seq = AnimSequence([frame(), frame()])
    out = plot.plot_sequence(seq, tmp_path, "pdf")[0]
    data = out.read_bytes()
    assert data.startswith(b"%PDF-1.4") and data.rstrip().endswith(b"%%EOF")
    start = int(data.rsplit(b"startxref", 1)[1].split()[0])
    assert data[start:start + 4] == b"xref"
    count = int(data[start:].split(b"\n")[1].split()[1])
    offsets = [int(line[:10]) for line in data[start:].split(b"\n")[3:2 + count]]
    for k, off in enumerate(offsets, start=1):
        assert data[off:].startswith(f"{k} 0 obj".encode())
    assert data.count(b"/Type /Page ") == 2
    for m in re.finditer(rb"/Length (\d+) >>\nstream\n", data):
        end = m.end() + int(m.group(1))
        assert data[end:end + 10] == b"\nendstream"


def test_plot_files_written(tmp_path):
    seq = AnimSequence([frame()] * 3)
    calls = []
    files = plot.plot_sequence(seq, tmp_path, "hpgl", progress=lambda i, n: calls.append(i))
    assert [f.name for f in files] == ["frame_0001.hpgl", "frame_0002.hpgl", "frame_0003.hpgl"]
    assert calls == [1, 2, 3]


def test_raster_draws_field_colours():
    img = render(frame(), 120)
    assert img.shape == (88, 120, 3)
    assert tuple(img[43, 90]) == (0, 96, 255)  # the blue segment along y = 0, row 43.75
    assert tuple(img[10, 10]) == (0, 0, 0)


def test_export_gif_png_mp4(tmp_path):
    seq = AnimSequence([Drawing([Chain.from_points([(i - 3, 0), (i - 2, 1)], 2)])
                        for i in range(6)])
    progress = []
    gif = export(seq, tmp_path / "a.gif", 96, progress=lambda i, n: progress.append((i, n)))
    assert progress[-1] == (6, 6)
    frames = iio.imread(gif, index=None)
    assert frames.shape[0] == 6
    assert not np.array_equal(frames[0], frames[5])
    export(seq, tmp_path / "p.png", 96)
    assert len(list(tmp_path.glob("p_*.png"))) == 6
    mp4 = export(seq, tmp_path / "m.mp4", 96)
    assert mp4.stat().st_size > 0
    assert not list(tmp_path.glob(".*partial*"))
