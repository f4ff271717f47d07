"""The 1984 host program (thesis 6.4.1): the frame computed on the host, sent to a Sigma
T5688 over the 9600-baud line in Sigma orders only.

Per frame, in the painter's order (painter.py): the background as one solid block; each
polygon outlined in its colour and flood-filled by the terminal's firmware (``KK`` with the
polygon's colour as the boundary), then its anti-aliased edge pixels (Pitteway & Watkinson
coverage, blended with what the host knows is underneath) sent as pixels; the ball shadows
and the balls sent as pixel runs. The LUT holds a 256-colour palette, gamma-corrected.

``mode="period"`` outlines each polygon with the firmware's line drawer (``GJ`` between the
rounded vertices). The firmware is not Bresenham's algorithm, so its steps fall where the
anti-aliasing did not expect them and "the colour inside a polygon sometimes appears on the
outside the polygon's anti-aliased boundary" — the defect the thesis reports. The host does
not know; it keeps the picture it *meant* (``SigmaFrame.intended``), and comparing that with
the terminal's screen counts the leaking pixels.

``mode="fixed"`` is the cure §6.4.1 proposes: "using software to draw lines for the polygon
boundaries using Bresenham's algorithm" — the host sends the outline's pixels itself (as
horizontal runs, which any line drawer draws exactly), so the fill stops exactly where the
anti-aliased boundary expects it: no leaks.

``mode="adapted"`` is the thesis's other cure: "adapting the Pitteway and Watkinson
algorithm to perform anti-aliasing along the lines produced by the Sigma". The outlines are
the firmware's vectors again (as cheap on the line as ``period``), but the host knows where
the firmware puts their pixels (its DDA, docs/fidelity/sigma.md) and anti-aliases those:
no leaks either.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from camlab88.apps.snooker.render import host_kernels as HK
from camlab88.apps.snooker.render import kernels as K
from camlab88.apps.snooker.render.balls import ball_params
from camlab88.apps.snooker.render.frame import (
    FrameGeometry,
    camera_params,
    clip_project,
    frame_geometry,
)
from camlab88.apps.snooker.render.materials import BACKGROUND
from camlab88.apps.snooker.render.modes import SIGMA_MODES as MODES
from camlab88.apps.snooker.render.outline import (
    clip_to_screen,
    coverage,
    firmware_outline,
    outline_pixels,
    pixel_vertices,
    signed_area,
)
from camlab88.apps.snooker.render.painter import BallItem, PolygonItem, ShadowItem
from camlab88.apps.snooker.render.palette import Palette
from camlab88.apps.snooker.render.runs import RunWriter
from camlab88.apps.snooker.render.scene import Scene
from camlab88.apps.snooker.render.shading import lights_array
from camlab88.apps.snooker.render.shadow_pass import shadow_occlusion
from camlab88.apps.snooker.render.specks import speck_directions
from camlab88.protocols.sigma import Encoder

SCREEN_W, SCREEN_H = 768, 512  # the T5688's screen: the drawing area's first quadrant


@dataclass
class SigmaFrame:
    data: bytes
    intended: np.ndarray  # (512, 768) uint8 indices the host meant, row 0 = top
    bytes_by_kind: dict[str, int] = field(default_factory=dict)
    flat_colours: frozenset[int] = frozenset()  # the polygons' fill colours this frame


class SigmaHost:
    """Computes frames and the Sigma orders that draw them (no device: bytes out only)."""

    def __init__(self, scene: Scene, palette: Palette, mode: str = "period",
                 specks: bool = True) -> None:
        if mode not in MODES:
            raise ValueError(f"unknown Sigma mode {mode!r}; choose from {', '.join(MODES)}")
        self.scene, self.palette, self.mode, self.specks = scene, palette, mode, specks
        self.enc = Encoder(high_res=True)
        self._stack = np.empty(2 * SCREEN_W * SCREEN_H + 16, dtype=np.int64)

    def setup(self) -> bytes:
        """Graphics mode, reset, all 8 planes, quadrant 0 on screen, the palette in the LUT."""
        e = self.enc
        return e.take_over() + e.full_colour_screen() + e.lut24_table(self.palette.lut.tolist())

    def frame(self, view: object, frame: int | None = None) -> SigmaFrame:
        g = frame_geometry(self.scene, np.asarray(view.observer), np.asarray(view.viewpoint),
                           float(view.focal_mm), int(view.frame if frame is None else frame),
                           SCREEN_W, SCREEN_H)
        return _FrameJob(self, g).run()


class _FrameJob:
    """One frame: the host's picture (linear light and LUT indices) and the orders."""

    def __init__(self, host: SigmaHost, g: FrameGeometry) -> None:
        self.host, self.g = host, g
        self.lin = np.empty((SCREEN_H, SCREEN_W, 3))
        self.lin[:] = BACKGROUND
        self.idx = np.full((SCREEN_H, SCREEN_W), host.palette.index(BACKGROUND), np.uint8)
        self.runs = RunWriter(host.enc, SCREEN_H)
        self.out = bytearray()
        self.kinds: dict[str, int] = {}
        self.flat: set[int] = set()

    def _emit(self, kind: str, data: bytes) -> None:
        self.out += data
        self.kinds[kind] = self.kinds.get(kind, 0) + len(data)

    def run(self) -> SigmaFrame:
        e = self.host.enc
        self._emit("background", self.runs.set_colour(int(self.idx[0, 0]))
                   + e.move(0, 0) + e.block(SCREEN_W - 1, SCREEN_H - 1))
        for item in self.g.items:
            if isinstance(item, PolygonItem):
                self.polygon(item)
            elif isinstance(item, ShadowItem):
                self.shadows(item)
            elif isinstance(item, BallItem):
                self.ball(item)
        return SigmaFrame(bytes(self.out), self.idx.copy(), dict(self.kinds),
                          frozenset(self.flat))

    # -------------------------------------------------------------- polygons
    def polygon(self, item: PolygonItem) -> None:
        xy = clip_project(self.g.pin, item.face.vertices)
        if xy is None:
            return
        v = pixel_vertices(clip_to_screen(xy, SCREEN_W, SCREEN_H))
        if len(v) < 3 or abs(signed_area(v)) < 0.5:
            return  # thinner than a pixel once its corners are whole pixels: not drawn
        c = int(self.host.palette.index(item.colour))
        self.flat.add(c)
        ring = firmware_outline(v, SCREEN_H) if self.host.mode == "adapted" else \
            outline_pixels(v)
        xs, rows = ring[:, 0], ring[:, 1]
        under_lin, under_idx = self.lin[rows, xs].copy(), self.idx[rows, xs].copy()
        self.idx[rows, xs] = c
        self._emit("outline", self._outline(v, ring, c))
        self._fill(v, c, item.colour)
        cov = coverage(v, ring)[:, None]
        aa_lin = cov * item.colour + (1.0 - cov) * under_lin
        aa_idx = self.host.palette.index(aa_lin)
        none = cov[:, 0] <= 0.0
        aa_idx[none], aa_lin[none] = under_idx[none], under_lin[none]
        self.lin[rows, xs], self.idx[rows, xs] = aa_lin, aa_idx
        self._emit("edges", self.runs.pixels(rows, xs, aa_idx))

    def _outline(self, v: np.ndarray, ring: np.ndarray, c: int) -> bytes:
        if self.host.mode == "fixed":  # Bresenham's pixels, drawn by the host (6.4.1's cure)
            return self.runs.pixels(ring[:, 1], ring[:, 0], np.full(len(ring), c))
        e = self.host.enc
        dev = [(int(x), SCREEN_H - 1 - int(y)) for x, y in v]
        return self.runs.set_colour(c) + e.polyline([*dev, dev[0]])

    def _fill(self, v: np.ndarray, c: int, colour: np.ndarray) -> None:
        found = interior_seed(v, self.idx, c)
        if found is None:
            return
        (sx, sy), safe = found
        before = self.idx.copy()
        HK.fill4(self.idx, np.int64(sx), np.int64(sy), np.uint8(c), self.host._stack)
        filled = self.idx != before
        self.lin[filled] = colour
        if safe:
            e = self.host.enc
            self._emit("fill", self.runs.set_colour(c) + e.move(sx, SCREEN_H - 1 - sy)
                       + e.fill8(c))
        else:  # too thin to seed the filler where no outline can pass: send the pixels
            rows, xs = np.nonzero(filled)
            self._emit("fill", self.runs.pixels(rows, xs, np.full(len(rows), c)))

    # -------------------------------------------------------------- shadows and balls
    def shadows(self, item: ShadowItem) -> None:
        occ, x0, y0 = shadow_occlusion(self.g, item, SCREEN_H, SCREEN_W)
        if occ.size == 0:
            return
        new = self.lin[y0:y0 + occ.shape[1], x0:x0 + occ.shape[2]].copy()  # C order
        K.dim(new, occ, np.ascontiguousarray(item.removed), np.int64(0), np.int64(0))
        self._send_changed("shadows", new, y0, x0)

    def ball(self, item: BallItem) -> None:
        g, scene = self.g, self.host.scene
        b = item.ball
        r = float(g.ball_r_px[b])
        if g.ball_depth[b] <= scene.table.radius + 1e-3:
            return
        cx, cy = g.ball_xy[b]
        x0, y0 = max(int(np.floor(cx - r)) - 2, 0), max(int(np.floor(cy - r)) - 2, 0)
        x1 = min(int(np.floor(cx + r)) + 3, SCREEN_W)
        y1 = min(int(np.floor(cy + r)) + 3, SCREEN_H)
        if x0 >= x1 or y0 >= y1:
            return
        sub = self.lin[y0:y1, x0:x1].copy()  # C order, never a view of the picture
        params = ball_params(np.array([cx - x0, cy - y0]), r, item.centre, scene.table.radius,
                             item.albedo, scene.orientations[g.row, b], scene.lights,
                             self.host.specks)
        K.ball(sub, camera_params(g.pin), params, lights_array(scene.lights),
               speck_directions(b))
        self._send_changed("balls", sub, y0, x0)

    def _send_changed(self, kind: str, new: np.ndarray, y0: int, x0: int) -> None:
        h, w = new.shape[:2]
        old = self.lin[y0:y0 + h, x0:x0 + w]
        moved = np.any(new != old, axis=2)
        if not moved.any():
            return
        rr, cc = np.nonzero(moved)
        idx = self.host.palette.index(new[rr, cc])
        rows, xs = rr + y0, cc + x0
        self.lin[rows, xs] = new[rr, cc]
        send = idx != self.idx[rows, xs]
        self.idx[rows, xs] = idx
        self._emit(kind, self.runs.pixels(rows[send], xs[send], idx[send]))


