"""Drawing a title frame (thesis 6.5): the table invisible, only the giant balls, each Phong
lit by the scene's point lights (as the renderer's balls, §6.4.1) with its letter painted on
it, turning with the ball as it rolls. Letters are the Sigma's own 5 x 7 character
generator glyphs (roms/sigma); every pixel is sampled SUB x SUB times for its coverage
(anti-aliased edges of the ball and of the letter)."""

from __future__ import annotations

from functools import lru_cache

import numpy as np

from camlab88.apps.snooker.film.titles import TitleScene
from camlab88.apps.snooker.render.gamma import encode_image
from camlab88.apps.snooker.render.materials import BALL_PHONG
from camlab88.apps.snooker.render.pinhole import Pinhole

SUB = 3
IVORY = np.array((0.78, 0.70, 0.52))
INK = np.array((0.35, 0.02, 0.02))
BACKDROP = np.array((0.0, 0.0, 0.0))
LETTER_HALF = 0.66  # the glyph's half height on the ball, in radii (seen face on)


@lru_cache(maxsize=64)
def glyph(ch: str) -> np.ndarray:
    """(7, 5) bool: the character generator's glyph without its descender rows."""
    from camlab88.roms.sigma.chargen import load_font

    return np.ascontiguousarray(load_font().glyph(ord(ch))[:7])


def render_title(scene: TitleScene, view: object, frame: int, width: int,
                 height: int) -> np.ndarray:
    """(H, W, 3) uint8: frame ``frame`` of the title."""
    pin = Pinhole.of(np.asarray(view.observer), np.asarray(view.viewpoint),
                     float(view.focal_mm), width, height)
    row = scene.index(frame)
    img = np.empty((height, width, 3))
    img[:] = BACKDROP
    xy, depth, _ = pin.project(scene.centres[row])
    for b in np.argsort(-depth):
        if scene.on_table[row, b] and b < len(scene.letters) and depth[b] > scene.table.radius:
            r_px = scene.table.radius * pin.focal_px / depth[b]
            _ball(img, pin, scene, row, int(b), xy[b], r_px)
    return encode_image(img)


def _ball(img: np.ndarray, pin: Pinhole, scene: TitleScene, row: int, b: int,
          xy: np.ndarray, r_px: float) -> None:
    h, w = img.shape[:2]
    reach = 1.3 * r_px + 2
    x0, x1 = max(int(xy[0] - reach), 0), min(int(xy[0] + reach) + 1, w)
    y0, y1 = max(int(xy[1] - reach), 0), min(int(xy[1] + reach) + 1, h)
    if x0 >= x1 or y0 >= y1:
        return
    off = (np.arange(SUB) + 0.5) / SUB
    xs = (np.arange(x0, x1)[:, None] + off).reshape(-1)
    ys = (np.arange(y0, y1)[:, None] + off).reshape(-1)
    gx, gy = np.meshgrid(xs, ys)
    colour, hit = _shade(pin, scene, row, b, gx, gy)
    ny, nx = y1 - y0, x1 - x0
    cov = hit.reshape(ny, SUB, nx, SUB).mean(axis=(1, 3))
    total = (colour * hit[..., None]).reshape(ny, SUB, nx, SUB, 3).sum(axis=(1, 3))
    mean = total / np.maximum(cov * SUB * SUB, 1)[..., None]
    patch = img[y0:y1, x0:x1]
    patch[:] = patch * (1 - cov[..., None]) + mean * cov[..., None]


def _shade(pin: Pinhole, scene: TitleScene, row: int, b: int, gx: np.ndarray,
           gy: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Phong colour at every sample's ray hit on ball b, and which samples hit it."""
    c, r = scene.centres[row, b], scene.table.radius
    d = pin.rays(gx, gy)
    d /= np.linalg.norm(d, axis=-1, keepdims=True)
    oc = pin.observer - c
    half_b = d @ oc
    disc = half_b ** 2 - (oc @ oc - r * r)
    hit = disc > 0
    t = -half_b - np.sqrt(np.where(hit, disc, 0.0))
    p = pin.observer + t[..., None] * d
    n = (p - c) / r
    albedo = _paint(scene, row, b, n)
    return _phong(scene, p, n, -d, albedo), hit & (t > 0)


def _paint(scene: TitleScene, row: int, b: int, n: np.ndarray) -> np.ndarray:
    """Ivory, with the letter in ink where the ball-frame normal falls inside its glyph."""
    m = n @ scene.orientations[row, b]  # world normal -> the ball's own frame
    centre, right, up = scene.faces[b]
    u, v, front = m @ right, m @ up, m @ centre
    g = glyph(scene.letters[b])
    gh, gw = g.shape
    col = np.floor((u / (LETTER_HALF * gw / gh) + 1) * gw / 2).astype(np.int64)
    ln = np.floor((1 - v / LETTER_HALF) * gh / 2).astype(np.int64)
    inside = (front > 0) & (col >= 0) & (col < gw) & (ln >= 0) & (ln < gh)
    ink = inside & g[np.clip(ln, 0, gh - 1), np.clip(col, 0, gw - 1)]
    return np.where(ink[..., None], INK, IVORY)


def _phong(scene: TitleScene, p: np.ndarray, n: np.ndarray, eye: np.ndarray,
           albedo: np.ndarray) -> np.ndarray:
    ph, lights = BALL_PHONG, scene.lights
    out = ph.ka * np.asarray(lights.ambient) * albedo
    for pos, colour in zip(lights.positions, lights.colours, strict=True):
        lv = pos - p
        lv /= np.linalg.norm(lv, axis=-1, keepdims=True)
        nl = np.sum(n * lv, axis=-1)
        refl = 2 * nl[..., None] * n - lv
        rv = np.maximum(np.sum(refl * eye, axis=-1), 0.0)
        out = out + (ph.kd * albedo * np.maximum(nl, 0.0)[..., None]
                     + ph.ks * (rv ** ph.n)[..., None]) * colour
    return out
