"""Per-vendor HID profiles for tablets whose pen reports are vendor-specific.

Wacom (VID 0x056A) legacy tablets power up sending mouse-like reports; the kernel switches
them to tablet mode by setting feature report 2 to 2 (``02 02``) and then decodes fixed
layouts per family (``drivers/hid/wacom_wac.c``, facts §4.4).  Newer Wacoms describe their pen
on page 0xFF0D and are decoded from the descriptor (see ``hid_decode``).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

from camlab88.protocols.tablets.events import TabletEvent, TabletModel

WACOM_VID = 0x056A
MODE_SWITCH = bytes((2, 2))  # feature report ID 2 := 2 ("tablet mode")


def _le16(d: bytes, i: int) -> int:
    return d[i] | d[i + 1] << 8


def _graphire(d: bytes, t: float) -> TabletEvent | None:
    """Graphire/Graphire2-4/Bamboo1/Volito: 8-byte report ID 2 (``wacom_graphire_irq``)."""
    if d[0] != 2 or len(d) < 8:
        return None
    proximity = bool(d[1] & 0x80)
    kind = d[1] >> 5 & 3  # 0 pen, 1 eraser, 2 wheel mouse, 3 mouse
    tool = ("pen", "eraser", "puck", "puck")[kind]
    buttons = d[1] & 0x07
    pressure = (d[6] | (d[7] & 3) << 8) if kind < 2 else None
    return TabletEvent(_le16(d, 2), _le16(d, 4), proximity, buttons, pressure, None, None,
                       tool, t)


def _bamboo_pen(d: bytes, t: float) -> TabletEvent | None:
    """Bamboo pen / Intuos "HT" (CTL/CTH-4xx..6xx): report ID 2 (``wacom_bpt_pen``)."""
    if d[0] != 2 or len(d) < 9:
        return None
    proximity = bool(d[1] & 0x20)
    tool = "eraser" if d[1] & 0x08 else "pen"
    return TabletEvent(_le16(d, 2), _le16(d, 4), proximity, d[1] & 0x07, _le16(d, 6), None,
                       None, tool, t)


class _IntuosState:
    """Intuos sends a tool-enter packet naming the tool, then general packets."""

    def __init__(self) -> None:
        self.tool = "pen"
        self.in_prox = False

    def __call__(self, d: bytes, t: float) -> TabletEvent | None:
        if d[0] not in (2, 5, 6, 16) or len(d) < 10:
            return None
        head = d[1]
        if head & 0xFC == 0xC0:  # tool enters: id from the serial bytes
            tool_id = d[2] << 4 | d[3] >> 4 | (d[7] & 0x0F) << 20 | (d[8] & 0xF0) << 12
            low = tool_id & 0xFFF
            self.tool = "eraser" if low in ERASER_IDS else "puck" if low in PUCK_IDS else "pen"
            self.in_prox = True
            return None
        if head & 0xFE == 0x80:  # out of proximity
            self.in_prox = False
            return TabletEvent(0, 0, False, 0, None, None, None, self.tool, t)
        if head & 0xFE == 0x20:  # in range, no data yet
            return None
        kind = head >> 1 & 0x0F
        x = (d[2] << 8 | d[3]) << 1 | (d[9] >> 1 & 1)
        y = (d[4] << 8 | d[5]) << 1 | (d[9] & 1)
        x, y = x >> 1, y >> 1  # pre-Intuos3 layout: 16-bit coordinates
        if kind > 3:
            return TabletEvent(x, y, True, 0, None, None, None, "puck", t)
        pressure = d[6] << 3 | (d[7] & 0xC0) >> 5 | (head & 1)
        pressure >>= 1  # Intuos1/2: pressure_max 1023
        tilt_x = ((d[7] << 1) & 0x7E | d[8] >> 7) - 64
        tilt_y = (d[8] & 0x7F) - 64
        buttons = (1 if pressure > 10 else 0) | (2 if head & 2 else 0) | (4 if head & 4 else 0)
        return TabletEvent(x, y, True, buttons, pressure, tilt_x, tilt_y, self.tool, t)


ERASER_IDS = {0x82A, 0x85A, 0x91A, 0x0FA, 0x80A}
PUCK_IDS = {0x007, 0x094, 0x09C, 0x017, 0x806, 0x096, 0x097, 0x006}


@dataclass(frozen=True)
class WacomProfile:
    pid: int
    name: str
    family: str  # "graphire", "bamboo-pen", "intuos"
    max_x: int
    max_y: int
    pressure_max: int
    res_per_mm: int

    @property
    def model(self) -> TabletModel:
        return TabletModel(self.name, self.max_x, self.max_y, self.res_per_mm * 25.4,
                           self.pressure_max, (-64, 63) if self.family == "intuos" else None)

    @property
    def init_feature_report(self) -> bytes:
        return MODE_SWITCH

    def make_decoder(self) -> Callable[[bytes, float], TabletEvent | None]:
        if self.family == "graphire":
            return _graphire
        if self.family == "bamboo-pen":
            return _bamboo_pen
        return _IntuosState()


_INTUOS_SIZES = (("4x5", 12700, 10600), ("6x8", 20320, 16240), ("9x12", 30480, 24060),
                 ("12x12", 30480, 31680), ("12x18", 45720, 31680))
_TABLE = [
    (0x10, "Graphire", "graphire", 10206, 7422, 511, 80),
    (0x11, "Graphire2 4x5", "graphire", 10206, 7422, 511, 80),
    (0x12, "Graphire2 5x7", "graphire", 13918, 10206, 511, 80),
    (0x13, "Graphire3", "graphire", 10208, 7424, 511, 80),
    (0x14, "Graphire3 6x8", "graphire", 16704, 12064, 511, 80),
    (0x15, "Graphire4 4x5", "graphire", 10208, 7424, 511, 80),
    (0x16, "Graphire4 6x8", "graphire", 16704, 12064, 511, 80),
    (0x17, "BambooFun 4x5", "graphire", 14760, 9225, 511, 100),
    (0x18, "BambooFun 6x8", "graphire", 21648, 13530, 511, 100),
    (0x60, "Volito", "graphire", 5104, 3712, 511, 50),
    (0x62, "Volito2 4x5", "graphire", 5104, 3712, 511, 50),
    (0x63, "Volito2 2x3", "graphire", 3248, 2320, 511, 50),
    (0x65, "Bamboo", "graphire", 14760, 9225, 511, 100),
    (0xD4, "Bamboo Pen", "bamboo-pen", 14720, 9200, 1023, 100),
    (0x300, "Bamboo One S", "bamboo-pen", 14720, 9225, 1023, 100),
    (0x302, "Intuos PT S", "bamboo-pen", 15200, 9500, 1023, 100),
    (0x30E, "Intuos S (CTL-480)", "bamboo-pen", 15200, 9500, 1023, 100),
    (0x303, "Intuos PT M", "bamboo-pen", 21600, 13500, 1023, 100),
    # Intuos 1 (GD-xxxx-U) and Intuos2 (XD-xxxx-U); the facts give the ends of the range,
    # the sizes in between are the kernel's wacom_wac.c device table.
    *[(pid, f"Intuos{gen} {size}", "intuos", mx, my, 1023, 100)
      for gen, pids in (("", (0x20, 0x21, 0x22, 0x23, 0x24)),
                        ("2", (0x41, 0x42, 0x43, 0x44, 0x45)))
      for pid, (size, mx, my) in zip(pids, _INTUOS_SIZES, strict=True)],
    (0x47, "Intuos2 6x8", "intuos", 20320, 16240, 1023, 100),
]
PROFILES = {pid: WacomProfile(pid, f"Wacom {name}", fam, mx, my, p, r)
            for pid, name, fam, mx, my, p, r in _TABLE}


def profile_for(vendor_id: int, product_id: int) -> WacomProfile | None:
    if vendor_id != WACOM_VID:
        return None
    return PROFILES.get(product_id)


def encode_graphire(event: TabletEvent) -> bytes:
    """A Graphire report for an event (computed vectors for tests; the layout's inverse)."""
    kind = {"pen": 0, "eraser": 1, "puck": 3}[event.tool]
    b1 = (0x80 if event.proximity else 0) | kind << 5 | (event.buttons & 7)
    p = event.pressure or 0
    return bytes((2, b1, event.x & 0xFF, event.x >> 8, event.y & 0xFF, event.y >> 8,
                  p & 0xFF, p >> 8 & 3))


def encode_bamboo_pen(event: TabletEvent) -> bytes:
    b1 = (0x20 if event.proximity else 0) | (0x08 if event.tool == "eraser" else 0)
    b1 |= event.buttons & 7
    p = event.pressure or 0
    return bytes((2, b1, event.x & 0xFF, event.x >> 8, event.y & 0xFF, event.y >> 8,
                  p & 0xFF, p >> 8, 0))
