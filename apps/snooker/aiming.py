"""The two aiming aids of the orange menu (§6.2.2).  Pure geometry plus the speed curve;
other balls are ignored, exactly as the thesis says.

* `aim_to_pot`: point the ball at a pocket (chosen by pointing: `nearest_pocket`), keeping
  its speed; warn if it is too slow to get there.
* `aim_next_shot`: the velocity that brings the ball to a target position with a given
  speed there (0 = stop on it), optionally off an ordered list of cushions.  Cushions are
  handled exactly: with restitution e a bounce maps the normal velocity vn to -e vn, so the
  unfolded path is a straight line to the target's image under the maps that send a
  point's signed distance s from each cushion line to -s/e (plain mirror images when
  e = 1).  The speed is then solved on the real speed curve -- held for each 1/25 s; at a
  bounce the ball stays at the same point of its curve, the curve rescaled by the bounce's
  speed ratio (as physics._bounce does) -- by bisection, so simulating the shot reproduces it.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from camlab88.apps.snooker.speed_curve import curve_for
from camlab88.apps.snooker.state import BallState
from camlab88.apps.snooker.table import Table, cushion_sides

Point = tuple[float, float]


class AimError(ValueError):
    pass


@dataclass(frozen=True)
class Aim:
    ball: int
    old_velocity: Point
    velocity: Point
    path: tuple[Point, ...]  # the ball centre's path: start, each bounce, target (dotted line)
    warning: str | None = None


def nearest_pocket(table: Table, x: float, y: float) -> int:
    """The pocket the animator pointed at."""
    d = [math.hypot(p.centre[0] - x, p.centre[1] - y) for p in table.pockets]
    return int(np.argmin(d))


def _cushion_line(table: Table, side: str) -> tuple[Point, Point]:
    """(point on the ball-centre line, inward unit normal) for a side of the table."""
    r, L, W = table.radius, table.length_m, table.width_m
    lines = {
        "baulk": ((r, 0.0), (1.0, 0.0)),
        "top": ((L - r, 0.0), (-1.0, 0.0)),
        "right": ((0.0, r), (0.0, 1.0)),
        "left": ((0.0, W - r), (0.0, -1.0)),
    }
    if side not in lines:
        raise AimError(f"unknown cushion {side!r}; cushions are {', '.join(cushion_sides())}")
    return lines[side]


class _Travel:
    """A single ball moving along a known path: speed held per frame, scaled at bounces."""

    def __init__(self, table: Table, t0: float) -> None:
        self.table = table
        self.curve = curve_for(table)
        self.t0 = t0

    def run(self, v0: float, bounce_at: Sequence[float], factors: Sequence[float],
            target: float) -> tuple[float, float]:
        """(distance travelled before stopping (capped a little past target), speed on
        reaching `target`, 0 if it never gets there)."""
        fr = self.table.frame_rate
        t = self.t0
        n = math.floor(t * fr + 1e-9) + 1
        v, cv0, ct0 = v0, v0, t
        dist, k, at_target = 0.0, 0, 0.0
        while v > 0.0:
            tb = n / fr
            nxt = bounce_at[k] if k < len(bounce_at) else math.inf
            t_hit = t + (nxt - dist) / v
            if at_target == 0.0 and dist + v * (min(t_hit, tb) - t) >= target:
                at_target = v
            if t_hit < tb:
                dist, t = nxt, t_hit
                v *= factors[k]  # as physics._bounce: same point of the rescaled curve
                cv0, ct0 = cv0 * factors[k], t - factors[k] * (t - ct0)
                k += 1
                continue
            dist += v * (tb - t)
            t = tb
            n += 1
            v = float(self.curve(np.array([cv0]), np.array([tb - ct0]), self.table)[0])
            if dist > 4 * target + 100.0:
                break
        return dist, at_target


def _solve(fn, want: float, what: str) -> float:
    """Smallest v0 with fn(v0) >= want, by doubling then bisection (fn is non-decreasing)."""
    lo, hi = 0.0, 0.05
    while fn(hi) < want:
        lo, hi = hi, hi * 2.0
        if hi > 1e4:
            raise AimError(f"no speed below {hi:g} m/s can {what}")
    for _ in range(60):
        mid = (lo + hi) / 2.0
        if fn(mid) >= want:
            hi = mid
        else:
            lo = mid
        if hi - lo <= 1e-12 * hi:
            break
    return hi


def aim_to_pot(table: Table, balls: BallState, ball: int, pocket: int) -> Aim:
    if not balls.on_table[ball]:
        raise AimError("that ball is not on the table")
    px, py = (float(v) for v in balls.pos[ball])
    cx, cy = table.pockets[pocket].centre
    dist = math.hypot(cx - px, cy - py)
    old = (float(balls.vel[ball, 0]), float(balls.vel[ball, 1]))
    speed = math.hypot(*old)
    if dist == 0.0:
        raise AimError("the ball is already in the pocket mouth")
    ux, uy = (cx - px) / dist, (cy - py) / dist
    warning = None
    if speed == 0.0:
        warning = "the ball is not moving: give it a speed first"
    else:
        travelled, _ = _Travel(table, balls.t).run(speed, (), (), dist)
        if travelled < dist:
            warning = (f"too slow: at {speed:.3f} m/s the ball stops "
                       f"{dist - travelled:.3f} m short of the {table.pockets[pocket].name} pocket")
    return Aim(ball, old, (ux * speed, uy * speed), ((px, py), (cx, cy)), warning)


def aim_next_shot(table: Table, balls: BallState, ball: int, target: Point,
                  speed_at_target: float = 0.0, cushions: Sequence[str] = ()) -> Aim:
    if not balls.on_table[ball]:
        raise AimError("that ball is not on the table")
    if speed_at_target < 0 or not math.isfinite(speed_at_target):
        raise AimError("the speed at the target must be >= 0")
    r, L, W = table.radius, table.length_m, table.width_m
    tx, ty = float(target[0]), float(target[1])
    if not (r <= tx <= L - r and r <= ty <= W - r):
        raise AimError("the target is not on the playing area")
    e = table.cushion_restitution
    if cushions and e <= 0.0:
        raise AimError("with cushion restitution 0 a ball cannot come off a cushion")
    lines = [_cushion_line(table, c) for c in cushions]
    # Image of the target: apply the unfolding maps of the last cushion first.
    ix, iy = tx, ty
    for (qx, qy), (nx, ny) in reversed(lines):
        s = (ix - qx) * nx + (iy - qy) * ny
        k = (1.0 + 1.0 / e) * s
        ix, iy = ix - k * nx, iy - k * ny
    px, py = (float(v) for v in balls.pos[ball])
    dx, dy = ix - px, iy - py
    norm = math.hypot(dx, dy)
    if norm == 0.0:
        raise AimError("the ball is already at the target")
    vx, vy = dx / norm, dy / norm
    # Trace the real path forward, bounce by bounce, checking it is the one asked for.
    path: list[Point] = [(px, py)]
    legs: list[float] = []
    factors: list[float] = []
    x, y = px, py
    for name, ((qx, qy), (nx, ny)) in zip(cushions, lines, strict=True):
        vn = vx * nx + vy * ny
        if vn >= 0.0:
            raise AimError(f"the ball cannot reach the {name} cushion on this path")
        lam = -((x - qx) * nx + (y - qy) * ny) / vn
        hx, hy = x + vx * lam, y + vy * lam
        _check_leg(table, (x, y), (hx, hy), name)
        if not _on_cushion(table, name, hx, hy):
            raise AimError(f"the path meets the {name} cushion in a pocket mouth")
        legs.append(lam)
        vx, vy = vx - (1.0 + e) * vn * nx, vy - (1.0 + e) * vn * ny
        f = math.hypot(vx, vy)
        factors.append(f)  # (physics caps the speed at max_speed_m_s; aims stay below it)
        vx, vy = vx / f, vy / f
        x, y = hx, hy
        path.append((x, y))
    last = math.hypot(tx - x, ty - y)
    if abs((tx - x) - vx * last) > 1e-6 or abs((ty - y) - vy * last) > 1e-6:
        raise AimError("no path off those cushions reaches the target")
    _check_leg(table, (x, y), (tx, ty), "target")
    path.append((tx, ty))
    bounce_at = list(np.cumsum(legs)) if legs else []
    total = float(sum(legs) + last)
    travel = _Travel(table, balls.t)
    if speed_at_target == 0.0:
        v0 = _solve(lambda v: travel.run(v, bounce_at, factors, total)[0], total,
                    "reach the target")
    else:
        v0 = _solve(lambda v: travel.run(v, bounce_at, factors, total)[1], speed_at_target,
                    f"arrive at {speed_at_target:g} m/s")
    top = v0 * max([1.0, *np.cumprod(factors)])
    if top > table.max_speed_m_s:
        raise AimError(f"that needs {top:.1f} m/s, over the table's max_speed_m_s")
    ux, uy = dx / norm, dy / norm
    old = (float(balls.vel[ball, 0]), float(balls.vel[ball, 1]))
    warning = None
    if balls.spin[ball] != 0.0:
        warning = "the ball's spin is not allowed for; it will be cleared"
    return Aim(ball, old, (ux * v0, uy * v0), tuple(path), warning)


def _on_cushion(table: Table, side: str, x: float, y: float) -> bool:
    for s in table.segments:
        if s.side != side:
            continue
        tx, ty = s.tangent
        u = (x - s.ax) * tx + (y - s.ay) * ty
        if 0.0 <= u <= s.length:
            return True
    return False


def _check_leg(table: Table, a: Point, b: Point, goal: str) -> None:
    """A leg must stay between the cushion lines (else it would hit another cushion first)."""
    r, L, W = table.radius, table.length_m, table.width_m
    eps = 1e-9
    for x, y in (a, b):
        if not (r - eps <= x <= L - r + eps and r - eps <= y <= W - r + eps):
            raise AimError(f"the path leaves the table on the way to the {goal}")
