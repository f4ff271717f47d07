"""Actors as triangles: each solid part tessellated in the actor's own frame (cell units, z
up, the cell's centre at the origin), with a normal at every corner for Phong shading.

A lathe's profile is revolved in ``SEGMENTS`` steps; where two profile segments meet at
less than ``CREASE_DEG`` the normals are averaged (a smooth turned surface), at a sharper
angle each keeps its own (the crisp edge of a base or a collar). Its ends are closed by flat
discs. A sphere is a latitude-longitude mesh; a box and an extrusion have flat faces (the
extrusion's polygon triangulated by ear clipping, so a concave outline works).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from camlab88.apps.actors.model import Actor, Part

SEGMENTS = 24  # around a lathe or a sphere
RINGS = 12  # a sphere's latitude bands
CREASE_DEG = 40.0


@dataclass(frozen=True, eq=False)
class Mesh:
    """Triangles (n, 3, 3) and corner normals (n, 3, 3), float64, in the actor's frame."""

    verts: np.ndarray
    normals: np.ndarray

    @staticmethod
    def empty() -> Mesh:
        return Mesh(np.zeros((0, 3, 3)), np.zeros((0, 3, 3)))

    @staticmethod
    def join(meshes: list[Mesh]) -> Mesh:
        if not meshes:
            return Mesh.empty()
        return Mesh(np.concatenate([m.verts for m in meshes]),
                    np.concatenate([m.normals for m in meshes]))


def _unit(v: np.ndarray) -> np.ndarray:
    n = np.linalg.norm(v, axis=-1, keepdims=True)
    return v / np.where(n > 0, n, 1.0)


def _quads(a: np.ndarray, b: np.ndarray, c: np.ndarray, d: np.ndarray,
           na: np.ndarray, nb: np.ndarray, nc: np.ndarray, nd: np.ndarray) -> Mesh:
    """Quads a-b-c-d (arrays (k, 3)) as two triangles each."""
    v = np.concatenate([np.stack([a, b, c], 1), np.stack([a, c, d], 1)])
    n = np.concatenate([np.stack([na, nb, nc], 1), np.stack([na, nc, nd], 1)])
    return Mesh(v, n)


def _next(x: np.ndarray) -> np.ndarray:
    """Each ring point's neighbour along the next meridian."""
    return np.roll(x, -1, axis=0)


def _ring(r: float, z: float, cos: np.ndarray, sin: np.ndarray) -> np.ndarray:
    return np.stack([r * cos, r * sin, np.full_like(cos, z)], axis=1)


def _disc(r: float, z: float, up: bool, cos: np.ndarray, sin: np.ndarray) -> Mesh:
    ring = _ring(r, z, cos, sin)
    nxt = np.roll(ring, -1, axis=0)
    centre = np.broadcast_to([0.0, 0.0, z], ring.shape)
    v = np.stack([centre, ring, nxt] if up else [centre, nxt, ring], axis=1)
    n = np.broadcast_to([0.0, 0.0, 1.0 if up else -1.0], v.shape)
    return Mesh(v.copy(), n.copy())


def lathe(profile: tuple[tuple[float, float], ...]) -> Mesh:
    """The profile (radius, height) revolved about z; flat discs close its ends."""
    pts = [p for i, p in enumerate(profile) if i == 0 or p != profile[i - 1]]
    if len(pts) < 2:
        return Mesh.empty()
    ang = 2 * np.pi * np.arange(SEGMENTS) / SEGMENTS
    cos, sin = np.cos(ang), np.sin(ang)
    seg = [(b[0] - a[0], b[1] - a[1]) for a, b in zip(pts, pts[1:])]
    own = [_unit(np.array([dh, -dr])) for dr, dh in seg]  # outward (radial, vertical)
    crease = math.cos(math.radians(CREASE_DEG))
    parts: list[Mesh] = []
    for k, (a, b) in enumerate(zip(pts, pts[1:])):
        n_lo, n_hi = own[k], own[k]
        if k > 0 and float(own[k] @ own[k - 1]) > crease:
            n_lo = _unit(own[k] + own[k - 1])
        if k + 1 < len(own) and float(own[k] @ own[k + 1]) > crease:
            n_hi = _unit(own[k] + own[k + 1])
        lo, hi = _ring(a[0], a[1], cos, sin), _ring(b[0], b[1], cos, sin)
        nlo = np.stack([n_lo[0] * cos, n_lo[0] * sin, np.full_like(cos, n_lo[1])], 1)
        nhi = np.stack([n_hi[0] * cos, n_hi[0] * sin, np.full_like(cos, n_hi[1])], 1)
        r = _next
        parts.append(_quads(lo, r(lo), r(hi), hi, nlo, r(nlo), r(nhi), nhi))
    if pts[0][0] > 0:
        parts.append(_disc(pts[0][0], pts[0][1], False, cos, sin))
    if pts[-1][0] > 0:
        parts.append(_disc(pts[-1][0], pts[-1][1], True, cos, sin))
    return Mesh.join(parts)


