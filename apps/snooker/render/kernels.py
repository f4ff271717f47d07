"""The truecolour renderer's per-pixel loops, compiled with numba (measured in
docs/perf/render.md: 22 balls shaded in numpy take about five times what the compiled
ball kernel takes for shading, specks, coverage and blending together). Every kernel is
called with one set of argument types only (float64 arrays, C order, int64 offsets;
docs/development.md "numba's cache").

Pinhole parameters travel as one float64 array ``cam``: observer (3), right (3), up (3),
forward (3), focal_px, width, height.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit


@njit(cache=True, nogil=True)
def _orientation(verts):  # numba kernel
    """+1 for an anticlockwise polygon (k, 2), -1 clockwise, 0 degenerate (no area)."""
    k = verts.shape[0]
    area = 0.0
    for e in range(k):
        f = (e + 1) % k
        area += verts[e, 0] * verts[f, 1] - verts[f, 0] * verts[e, 1]
    if abs(area) < 1e-12:
        return 0.0
    return 1.0 if area > 0 else -1.0


@njit(cache=True, nogil=True)
def _edge(verts, e):  # numba kernel
    """Edge ``e`` of a polygon (k, 2): its first corner and the step to the next one."""
    f = (e + 1) % verts.shape[0]
    ax, ay = verts[e, 0], verts[e, 1]
    return ax, ay, verts[f, 0] - ax, verts[f, 1] - ay


@njit(cache=True, nogil=True)
def polygon(img, verts, colour):  # numba kernel
    """Blend a convex polygon (k, 2 screen pixels) of one colour over ``img`` (H, W, C) by
    its coverage of each pixel, Pitteway & Watkinson's area rule: along an edge whose x
    extent is the larger, a pixel's share of the area below it is the edge's height above
    the pixel's bottom at the pixel centre (exact while the edge crosses the pixel's
    sides); across a y-major edge, the same sideways. Edges combine by summing what each
    excludes (exact unless two edges cut off the same part of a pixel). Returns pixels touched.
    """
    h = img.shape[0]
    w = img.shape[1]
    orient = _orientation(verts)
    if orient == 0.0:
        return 0
    ymin = verts[:, 1].min()
    ymax = verts[:, 1].max()
    j0 = max(int(math.floor(ymin)) - 1, 0)
    j1 = min(int(math.floor(ymax)) + 1, h - 1)
    touched = 0
    for j in range(j0, j1 + 1):
        yc = j + 0.5
        i0, i1 = row_range(verts, j, w)
        f0, f1 = full_span(verts, orient, yc)
        for i in range(i0, i1 + 1):
            xc = i + 0.5
            if f0 <= xc <= f1:  # inside every edge by half a pixel or more: covered
                for c in range(img.shape[2]):
                    img[j, i, c] = colour[c]
                touched += 1
                continue
            cov = coverage_at(verts, orient, xc, yc)
            if cov <= 0.0:
                continue
            touched += 1
            for c in range(img.shape[2]):
                img[j, i, c] = cov * colour[c] + (1.0 - cov) * img[j, i, c]
    return touched


@njit(cache=True, nogil=True)
def row_range(verts, j, w):  # numba kernel
    """(i0, i1): the pixels of row j the polygon can touch (its x extent over the band of
    rows j - 1 .. j + 2, a pixel more each side), clipped to 0..w-1; i0 > i1 if none."""
    k = verts.shape[0]
    lo = 1e300
    hi = -1e300
    for e in range(k):
        f = (e + 1) % k
        ax, ay, bx, by = verts[e, 0], verts[e, 1], verts[f, 0], verts[f, 1]
        ya = max(min(ay, by), j - 1.0)
        yb = min(max(ay, by), j + 2.0)
        if ya > yb:
            continue
        if by == ay:
            xa, xb = ax, bx
        else:
            xa = ax + (ya - ay) * (bx - ax) / (by - ay)
            xb = ax + (yb - ay) * (bx - ax) / (by - ay)
        lo = min(lo, xa, xb)
        hi = max(hi, xa, xb)
    if lo > hi:
        return 1, 0
    return max(int(math.floor(lo)) - 1, 0), min(int(math.floor(hi)) + 1, w - 1)


@njit(cache=True, nogil=True)
def full_span(verts, orient, yc):  # numba kernel
    """(x0, x1): the pixel centres on row centre yc that every edge covers wholly. Along a
    row each edge's 0.5 + d is linear in x, so each edge bounds the run on one side."""
    k = verts.shape[0]
    x0 = -1e300
    x1 = 1e300
    for e in range(k):
        ax, ay, dx, dy = _edge(verts, e)
        if dx == 0.0 and dy == 0.0:
            continue
        # 0.5 + d = alpha + beta * x (as in coverage_at)
        if abs(dx) >= abs(dy):
            sgn = (1.0 if dx > 0 else -1.0) * orient
            beta = -dy / dx * sgn
            alpha = 0.5 + (yc - ay + ax * dy / dx) * sgn
        else:
            sgn = (1.0 if dy > 0 else -1.0) * orient
            beta = -sgn
            alpha = 0.5 + (ax + (yc - ay) * dx / dy) * sgn
        if beta > 0.0:
            x0 = max(x0, (1.0 - alpha) / beta)
        elif beta < 0.0:
            x1 = min(x1, (1.0 - alpha) / beta)
        elif alpha < 1.0:
            return 1.0, 0.0
    return x0 + 1e-9, x1 - 1e-9


