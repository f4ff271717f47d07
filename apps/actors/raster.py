"""The actors renderer's per-pixel loops (numba): a z-buffer triangle rasteriser, shadow maps
from each point light, and Phong shading of every pixel with the snooker renderer's lighting
model (thesis 6.4.1: point lights, ambient + diffuse + specular, no attenuation).

The snooker renderer draws balls and flat polygons in painter's order; turned and extruded
solids need hidden surfaces removed per pixel, hence a z-buffer here. Every kernel is called
with one set of argument types (float64 / int64 arrays, C order; docs/development.md
"numba's cache"). Loops run serially in a fixed order, so a frame is bit-identical wherever
it is rendered.

Camera parameters travel as snooker's ``cam`` array (frame.camera_params): observer (3),
right (3), up (3), forward (3), focal_px, width, height. A light's shadow map looks straight
down from the light: texel (u, v) = M/2 + f * (X - lx, Y - ly) / (lz - Z); the map stores
lz - Z of the nearest surface.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from camlab88.base.kernel_notice import announce_compiles

announce_compiles("actors renderer", 6.0, __name__)  # cold compile, measured on the 2-core box

NEAR = 0.01  # cell units: a triangle with a corner nearer the eye than this is not drawn
SHADOW_BIAS = 0.01


@njit(cache=True, nogil=True)
def rasterise(sx, sy, d, zbuf, ids, b1, b2):  # numba kernel
    """Triangles (n, 3) screen x, y (pixels, y down) and depth d -> nearest per pixel centre:
    zbuf (depth), ids (triangle), b1, b2 (perspective-correct weights of corners 1, 2); with
    ids of no rows (0, 0), only the depths."""
    h = zbuf.shape[0]
    w = zbuf.shape[1]
    full = ids.shape[0] > 0
    for t in range(sx.shape[0]):
        d0 = d[t, 0]
        d1 = d[t, 1]
        d2 = d[t, 2]
        if d0 < NEAR or d1 < NEAR or d2 < NEAR:
            continue
        x0 = sx[t, 0]
        y0 = sy[t, 0]
        x1 = sx[t, 1]
        y1 = sy[t, 1]
        x2 = sx[t, 2]
        y2 = sy[t, 2]
        area = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0)
        if abs(area) < 1e-12:
            continue
        i0 = max(int(math.ceil(min(x0, min(x1, x2)) - 0.5)), 0)
        i1 = min(int(math.floor(max(x0, max(x1, x2)) - 0.5)), w - 1)
        j0 = max(int(math.ceil(min(y0, min(y1, y2)) - 0.5)), 0)
        j1 = min(int(math.floor(max(y0, max(y1, y2)) - 0.5)), h - 1)
        inv = 1.0 / area
        for j in range(j0, j1 + 1):
            yc = j + 0.5
            for i in range(i0, i1 + 1):
                xc = i + 0.5
                e1 = ((xc - x0) * (y2 - y0) - (x2 - x0) * (yc - y0)) * inv
                e2 = ((x1 - x0) * (yc - y0) - (xc - x0) * (y1 - y0)) * inv
                e0 = 1.0 - e1 - e2
                if e0 < -1e-9 or e1 < -1e-9 or e2 < -1e-9:
                    continue
                q = e0 / d0 + e1 / d1 + e2 / d2
                z = 1.0 / q
                if z < zbuf[j, i]:
                    zbuf[j, i] = z
                    if full:
                        ids[j, i] = t
                        b1[j, i] = e1 / d1 * z
                        b2[j, i] = e2 / d2 * z


@njit(cache=True, nogil=True)
def shadow_depth(verts, light, smap):  # numba kernel
    """Rasterise world triangles (n, 3, 3) into the shadow map of the light
    (lx, ly, lz, f): the nearest lz - Z per texel (``rasterise`` with the light's view)."""
    m = smap.shape[0]
    n = verts.shape[0]
    u = np.zeros((n, 3))
    v = np.zeros((n, 3))
    d = np.empty((n, 3))
    for t in range(n):
        for k in range(3):
            d[t, k] = light[2] - verts[t, k, 2]
            if d[t, k] >= NEAR:  # else rasterise skips the triangle
                u[t, k] = m / 2.0 + light[3] * (verts[t, k, 0] - light[0]) / d[t, k]
                v[t, k] = m / 2.0 + light[3] * (verts[t, k, 1] - light[1]) / d[t, k]
    rasterise(u, v, d, smap, np.empty((0, 0), np.int64), np.empty((0, 0)), np.empty((0, 0)))


@njit(cache=True, nogil=True)
def lit_fraction(smap, light, px, py, pz, nx, ny, nz):  # numba kernel
    """How much of the light reaches the point (0..1): 3 x 3 percentage-closer filtering of
    the shadow map, the point pushed 1.5 texels along its normal against self-shadowing."""
    m = smap.shape[0]
    lz = light[2]
    f = light[3]
    d = lz - pz
    if d <= NEAR:
        return 1.0
    push = 1.5 * d / f
    qx = px + nx * push
    qy = py + ny * push
    qz = pz + nz * push
    d = lz - qz
    if d <= NEAR:
        return 1.0
    u = m / 2.0 + f * (qx - light[0]) / d
    v = m / 2.0 + f * (qy - light[1]) / d
    iu = int(math.floor(u))
    iv = int(math.floor(v))
    dark = 0
    for dv in range(-1, 2):
        for du in range(-1, 2):
            a = iu + du
            b = iv + dv
            if 0 <= a < m and 0 <= b < m and smap[b, a] < d - SHADOW_BIAS:
                dark += 1
    return 1.0 - dark / 9.0


@njit(cache=True, nogil=True)
def _phong(out, albedo, mat, px, py, pz, nx, ny, nz, vx, vy, vz, lights, smaps, lp,
           ambient):  # numba kernel
    """out (3,) = ka A c + sum over lights of vis (kd c N.L + ks (R.V)^n) I_l."""
    for c in range(3):
        out[c] = mat[0] * ambient[c] * albedo[c]
    for k in range(lights.shape[0]):
        lx = lights[k, 0] - px
        ly = lights[k, 1] - py
        lz = lights[k, 2] - pz
        ln = math.sqrt(lx * lx + ly * ly + lz * lz)
        if ln <= 0.0:
            continue
        lx /= ln
        ly /= ln
        lz /= ln
        ndl = nx * lx + ny * ly + nz * lz
        if ndl <= 0.0:
            continue
        vis = lit_fraction(smaps[k], lp[k], px, py, pz, nx, ny, nz)
        if vis <= 0.0:
            continue
        rx = 2.0 * ndl * nx - lx
        ry = 2.0 * ndl * ny - ly
        rz = 2.0 * ndl * nz - lz
        rdv = max(rx * vx + ry * vy + rz * vz, 0.0)
        spec = mat[2] * rdv ** mat[3] if rdv > 0.0 else 0.0
        for c in range(3):
            out[c] += vis * (mat[1] * albedo[c] * ndl + spec) * lights[k, 3 + c]


@njit(cache=True, nogil=True)
def _ray(cam, w, h, j, i):  # numba kernel
    """The (unnormalised, forward component 1) ray through sample (j, i)'s centre."""
    fpx = cam[12]
    a = (i + 0.5 - w / 2.0) / fpx
    b = (h / 2.0 - (j + 0.5)) / fpx
    return (cam[9] + a * cam[3] + b * cam[6], cam[10] + a * cam[4] + b * cam[7],
            cam[11] + a * cam[5] + b * cam[8])


@njit(cache=True, nogil=True)
def sample_key(zbuf, ids, cam, floor, th, tw, j, i):  # numba kernel
    """What sample (j, i) sees: triangle t >= 0, -2 - (row * tw + col) for a cell of the
    board, -1 for the room. Samples of one pixel with one key shade alike."""
    h = zbuf.shape[0]
    w = zbuf.shape[1]
    rx, ry, rz = _ray(cam, w, h, j, i)
    zf = math.inf
    if rz < 0.0:
        zf = -cam[2] / rz
    t = ids[j, i]
    if t >= 0 and zbuf[j, i] <= zf:
        return t
    if zf < math.inf:
        col = int(math.floor(cam[0] + zf * rx)) - int(floor[0])
        row = int(math.floor(-(cam[1] + zf * ry))) - int(floor[1])
        if 0 <= col < tw and 0 <= row < th:
            return -2 - (row * tw + col)
    return -1


@njit(cache=True, nogil=True)
def _shade_sample(out, j, i, key, zbuf, b1, b2, cam, normals, tri_mat, albedo, mats, lights,
                  ambient, smaps, lp, tiles, fmat, background):  # numba kernel
    h = zbuf.shape[0]
    w = zbuf.shape[1]
    rx, ry, rz = _ray(cam, w, h, j, i)
    rn = math.sqrt(rx * rx + ry * ry + rz * rz)
    vx = -rx / rn
    vy = -ry / rn
    vz = -rz / rn
    if key >= 0:
        t = key
        z = zbuf[j, i]
        w1 = b1[j, i]
        w2 = b2[j, i]
        w0 = 1.0 - w1 - w2
        nx = w0 * normals[t, 0, 0] + w1 * normals[t, 1, 0] + w2 * normals[t, 2, 0]
        ny = w0 * normals[t, 0, 1] + w1 * normals[t, 1, 1] + w2 * normals[t, 2, 1]
        nz = w0 * normals[t, 0, 2] + w1 * normals[t, 1, 2] + w2 * normals[t, 2, 2]
        nn = math.sqrt(nx * nx + ny * ny + nz * nz)
        if nn <= 0.0:
            nn = 1.0
        nx /= nn
        ny /= nn
        nz /= nn
        if nx * vx + ny * vy + nz * vz < 0.0:  # seen from inside: light the side seen
            nx = -nx
            ny = -ny
            nz = -nz
        k = tri_mat[t]
        _phong(out, albedo[k], mats[k], cam[0] + z * rx, cam[1] + z * ry, cam[2] + z * rz,
               nx, ny, nz, vx, vy, vz, lights, smaps, lp, ambient)
    elif key <= -2:
        cell = -2 - key
        tw = tiles.shape[1]
        zf = -cam[2] / rz
        _phong(out, tiles[cell // tw, cell % tw], fmat, cam[0] + zf * rx, cam[1] + zf * ry,
               0.0, 0.0, 0.0, 1.0, vx, vy, vz, lights, smaps, lp, ambient)
    else:
        for c in range(3):
            out[c] = background[c]


@njit(cache=True, nogil=True)
def shade(img, ss, zbuf, ids, b1, b2, cam, normals, tri_mat, albedo, mats, lights, ambient,
          smaps, lp, tiles, floor, background):  # numba kernel
    """Every pixel of ``img`` (H, W, 3) from its ss x ss samples (the buffers are at sample
    resolution): the nearest of an actor's triangle (normal interpolated) and the board
    z = 0 (albedo ``tiles[row - floor[1], col - floor[0]]`` within its cells), Phong-shaded,
    else the room. Where every sample of a pixel sees the same triangle or the same board
    cell, one sample (the one right and below the centre) is shaded for all (adaptive
    anti-aliasing: edges get the mean of all their samples). floor = (col0, row0, ka kd ks n).
    """
    hh = img.shape[0]
    ww = img.shape[1]
    out = albedo[0].copy()
    acc = albedo[0].copy()
    fmat = floor[2:6].copy()
    th = tiles.shape[0]
    tw = tiles.shape[1]
    n = ss * ss
    keys = np.empty(n, dtype=np.int64)
    for jj in range(hh):
        for ii in range(ww):
            same = True
            for s in range(n):
                keys[s] = sample_key(zbuf, ids, cam, floor, th, tw, jj * ss + s // ss,
                                     ii * ss + s % ss)
                if keys[s] != keys[0]:
                    same = False
            if same:
                mid = (ss // 2) * ss + ss // 2
                _shade_sample(out, jj * ss + ss // 2, ii * ss + ss // 2, keys[mid], zbuf, b1,
                              b2, cam, normals, tri_mat, albedo, mats, lights, ambient, smaps,
                              lp, tiles, fmat, background)
                for c in range(3):
                    img[jj, ii, c] = out[c]
                continue
            for c in range(3):
                acc[c] = 0.0
            for s in range(n):
                _shade_sample(out, jj * ss + s // ss, ii * ss + s % ss, keys[s], zbuf, b1, b2,
                              cam, normals, tri_mat, albedo, mats, lights, ambient, smaps, lp,
                              tiles, fmat, background)
                for c in range(3):
                    acc[c] += out[c]
            for c in range(3):
                img[jj, ii, c] = acc[c] / n