def box(w: float, d: float, h: float) -> Mesh:
    x, y = w / 2, d / 2
    c = np.array([[-x, -y, 0], [x, -y, 0], [x, y, 0], [-x, y, 0],
                  [-x, -y, h], [x, -y, h], [x, y, h], [-x, y, h]], dtype=np.float64)
    faces = [((0, 3, 2, 1), (0, 0, -1)), ((4, 5, 6, 7), (0, 0, 1)), ((0, 1, 5, 4), (0, -1, 0)),
             ((1, 2, 6, 5), (1, 0, 0)), ((2, 3, 7, 6), (0, 1, 0)), ((3, 0, 4, 7), (-1, 0, 0))]
    out = []
    for (a, b, cc, dd), n in faces:
        nn = np.array([n], dtype=np.float64)
        out.append(_quads(c[[a]], c[[b]], c[[cc]], c[[dd]], nn, nn, nn, nn))
    return Mesh.join(out)


def sphere(r: float) -> Mesh:
    """Radius ``r``, standing on the origin (its centre at height r)."""
    lat = np.pi * np.arange(RINGS + 1) / RINGS - np.pi / 2
    ang = 2 * np.pi * np.arange(SEGMENTS) / SEGMENTS
    cos, sin = np.cos(ang), np.sin(ang)
    out = []
    for a, b in zip(lat, lat[1:]):
        na = np.stack([np.cos(a) * cos, np.cos(a) * sin, np.full_like(cos, np.sin(a))], 1)
        nb = np.stack([np.cos(b) * cos, np.cos(b) * sin, np.full_like(cos, np.sin(b))], 1)
        ra, rb = np.roll(na, -1, axis=0), np.roll(nb, -1, axis=0)
        lift = np.array([0.0, 0.0, r])
        out.append(_quads(r * na + lift, r * ra + lift, r * rb + lift, r * nb + lift,
                          na, ra, rb, nb))
    m = Mesh.join(out)
    area = np.linalg.norm(np.cross(m.verts[:, 1] - m.verts[:, 0],
                                   m.verts[:, 2] - m.verts[:, 0]), axis=1)
    keep = area > 1e-12 * max(r * r, 1e-12)  # the poles' collapsed triangles
    return Mesh(m.verts[keep], m.normals[keep])


def _ear_clip(poly: np.ndarray) -> list[tuple[int, int, int]]:
    """Triangles of a simple anticlockwise polygon (a fan if it is not simple)."""
    idx = list(range(len(poly)))
    tris: list[tuple[int, int, int]] = []
    guard = 0
    while len(idx) > 3 and guard < 4 * len(poly) ** 2:
        guard += 1
        for k in range(len(idx)):
            i, j, m = idx[k - 1], idx[k], idx[(k + 1) % len(idx)]
            a, b, c = poly[i], poly[j], poly[m]
            if (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]) <= 0:
                continue  # reflex (or flat) corner
            if any(_inside(poly[q], a, b, c) for q in idx if q not in (i, j, m)):
                continue
            tris.append((i, j, m))
            idx.pop(k)
            break
        else:
            break
    if len(idx) > 3:  # not simple: fan the rest
        tris += [(idx[0], idx[k], idx[k + 1]) for k in range(1, len(idx) - 1)]
    elif len(idx) == 3:
        tris.append((idx[0], idx[1], idx[2]))
    return tris


def _inside(p: np.ndarray, a: np.ndarray, b: np.ndarray, c: np.ndarray) -> bool:
    def side(u: np.ndarray, v: np.ndarray) -> float:
        return float((v[0] - u[0]) * (p[1] - u[1]) - (v[1] - u[1]) * (p[0] - u[0]))
    return side(a, b) >= 0 and side(b, c) >= 0 and side(c, a) >= 0