@njit(cache=True, nogil=True)
def coverage_at(verts, orient, xc, yc):  # numba kernel
    """Coverage (0..1) of the pixel centred at (xc, yc) by the convex polygon (see polygon)."""
    k = verts.shape[0]
    excl = 0.0
    for e in range(k):
        ax, ay, dx, dy = _edge(verts, e)
        if dx == 0.0 and dy == 0.0:
            continue
        if abs(dx) >= abs(dy):
            d = (yc - (ay + (xc - ax) * dy / dx)) * (1.0 if dx > 0 else -1.0) * orient
        else:
            d = -(xc - (ax + (yc - ay) * dx / dy)) * (1.0 if dy > 0 else -1.0) * orient
        c = 0.5 + d
        if c < 1.0:
            excl += 1.0 - c if c > 0.0 else 1.0
            if excl >= 1.0:
                return 0.0
    return 1.0 - excl


@njit(cache=True, nogil=True)
def _ground(cam, x, y):  # numba kernel
    """Where the ray through screen (x, y) meets z = 0: (gx, gy, hit)."""
    f = cam[12]
    a = (x - cam[13] / 2.0) / f
    b = (cam[14] / 2.0 - y) / f
    dx = cam[9] + a * cam[3] + b * cam[6]
    dy = cam[10] + a * cam[4] + b * cam[7]
    dz = cam[11] + a * cam[5] + b * cam[8]
    if dz >= -1e-12:
        return 0.0, 0.0, False
    t = -cam[2] / dz
    if t <= 0.0:
        return 0.0, 0.0, False
    return cam[0] + t * dx, cam[1] + t * dy, True


@njit(cache=True, nogil=True)
def _ellipse_q(e, gx, gy):  # numba kernel
    du = (gx - e[0]) * e[2] + (gy - e[1]) * e[3]
    dv = -(gx - e[0]) * e[3] + (gy - e[1]) * e[2]
    return (du / e[4]) ** 2 + (dv / e[5]) ** 2


