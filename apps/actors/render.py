"""Actors on the floor of the grid, rendered: a pure function of picklable arguments, so a
frame is bit-identical in any process (local pool or Dask).

World frame (cell units, right-handed): X = column, Y = -row, Z up; cell (col, row) is the
floor square [col, col + 1) x (-row - 1, -row], an actor stands on its centre. The floor
is a board of the cells in ``Stage.floor`` (two tones, like a chessboard); a cell of a state
without an actor is a tile of that state's colour. Lights are snooker's point lights
(apps.snooker.render.lights.Lights) in this frame. The camera is snooker's pinhole (a view's
observer, viewpoint and focal length in mm on 35 mm film).

Anti-aliasing: ``ss`` x ``ss`` samples a pixel; a pixel whose samples all see one triangle or
one board cell is shaded once, any other is the mean of its samples in linear light.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from camlab88.apps.actors.mesh import actor_mesh, articulated, posed_actor_mesh, triangle_count
from camlab88.apps.actors.model import Actor, ActorSet
from camlab88.apps.snooker.render.frame import camera_params
from camlab88.apps.snooker.render.gamma import decode, encode_image
from camlab88.apps.snooker.render.lights import DEFAULT_AMBIENT, DEFAULT_INTENSITY, Lights
from camlab88.apps.snooker.render.pinhole import Pinhole

BACKGROUND = np.array((0.012, 0.010, 0.010))  # the dark room round the board (snooker's)
BOARD = (np.array((0.26, 0.17, 0.085)), np.array((0.045, 0.026, 0.014)))  # maple, walnut
FLOOR_PHONG = (1.0, 1.0, 0.08, 12.0)  # ka kd ks n: a waxed board, reconstructed
SHADOW_MAP = 1024


@dataclass(frozen=True)
class Placed:
    """One actor in one frame: its state, cell centre (col, row: may be fractional while
    gliding), scale (0 unborn .. 1), turn (degrees about z) and lift (bob, cells)."""

    state: int
    col: float
    row: float
    scale: float = 1.0
    turn: float = 0.0
    lift: float = 0.0
    clock: float = 0.0  # the actor's own frame: where its swinging parts are


@dataclass(frozen=True, eq=False)
class Stage:
    """What a frame shows: the actors, the tiles, the board and the lights."""

    actors: ActorSet
    floor: tuple[int, int, int, int]  # col0, row0, col1, row1 (exclusive): the board's cells
    lights: Lights
    placed: tuple[Placed, ...] = ()
    tiles: tuple[tuple[int, int, tuple[int, int, int]], ...] = ()  # (col, row, rgb)


@dataclass(frozen=True)
class Look:
    width: int = 768
    height: int = 512
    ss: int = 2  # samples per pixel along each axis
    shadows: bool = True
    shadow_map: int = SHADOW_MAP


@dataclass(frozen=True)
class Shot:
    observer: tuple[float, float, float]
    viewpoint: tuple[float, float, float]
    focal_mm: float = 35.0


def canopy_over(floor: tuple[int, int, int, int], n: int = 4) -> Lights:
    """``n`` (1, 2 or 4) bulbs above the board, like the snooker table's canopy: high
    enough that every actor (under 2 cells tall) is below them."""
    c0, r0, c1, r1 = floor
    cx, cy = (c0 + c1) / 2.0, -(r0 + r1) / 2.0
    span = max(c1 - c0, r1 - r0, 4)
    z = 0.3 * span + 4.0  # low enough for shadows a cell or so long at the board's edge
    dx, dy = 0.3 * (c1 - c0), 0.3 * (r1 - r0)
    spots = {1: [(0, 0)], 2: [(-1, 0), (1, 0)], 4: [(-1, -1), (-1, 1), (1, -1), (1, 1)]}[n]
    pos = np.array([(cx + sx * dx, cy + sy * dy, z) for sx, sy in spots], dtype=np.float64)
    return Lights(pos, np.full((len(spots), 3), DEFAULT_INTENSITY * 4.0 / len(spots)),
                  np.full(3, DEFAULT_AMBIENT))


def linear_colour(rgb: tuple[int, int, int]) -> np.ndarray:
    return decode(np.array(rgb, dtype=np.float64))


# What a frame costs: a placed triangle ~800 bytes (its corners and normals, their world and
# camera copies, depths and screen positions, the mesh's temporaries), a sample ~48 (depth,
# triangle id, two barycentrics, the linear image), a light its shadow map of float64
TRIANGLE_BYTES = 800
SAMPLE_BYTES = 48


def frame_need(actors: ActorSet, placed: dict[int, int], lights: int, look: Look
               ) -> tuple[int, str]:
    """(bytes, what) a frame of ``look`` needs with ``placed[state]`` actors of each state
    and ``lights`` lights, worked out before anything is made (base.budget)."""
    tris = sum(triangle_count(actors.actors[s]) * k for s, k in placed.items()
               if s in actors.actors)
    samples = look.width * look.height * look.ss * look.ss
    shadow = look.shadow_map ** 2 * 8 if look.shadows else 8
    need = tris * TRIANGLE_BYTES + samples * SAMPLE_BYTES + lights * shadow
    return need, (f"a {look.width}x{look.height} frame of {tris:,} triangles and {lights:,} "
                  f"lights")


@lru_cache(maxsize=64)
def _mesh(actor: Actor) -> tuple[np.ndarray, np.ndarray]:
    m = actor_mesh(actor)
    return m.verts, m.normals


def world_triangles(stage: Stage) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(verts (n, 3, 3), normals (n, 3, 3), material row (n,)) of every placed actor, in
    the order placed; material row = index of the state in sorted(stage.actors.actors)."""
    order = {s: k for k, s in enumerate(sorted(stage.actors.actors))}
    vs, ns, ms = [], [], []
    for p in stage.placed:
        actor = stage.actors.actors.get(p.state)
        if actor is None or p.scale <= 0.0:
            continue
        if articulated(actor):
            m = posed_actor_mesh(actor, p.clock)
            v, n = m.verts, m.normals
        else:
            v, n = _mesh(actor)
        if len(v) == 0:
            continue
        a = np.radians(p.turn)
        rot = np.array([[np.cos(a), -np.sin(a), 0.0], [np.sin(a), np.cos(a), 0.0],
                        [0.0, 0.0, 1.0]])
        at = np.array([p.col + 0.5, -(p.row + 0.5), p.lift])
        vs.append((v * p.scale) @ rot.T + at)
        ns.append(n @ rot.T)
        ms.append(np.full(len(v), order[p.state], dtype=np.int64))
    if not vs:
        return np.zeros((0, 3, 3)), np.zeros((0, 3, 3)), np.zeros(0, np.int64)
    return np.concatenate(vs), np.concatenate(ns), np.concatenate(ms)