def extrude(polygon: tuple[tuple[float, float], ...], h: float) -> Mesh:
    poly = np.array(polygon, dtype=np.float64)
    area = 0.5 * float(np.sum(poly[:, 0] * np.roll(poly[:, 1], -1)
                              - np.roll(poly[:, 0], -1) * poly[:, 1]))
    if abs(area) < 1e-12:
        return Mesh.empty()
    if area < 0:
        poly = poly[::-1]
    tris = np.array(_ear_clip(poly), dtype=np.int64)
    flat = np.concatenate([poly, np.zeros((len(poly), 1))], axis=1)
    top = flat + [0.0, 0.0, h]
    caps = [Mesh(top[tris], np.broadcast_to([0.0, 0.0, 1.0], (len(tris), 3, 3)).copy()),
            Mesh(flat[tris[:, ::-1]], np.broadcast_to([0.0, 0.0, -1.0],
                                                      (len(tris), 3, 3)).copy())]
    nxt = np.roll(flat, -1, axis=0)
    edge = nxt - flat
    n = _unit(np.stack([edge[:, 1], -edge[:, 0], np.zeros(len(edge))], axis=1))
    side = _quads(flat, nxt, nxt + [0, 0, h], flat + [0, 0, h], n, n, n, n)
    return Mesh.join([*caps, side])


def part_mesh(p: Part) -> Mesh:
    """One part, placed and scaled as the actors file says (docs/ca_actors.md)."""
    sx, sy, sz = (float(v) for v in p.size)
    if p.kind == "box":
        m, scale = box(sx, sy, sz), np.ones(3)
    elif p.kind == "sphere":
        m, scale = sphere(sx), np.ones(3)
    elif p.kind == "lathe":
        m, scale = lathe(p.profile), np.array([sx, sy, sz])
    elif p.kind == "extrude":
        m, scale = extrude(p.profile, sz), np.array([sx, sy, 1.0])
    else:
        raise ValueError(f"unknown part kind {p.kind!r}")
    if len(m.verts) == 0:
        return m
    normals = m.normals if np.all(scale == 1) else _unit(m.normals / scale)
    return Mesh(m.verts * scale + np.asarray(p.offset, dtype=np.float64), normals)


def triangle_count(actor: Actor) -> int:
    """The triangles :func:`actor_mesh` makes of ``actor`` at most, counted without making
    them (a renderer checks its memory budget with it first)."""
    n = 0
    for p in actor.parts:
        if p.kind == "box":
            n += 12
        elif p.kind == "sphere":
            n += 2 * RINGS * SEGMENTS
        elif p.kind == "lathe":
            n += 2 * SEGMENTS * max(len(p.profile) - 1, 0) + 2 * SEGMENTS
        elif p.kind == "extrude":
            n += 4 * len(p.profile)
    return n


def actor_mesh(actor: Actor) -> Mesh:
    """The actor at rest (its swinging parts at angle 0)."""
    return Mesh.join([part_mesh(p) for p in actor.parts])


def articulated(actor: Actor) -> bool:
    return any(p.swing is not None for p in actor.parts)


def swing_angle(p: Part, clock: float) -> float:
    """Degrees a swinging part is turned at the actor's own frame ``clock``."""
    if p.swing is None:
        return 0.0
    _, amplitude, period, phase = p.swing
    return amplitude * math.sin(2.0 * math.pi * (clock / period + phase))


def posed_actor_mesh(actor: Actor, clock: float) -> Mesh:
    """The actor with each swinging part turned about the x axis through (its offset x and
    y, its pivot height) by ``swing_angle`` (a limb swinging forward and back)."""
    meshes = []
    for p in actor.parts:
        m = part_mesh(p)
        if p.swing is not None and len(m.verts):
            a = math.radians(swing_angle(p, clock))
            rot = np.array([[1.0, 0.0, 0.0], [0.0, math.cos(a), -math.sin(a)],
                            [0.0, math.sin(a), math.cos(a)]])
            pivot = np.array([0.0, p.offset[1], p.swing[0]])
            m = Mesh((m.verts - pivot) @ rot.T + pivot, m.normals @ rot.T)
        meshes.append(m)
    return Mesh.join(meshes)
