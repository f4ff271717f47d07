"""The state of the balls at one instant: positions, velocities, spin and where each ball is
on its speed curve.  `BallState` is immutable (read-only arrays) so frames can share it; the
simulator works on a `Motion`, its mutable twin."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from camlab88.apps.snooker.table import N_BALLS

_ARRAYS = ("pos", "vel", "spin", "curve_v0", "curve_t0", "spin0", "spin_t0", "on_table")


def _frozen(a: np.ndarray) -> np.ndarray:
    a = np.array(a, copy=True)
    a.flags.writeable = False
    return a


@dataclass(frozen=True, eq=False)
class BallState:
    """Balls at time `t` (s).  `vel` is the main (sliding/rolling) velocity in effect until the
    next frame boundary, `spin` the extra component along it (+ top spin, - back spin).  A
    ball's speed curve started at time `curve_t0` with speed `curve_v0`; its spin started
    decaying at `spin_t0` from `spin0`.  Potted balls have on_table False and sit off the
    playing area."""

    t: float
    pos: np.ndarray  # (22, 2) m
    vel: np.ndarray  # (22, 2) m/s
    spin: np.ndarray  # (22,) m/s
    curve_v0: np.ndarray
    curve_t0: np.ndarray
    spin0: np.ndarray
    spin_t0: np.ndarray
    on_table: np.ndarray  # (22,) bool

    def thaw(self) -> Motion:
        return Motion(self.t, *(np.array(getattr(self, n), copy=True) for n in _ARRAYS))

    def speed(self, ball: int) -> float:
        return math.hypot(float(self.vel[ball, 0]), float(self.vel[ball, 1]))

    def effective_velocity(self) -> np.ndarray:
        return effective_velocity(self.vel, self.spin)

    def any_moving(self) -> bool:
        return bool(np.any(self.on_table & np.any(self.vel != 0.0, axis=1)))

    def same_as(self, other: BallState) -> bool:
        return self.t == other.t and all(
            np.array_equal(getattr(self, n), getattr(other, n)) for n in _ARRAYS
        )

    def to_json(self) -> dict[str, object]:
        out: dict[str, object] = {"t": self.t}
        for n in _ARRAYS:
            out[n] = getattr(self, n).tolist()
        return out

    @classmethod
    def from_json(cls, data: dict[str, object]) -> BallState:
        arrays = []
        for n in _ARRAYS:
            dtype = bool if n == "on_table" else np.float64
            a = np.asarray(data[n], dtype=dtype)
            want = (N_BALLS, 2) if n in ("pos", "vel") else (N_BALLS,)
            if a.shape != want:
                raise ValueError(f"{n} has shape {a.shape}, expected {want}")
            if a.dtype != bool and not np.all(np.isfinite(a)):
                raise ValueError(f"{n} holds a non-finite number")
            arrays.append(a)
        return cls(float(data["t"]), *(_frozen(a) for a in arrays))

    @classmethod
    def at_rest(cls, positions: np.ndarray, on_table: np.ndarray, t: float = 0.0) -> BallState:
        z2 = np.zeros((N_BALLS, 2))
        z = np.zeros(N_BALLS)
        return cls(t, _frozen(positions), _frozen(z2), _frozen(z), _frozen(z), _frozen(z),
                   _frozen(z), _frozen(z), _frozen(np.asarray(on_table, dtype=bool)))


@dataclass(eq=False)
class Motion:
    """Mutable working copy used while simulating."""

    t: float
    pos: np.ndarray
    vel: np.ndarray
    spin: np.ndarray
    curve_v0: np.ndarray
    curve_t0: np.ndarray
    spin0: np.ndarray
    spin_t0: np.ndarray
    on_table: np.ndarray

    def freeze(self) -> BallState:
        return BallState(self.t, *(_frozen(getattr(self, n)) for n in _ARRAYS))

    def set_velocity(self, ball: int, vx: float, vy: float, spin: float = 0.0) -> None:
        """Set a ball moving: it starts a fresh speed curve (and spin decay) now."""
        speed = math.hypot(vx, vy)
        self.vel[ball] = (vx, vy)
        self.curve_v0[ball] = speed
        self.curve_t0[ball] = self.t
        s = spin if speed > 0 else 0.0
        self.spin[ball] = s
        self.spin0[ball] = s
        self.spin_t0[ball] = self.t


def effective_velocity(vel: np.ndarray, spin: np.ndarray) -> np.ndarray:
    """Main velocity plus the spin component along it; back spin can at most cancel it."""
    speed = np.hypot(vel[:, 0], vel[:, 1])
    with np.errstate(divide="ignore", invalid="ignore"):
        safe = np.where(speed > 0, speed, 1.0)
        factor = np.where(speed > 0, np.maximum(0.0, speed + spin) / safe, 0.0)
    return vel * factor[:, None]