def interior_seed(v: np.ndarray, idx: np.ndarray,
                  c: int) -> tuple[tuple[int, int], bool] | None:
    """The pixel deepest inside the polygon (integer vertices v, centres at +0.5) whose index
    is not yet ``c``, and whether it is safe for the terminal's filler: 1.5 pixels from every
    edge, so the firmware's outline, which may step a pixel later than Bresenham's, cannot
    pass through it. None if the polygon has no pixel inside its outline.
    (Margins are measured from pixel corners' lattice: centres are at v + 0.5 and so are
    the vertices, so the offset cancels.)"""
    lo, hi = v.min(axis=0), v.max(axis=0)
    span = hi - lo + 1
    step = max(1, int(np.ceil(np.sqrt(span[0] * span[1] / 40000.0))))
    gx, gy = np.meshgrid(np.arange(lo[0], hi[0] + 1, step), np.arange(lo[1], hi[1] + 1, step))
    px, py = gx.ravel(), gy.ravel()
    margin = np.full(px.shape, np.inf)
    a = v.astype(np.float64)
    b = np.roll(a, -1, axis=0)
    area = float(np.sum(a[:, 0] * b[:, 1] - b[:, 0] * a[:, 1]))
    if abs(area) < 1e-9:
        return None
    s = 1.0 if area > 0 else -1.0
    for (ax, ay), (bx, by) in zip(a, b):
        n = np.hypot(bx - ax, by - ay)
        if n == 0:
            continue
        d = s * ((bx - ax) * (py - ay) - (by - ay) * (px - ax)) / n
        margin = np.minimum(margin, d)
    free = idx[py, px] != c
    for need in (1.5, 0.5):  # a thin polygon: any pixel off its outline will do
        ok = (margin >= need) & free
        if ok.any():
            k = int(np.argmax(np.where(ok, margin, -np.inf)))
            return (int(px[k]), int(py[k])), need > 1.0
    return None