@njit(cache=True, nogil=True)
def shadows(occ, cam, ellipses, boxes, hl, hw, x0, y0):  # numba kernel
    """Ball shadows on the baize: for each ellipse row (cx, cy, ux, uy, a, b, light) in
    ground metres and its screen box (i0, j0, i1, j1), OR its coverage c into occ[light]
    (occ = c + (1 - c) * occ). Coverage from the ellipse's implicit function over its
    screen-space gradient (one pixel either way), clipped to the playing area |x| <= hl,
    |y| <= hw. ``occ`` covers the screen from pixel (x0, y0). Returns pixels touched."""
    touched = 0
    for m in range(ellipses.shape[0]):
        e = ellipses[m]
        li = int(e[6])
        for j in range(int(boxes[m, 1]), int(boxes[m, 3]) + 1):
            for i in range(int(boxes[m, 0]), int(boxes[m, 2]) + 1):
                x = i + 0.5
                y = j + 0.5
                gx, gy, hit = _ground(cam, x, y)
                if not hit or abs(gx) > hl or abs(gy) > hw:
                    continue
                q = _ellipse_q(e, gx, gy)
                if q > 4.0:
                    continue
                gx1, gy1, h1 = _ground(cam, x + 1.0, y)
                gx2, gy2, h2 = _ground(cam, x, y + 1.0)
                if not (h1 and h2):
                    continue
                qx = _ellipse_q(e, gx1, gy1) - q
                qy = _ellipse_q(e, gx2, gy2) - q
                g = math.sqrt(qx * qx + qy * qy)
                if g <= 0.0:
                    continue
                cov = 0.5 - (q - 1.0) / g
                if cov <= 0.0:
                    continue
                if cov > 1.0:
                    cov = 1.0
                occ[li, j - y0, i - x0, 0] = cov + (1.0 - cov) * occ[li, j - y0, i - x0, 0]
                touched += 1
    return touched


# layout of a ball's parameter row (see ball_params in balls.py)
B_CX, B_CY, B_RPX, B_C, B_R, B_ALBEDO, B_SPECK, B_M, B_AMB = 0, 1, 2, 3, 6, 7, 10, 13, 22
B_KA, B_KD, B_KS, B_N, B_SPECK_COS, B_SPECK_MIX, B_LEN = 25, 26, 27, 28, 29, 30, 31


@njit(cache=True, nogil=True)
def ball(img, cam, b, lights, specks):  # numba kernel
    """Blend one Phong-lit ball over ``img`` by its coverage of each pixel (thesis 6.4.1).

    The disc is the ball's radius projected at its centre's depth (the visualiser's disc);
    a pixel's coverage is r' + 1/2 - (distance of its centre from the disc's centre),
    clamped (the disc's area within the pixel to first order), r' = sqrt(r^2 - 1/12) so the
    coverages sum to the disc's area. The normal comes from the
    sphere itself: the pixel's offset in the disc gives its right and up components, the
    rest points back at the observer; outside the disc (edge pixels) the limb normal.
    The light and eye directions are computed per pixel from the surface point (point
    lights, none at infinity). Dust specks (unit vectors in the ball's own frame, turned to
    the world by its orientation M) tint the albedo. Returns pixels touched.
    """
    h = img.shape[0]
    w = img.shape[1]
    cx, cy, r = b[B_CX], b[B_CY], b[B_RPX]
    # the ramp r + 1/2 - d integrates to pi r^2 + pi/12 over a disc: shrink r to make the
    # ball's total coverage its area exactly
    r_edge = math.sqrt(max(r * r - 1.0 / 12.0, 0.0))
    touched = 0
    i0 = max(int(math.floor(cx - r - 1.0)), 0)
    i1 = min(int(math.floor(cx + r + 1.0)), w - 1)
    j0 = max(int(math.floor(cy - r - 1.0)), 0)
    j1 = min(int(math.floor(cy + r + 1.0)), h - 1)
    ox, oy, oz = cam[0], cam[1], cam[2]
    for j in range(j0, j1 + 1):
        for i in range(i0, i1 + 1):
            ux = (i + 0.5 - cx) / r
            uy = (cy - (j + 0.5)) / r
            rho = math.sqrt(ux * ux + uy * uy)
            cov = r_edge + 0.5 - rho * r
            if cov <= 0.0:
                continue
            if cov > 1.0:
                cov = 1.0
            if rho > 1.0:
                ux /= rho
                uy /= rho
                uz = 0.0
            else:
                uz = math.sqrt(max(1.0 - ux * ux - uy * uy, 0.0))
            nx = ux * cam[3] + uy * cam[6] - uz * cam[9]
            ny = ux * cam[4] + uy * cam[7] - uz * cam[10]
            nz = ux * cam[5] + uy * cam[8] - uz * cam[11]
            rgb = shade(b, lights, specks, nx, ny, nz, ox, oy, oz, r)
            for c in range(3):
                img[j, i, c] = cov * rgb[c] + (1.0 - cov) * img[j, i, c]
            touched += 1
    return touched