def materials(stage: Stage) -> tuple[np.ndarray, np.ndarray]:
    """(albedo (k, 3) linear, Phong (k, 4) ka kd ks n) per state in sorted order (one
    placeholder row when there are no actors: the kernel wants a row to copy)."""
    acts = [stage.actors.actors[s] for s in sorted(stage.actors.actors)]
    if not acts:
        return np.zeros((1, 3)), np.zeros((1, 4))
    alb = np.array([linear_colour(a.colour) for a in acts])
    mat = np.array([(a.material.ambient, a.material.diffuse, a.material.specular,
                     a.material.shininess) for a in acts], dtype=np.float64)
    return alb, mat


def board(stage: Stage) -> np.ndarray:
    """(rows, cols, 3) linear albedo of the floor's cells: the board, then the tiles."""
    c0, r0, c1, r1 = stage.floor
    rr, cc = np.mgrid[r0:r1, c0:c1]
    tiles = np.where(((rr + cc) % 2 == 0)[..., None], BOARD[0], BOARD[1])
    for col, row, rgb in stage.tiles:
        if c0 <= col < c1 and r0 <= row < r1:
            tiles[row - r0, col - c0] = linear_colour(rgb)
    return np.ascontiguousarray(tiles, dtype=np.float64)


def _light_params(lights: Lights, verts: np.ndarray, floor: tuple[int, int, int, int],
                  size: int) -> np.ndarray:
    """(L, 4) lx, ly, lz, f: f so that the board and every actor fit in the map."""
    c0, r0, c1, r1 = floor
    lo = np.array([c0, -r1, 0.0])
    hi = np.array([c1, -r0, 0.0])
    if len(verts):
        flat = verts.reshape(-1, 3)
        lo, hi = np.minimum(lo, flat.min(0)), np.maximum(hi, flat.max(0))
    out = []
    for lx, ly, lz in lights.positions.tolist():
        top = min(hi[2], lz - 0.05)
        reach = 1e-6
        for z in (lo[2], top):
            d = max(lz - z, 0.05)
            reach = max(reach, abs(lo[0] - lx) / d, abs(hi[0] - lx) / d,
                        abs(lo[1] - ly) / d, abs(hi[1] - ly) / d)
        out.append((lx, ly, lz, (size / 2.0 - 2.0) / reach))
    return np.ascontiguousarray(out, dtype=np.float64)


