"""Two-corner calibration: which tablet coordinates are the working area's corners.

Saved per device (the SOURCE's device key) in ``calibration.json`` under the config directory:
``$CAMLAB88_CONFIG_DIR``, else ``$XDG_CONFIG_HOME/camlab88``, else ``~/.config/camlab88``.
"""

from __future__ import annotations

import json
import os
from dataclasses import dataclass
from pathlib import Path

from camlab88.base.atomicfile import write_atomic
from camlab88.protocols.tablets.events import TabletEvent, TabletModel

FILE_NAME = "calibration.json"


class CalibrationError(ValueError):
    pass


@dataclass(frozen=True)
class Calibration:
    """``top_left``/``bottom_right`` are the tablet coordinates of the working area's corners
    (as the user sees it); a tablet whose Y grows upwards simply has top_left Y > bottom Y."""

    device: str
    top_left: tuple[int, int]
    bottom_right: tuple[int, int]

    def __post_init__(self) -> None:
        if self.top_left[0] == self.bottom_right[0] or self.top_left[1] == self.bottom_right[1]:
            raise CalibrationError(
                f"{self.device}: corners {self.top_left} and {self.bottom_right} share an axis; "
                "touch two opposite corners"
            )

    def to_fraction(self, x: float, y: float) -> tuple[float, float]:
        """Tablet units -> (0..1 across, 0..1 down) of the working area (may exceed 0..1)."""
        (ax, ay), (bx, by) = self.top_left, self.bottom_right
        return (x - ax) / (bx - ax), (y - ay) / (by - ay)

    def to_json(self) -> dict:
        return {"top_left": list(self.top_left), "bottom_right": list(self.bottom_right)}


def default_calibration(device: str, model: TabletModel) -> Calibration:
    """The whole active area, oriented by where the tablet puts its origin."""
    if model.origin == "lower-left":
        return Calibration(device, (0, model.max_y), (model.max_x, 0))
    return Calibration(device, (0, 0), (model.max_x, model.max_y))


def config_dir() -> Path:
    env = os.environ.get("CAMLAB88_CONFIG_DIR")
    if env:
        return Path(env)
    xdg = os.environ.get("XDG_CONFIG_HOME")
    return (Path(xdg) if xdg else Path.home() / ".config") / "camlab88"


def _read_all(path: Path) -> dict:
    if not path.exists():
        return {}
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except json.JSONDecodeError as exc:
        raise CalibrationError(f"{path}: line {exc.lineno}: {exc.msg}") from None
    if not isinstance(data, dict):
        raise CalibrationError(f"{path}: line 1: expected an object of devices")
    return data


def load_calibration(device: str, directory: Path | None = None) -> Calibration | None:
    path = (directory or config_dir()) / FILE_NAME
    entry = _read_all(path).get(device)
    if entry is None:
        return None
    try:
        a, b = entry["top_left"], entry["bottom_right"]
        return Calibration(device, (int(a[0]), int(a[1])), (int(b[0]), int(b[1])))
    except (KeyError, TypeError, ValueError, IndexError) as exc:
        raise CalibrationError(f"{path}: entry {device!r}: {exc}") from None


def save_calibration(cal: Calibration, directory: Path | None = None) -> Path:
    """Merge this device's corners into the file, atomically (temp file, fsync, replace)."""
    folder = directory or config_dir()
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / FILE_NAME
    data = _read_all(path)
    data[cal.device] = cal.to_json()
    write_atomic(path, json.dumps(data, indent=2, sort_keys=True) + "\n")
    return path


class CalibrationSession:
    """Collects the two corners: each is the position where the tip/button goes down."""

    PROMPTS = ("touch the TOP-LEFT corner of the working area",
               "touch the BOTTOM-RIGHT corner of the working area")

    def __init__(self, device: str) -> None:
        self.device = device
        self.corners: list[tuple[int, int]] = []
        self._down = False

    @property
    def prompt(self) -> str | None:
        return self.PROMPTS[len(self.corners)] if len(self.corners) < 2 else None

    @property
    def done(self) -> bool:
        return len(self.corners) == 2

    def feed(self, event: TabletEvent) -> bool:
        """True when this event recorded a corner."""
        pressed = event.proximity and bool(event.buttons)
        edge = pressed and not self._down
        self._down = pressed
        if edge and not self.done:
            self.corners.append((event.x, event.y))
            return True
        return False

    def result(self) -> Calibration:
        if not self.done:
            raise CalibrationError(f"{self.device}: only {len(self.corners)} corner(s) touched")
        return Calibration(self.device, self.corners[0], self.corners[1])