@njit(cache=True, nogil=True)
def _light_terms(lights, m, px, py, pz, nx, ny, nz, vx, vy, vz):  # numba kernel
    """Phong's two cosines for light ``m`` at point p with unit normal n and unit vector v
    to the eye: N.L, and R.V where R is L mirrored about N (R.V is 0 when N.L <= 0)."""
    lx, ly, lz = lights[m, 0] - px, lights[m, 1] - py, lights[m, 2] - pz
    ln = math.sqrt(lx * lx + ly * ly + lz * lz)
    lx, ly, lz = lx / ln, ly / ln, lz / ln
    ndl = nx * lx + ny * ly + nz * lz
    if ndl <= 0.0:
        return ndl, 0.0
    rx, ry, rz = 2.0 * ndl * nx - lx, 2.0 * ndl * ny - ly, 2.0 * ndl * nz - lz
    return ndl, rx * vx + ry * vy + rz * vz


@njit(cache=True, nogil=True)
def shade(b, lights, specks, nx, ny, nz, ox, oy, oz, r_px):
    """Phong at the sphere point with world normal n (eye at o): ambient, diffuse, specular."""
    px = b[B_C] + b[B_R] * nx
    py = b[B_C + 1] + b[B_R] * ny
    pz = b[B_C + 2] + b[B_R] * nz
    vx, vy, vz = ox - px, oy - py, oz - pz
    vn = math.sqrt(vx * vx + vy * vy + vz * vz)
    vx, vy, vz = vx / vn, vy / vn, vz / vn
    albedo = np.empty(3)
    mix = speck_mix(b, specks, nx, ny, nz, r_px) * b[B_SPECK_MIX]
    for c in range(3):
        albedo[c] = (1.0 - mix) * b[B_ALBEDO + c] + mix * b[B_SPECK + c]
    out = np.empty(3)
    for c in range(3):
        out[c] = b[B_KA] * b[B_AMB + c] * albedo[c]
    for m in range(lights.shape[0]):
        ndl, rdv = _light_terms(lights, m, px, py, pz, nx, ny, nz, vx, vy, vz)
        if ndl <= 0.0:
            continue
        spec = b[B_KS] * rdv ** b[B_N] if rdv > 0.0 else 0.0
        for c in range(3):
            out[c] += (b[B_KD] * ndl * albedo[c] + spec) * lights[m, 3 + c]
    return out


@njit(cache=True, nogil=True)
def speck_mix(b, specks, nx, ny, nz, r_px):  # numba kernel
    """How much of a speck covers the point with world normal n (anti-aliased over about a
    pixel's angle, 1 / r_px radians, at the disc's centre)."""
    # the normal in the ball's own frame: M^T n (M turns the ball's frame to the world)
    bx = b[B_M] * nx + b[B_M + 3] * ny + b[B_M + 6] * nz
    by = b[B_M + 1] * nx + b[B_M + 4] * ny + b[B_M + 7] * nz
    bz = b[B_M + 2] * nx + b[B_M + 5] * ny + b[B_M + 8] * nz
    cos_r = b[B_SPECK_COS]
    width = math.sqrt(max(1.0 - cos_r * cos_r, 1e-12)) / max(r_px, 0.5)
    best = 0.0
    for s in range(specks.shape[0]):
        d = bx * specks[s, 0] + by * specks[s, 1] + bz * specks[s, 2]
        m = (d - cos_r) / width + 0.5
        if m > best:
            best = min(m, 1.0)
    return best


@njit(cache=True, nogil=True)
def dim(img, occ, removed, x0, y0):  # numba kernel
    """Take each light's shadowed share of the baize away: img -= sum_l occ_l * removed_l
    (occ covers img from (x0, y0)), never below black."""
    for j in range(occ.shape[1]):
        for i in range(occ.shape[2]):
            for c in range(3):
                v = img[j + y0, i + x0, c]
                for li in range(occ.shape[0]):
                    v -= occ[li, j, i, 0] * removed[li, c]
                img[j + y0, i + x0, c] = v if v > 0.0 else 0.0