def shadow_maps(stage: Stage, verts: np.ndarray, look: Look) -> tuple[np.ndarray, np.ndarray]:
    from camlab88.apps.actors import raster

    lp = _light_params(stage.lights, verts, stage.floor, look.shadow_map)
    size = look.shadow_map if look.shadows else 1
    maps = np.full((len(lp), size, size), np.inf)
    if look.shadows:
        v = np.ascontiguousarray(verts, dtype=np.float64)
        for k in range(len(lp)):
            raster.shadow_depth(v, lp[k], maps[k])
    return maps, lp


def render_linear(stage: Stage, shot: Shot, look: Look | None = None) -> np.ndarray:
    """(H, W, 3) float64 linear light."""
    from camlab88.apps.actors import raster

    lk = look or Look()
    w, h = lk.width * lk.ss, lk.height * lk.ss
    pin = Pinhole.of(np.asarray(shot.observer, dtype=np.float64),
                     np.asarray(shot.viewpoint, dtype=np.float64), shot.focal_mm, w, h)
    verts, normals, tri_mat = world_triangles(stage)
    cam = pin.to_camera(verts.reshape(-1, 3)).reshape(-1, 3, 3)
    depth = np.ascontiguousarray(cam[..., 2])
    safe = np.where(depth > raster.NEAR, depth, 1.0)
    sx = np.ascontiguousarray(w / 2.0 + pin.focal_px * cam[..., 0] / safe)
    sy = np.ascontiguousarray(h / 2.0 - pin.focal_px * cam[..., 1] / safe)
    zbuf = np.full((h, w), np.inf)
    ids = np.full((h, w), -1, dtype=np.int64)
    b1, b2 = np.zeros((h, w)), np.zeros((h, w))
    raster.rasterise(sx, sy, depth, zbuf, ids, b1, b2)
    maps, lp = shadow_maps(stage, verts, lk)
    albedo, mats = materials(stage)
    img = np.empty((lk.height, lk.width, 3))
    c0, r0 = stage.floor[:2]
    raster.shade(img, np.int64(lk.ss), zbuf, ids, b1, b2, camera_params(pin),
                 np.ascontiguousarray(normals, dtype=np.float64),
                 np.ascontiguousarray(tri_mat, dtype=np.int64), albedo, mats,
                 np.ascontiguousarray(np.hstack([stage.lights.positions,
                                                 stage.lights.colours]), dtype=np.float64),
                 np.ascontiguousarray(stage.lights.ambient, dtype=np.float64), maps, lp,
                 board(stage), np.array([c0, r0, *FLOOR_PHONG], dtype=np.float64), BACKGROUND)
    return img


def render_frame(stage: Stage, shot: Shot, look: Look | None = None) -> np.ndarray:
    """(H, W, 3) uint8, gamma-encoded, row 0 = top."""
    return encode_image(render_linear(stage, shot, look))