@njit(cache=True, nogil=True)
def encode(out, linear, table):  # numba kernel
    """Linear light -> gamma-encoded uint8 through the gamma module's 65536-entry table."""
    n = table.shape[0] - 1
    for j in range(linear.shape[0]):
        for i in range(linear.shape[1]):
            for c in range(3):
                v = linear[j, i, c] * n + 0.5
                k = 0 if v <= 0.0 else (n if v >= n else int(v))
                out[j, i, c] = table[k]


# the wood parameter row (wood.py W_*)
@njit(cache=True, nogil=True)
def wood_polygon(img, verts, cam, p, lights, ambient):  # numba kernel
    """A wooden face: coverage as ``polygon``; each pixel's colour from the point where its
    ray meets the face (normal constant, light and eye directions per pixel: Phong) and the
    grain there, anti-aliased by fading its contrast with the pixel's footprint."""
    h = img.shape[0]
    w = img.shape[1]
    orient = _orientation(verts)
    if orient == 0.0:
        return 0
    j0 = max(int(math.floor(verts[:, 1].min())) - 1, 0)
    j1 = min(int(math.floor(verts[:, 1].max())) + 1, h - 1)
    touched = 0
    for j in range(j0, j1 + 1):
        i0, i1 = row_range(verts, j, w)
        f0, f1 = full_span(verts, orient, j + 0.5)
        for i in range(i0, i1 + 1):
            cov = 1.0 if f0 <= i + 0.5 <= f1 else coverage_at(verts, orient, i + 0.5, j + 0.5)
            if cov <= 0.0:
                continue
            rgb = wood_shade(cam, p, lights, ambient, i + 0.5, j + 0.5)
            for c in range(3):
                img[j, i, c] = cov * rgb[c] + (1.0 - cov) * img[j, i, c]
            touched += 1
    return touched


@njit(cache=True, nogil=True)
def wood_shade(cam, p, lights, ambient, x, y):  # numba kernel
    f = cam[12]
    a = (x - cam[13] / 2.0) / f
    b = (cam[14] / 2.0 - y) / f
    dx = cam[9] + a * cam[3] + b * cam[6]
    dy = cam[10] + a * cam[4] + b * cam[7]
    dz = cam[11] + a * cam[5] + b * cam[8]
    nx, ny, nz = p[3], p[4], p[5]
    den = dx * nx + dy * ny + dz * nz
    out = np.empty(3)
    t = ((p[0] - cam[0]) * nx + (p[1] - cam[1]) * ny + (p[2] - cam[2]) * nz) / den \
        if den != 0.0 else 0.0
    px, py, pz = cam[0] + t * dx, cam[1] + t * dy, cam[2] + t * dz
    u = px * p[6] + py * p[7] + pz * p[8]
    v = px * p[9] + py * p[10] + pz * p[11]
    # footprint: metres of face per pixel, from the ray's length and its slant to the face
    dn = math.sqrt(dx * dx + dy * dy + dz * dz)
    foot = t * dn / f / max(abs(den) / dn, 0.05)
    period_px = 1.0 / (p[19] * max(foot, 1e-9))
    fade = min(max((period_px - 2.0) / 4.0, 0.0), 1.0)
    phase = p[19] * v + 0.6 * math.sin(u * 1.7 + v * 30.0)  # stripes along u, wobbling
    grain = math.sin(2.0 * math.pi * phase)
    shade = 1.0 - p[20] * fade * grain
    vx, vy, vz = cam[0] - px, cam[1] - py, cam[2] - pz
    vn = math.sqrt(vx * vx + vy * vy + vz * vz)
    vx, vy, vz = vx / vn, vy / vn, vz / vn
    for c in range(3):
        out[c] = p[15] * ambient[c] * p[12 + c] * shade
    for m in range(lights.shape[0]):
        ndl, rdv = _light_terms(lights, m, px, py, pz, nx, ny, nz, vx, vy, vz)
        if ndl <= 0.0:
            continue
        spec = p[17] * rdv ** p[18] if rdv > 0.0 else 0.0
        for c in range(3):
            out[c] += (p[16] * ndl * p[12 + c] * shade + spec) * lights[m, 3 + c]
    return out
