"""Decode HID input reports with a parsed descriptor, and turn pen reports into events."""

from __future__ import annotations

from dataclasses import dataclass

from camlab88.protocols.tablets.events import TabletEvent, TabletModel
from camlab88.protocols.tablets.hid_descriptor import HidField, ReportDescriptor, canonical_usage

GD_X, GD_Y = 0x010030, 0x010031
GD_MOUSE = 0x010002
DG_PEN, DG_DIGITIZER, DG_PUCK = 0x0D0002, 0x0D0001, 0x0D0021
DG_TOUCH_SCREEN, DG_TOUCH_PAD, DG_STYLUS, DG_FINGER = 0x0D0004, 0x0D0005, 0x0D0020, 0x0D0022
PEN_COLLECTIONS = {DG_DIGITIZER, DG_PEN, DG_STYLUS, DG_PUCK}
TOUCH_COLLECTIONS = {DG_TOUCH_SCREEN, DG_TOUCH_PAD, DG_FINGER}
DG_TIP_PRESSURE, DG_IN_RANGE, DG_DATA_VALID = 0x0D0030, 0x0D0032, 0x0D0037
DG_INVERT, DG_TILT_X, DG_TILT_Y = 0x0D003C, 0x0D003D, 0x0D003E
DG_TIP, DG_TIP2, DG_BARREL, DG_ERASER = 0x0D0042, 0x0D0043, 0x0D0044, 0x0D0045
DG_TABLET_PICK, DG_BARREL2 = 0x0D0046, 0x0D005A
BUTTON_1, BUTTON_2, BUTTON_3 = 0x090001, 0x090002, 0x090003


class HidReportError(ValueError):
    """A report that does not fit the descriptor (message names the report ID and sizes)."""


def extract(payload: bytes, bit_offset: int, size: int, signed: bool) -> int:
    """Little-endian bit field, as HID packs it."""
    end_byte = (bit_offset + size + 7) // 8
    chunk = int.from_bytes(payload[bit_offset // 8 : end_byte], "little")
    value = chunk >> (bit_offset % 8) & ((1 << size) - 1)
    if signed and size and value & (1 << (size - 1)):
        value -= 1 << size
    return value


def insert(payload: bytearray, bit_offset: int, size: int, value: int) -> None:
    """The inverse of :func:`extract` (used to build computed reports)."""
    value &= (1 << size) - 1
    for k in range(size):
        byte, bit = divmod(bit_offset + k, 8)
        if value >> k & 1:
            payload[byte] |= 1 << bit
        else:
            payload[byte] &= ~(1 << bit) & 0xFF


@dataclass(frozen=True)
class DecodedReport:
    report_id: int
    values: dict[int, list[int]]  # canonical usage -> values (a usage may occur twice)
    extra_bytes: int  # bytes past what the descriptor describes (kept, not decoded)

    def get(self, usage: int, default: int | None = None) -> int | None:
        found = self.values.get(usage)
        return found[0] if found else default

    def any(self, usage: int) -> bool:
        return any(self.values.get(usage, ()))


class ReportDecoder:
    def __init__(self, descriptor: ReportDescriptor) -> None:
        self.descriptor = descriptor
        self._fields: dict[int, list[HidField]] = {}
        for f in descriptor.fields:
            if f.kind == "input":
                self._fields.setdefault(f.report_id, []).append(f)

    def split(self, report: bytes) -> tuple[int, bytes]:
        if not report:
            raise HidReportError("empty report")
        if self.descriptor.uses_report_ids:
            return report[0], report[1:]
        return 0, report

    def decode(self, report: bytes) -> DecodedReport:
        report_id, payload = self.split(report)
        fields = self._fields.get(report_id)
        if fields is None:
            raise HidReportError(f"report ID {report_id:#04x} is not an input report of this "
                                 f"descriptor (known: {sorted(self._fields)})")
        need = (self.descriptor.report_bits(report_id) + 7) // 8
        if len(payload) < need:
            raise HidReportError(f"report ID {report_id:#04x}: {len(payload)} payload bytes, "
                                 f"descriptor needs {need}")
        values: dict[int, list[int]] = {}
        for f in fields:
            if f.constant or not f.usages:
                continue
            for k in range(f.count):
                raw = extract(payload, f.bit_offset + k * f.size, f.size, f.signed)
                if f.variable:
                    values.setdefault(canonical_usage(f.usage_at(k)), []).append(raw)
                elif f.logical_min <= raw <= f.logical_max and raw - f.logical_min < len(f.usages):
                    values.setdefault(canonical_usage(f.usages[raw - f.logical_min]), []).append(1)
        return DecodedReport(report_id, values, len(payload) - need)


def _has(fields: list[HidField], usage: int) -> HidField | None:
    for f in fields:
        if f.variable and any(canonical_usage(u) == usage for u in f.usages):
            return f
    return None


class PenDecoder:
    """Finds the pen reports in a descriptor and decodes them.

    A pen report has absolute X and Y in a Digitizer, Pen, Stylus or Puck collection; a report
    whose X is in a Finger collection or a Touch Screen / Touch Pad application is a touch report
    (``touch_reports``), never a pen: a finger must not draw (N-Trig, Atmel and Goodix
    pen+touch screens send both).  A report outside any digitizer collection that still carries
    digitizer usages (Huion H610's report 9, a pen described as a mouse) is a pen too.

    Buttons follow Linux hid-input's pen mapping: bit 0 contact (Tip Switch, Eraser under
    Invert, or Button 1 on pens that describe themselves as a mouse), bit 1 Barrel Switch
    (or Button 2), bit 2 the second barrel button (Secondary Barrel Switch, Tablet Pick, an
    Eraser bit without Invert -- how the Gaomon M106K reports its second side button -- or
    Button 3).  In Range gives proximity; a report without it is taken as in proximity.
    """

    def __init__(self, descriptor: ReportDescriptor) -> None:
        self.descriptor = descriptor
        self.decoder = ReportDecoder(descriptor)
        self.pen_reports: dict[int, TabletModel] = {}
        self.touch_reports: list[int] = []
        for rid in descriptor.report_ids("input"):
            fields = descriptor.fields_for(rid)
            fx, fy = _has(fields, GD_X), _has(fields, GD_Y)
            if fx is None or fy is None or fx.flags & 0x04:  # relative X = a mouse
                continue
            within = {canonical_usage(c) for c in fx.collections}
            if within & TOUCH_COLLECTIONS:
                self.touch_reports.append(rid)
                continue
            digitizer = any(
                canonical_usage(u) >> 16 == 0x0D for f in fields for u in f.usages
            )
            in_digitizer = any(c >> 16 == 0x0D for c in within)
            if not (within & PEN_COLLECTIONS or (digitizer and not in_digitizer)):
                continue
            pressure = _has(fields, DG_TIP_PRESSURE)
            res = fx.resolution_per_mm()
            self.pen_reports[rid] = TabletModel(
                f"HID pen report {rid:#04x}", fx.logical_max, fy.logical_max,
                res * 25.4 if res else 0.0, pressure.logical_max if pressure else None,
                None,
            )

    def decode(self, report: bytes, timestamp: float = 0.0) -> TabletEvent | None:
        """The event in a pen report; None for reports that are not pen reports."""
        report_id, _ = self.decoder.split(report)
        if report_id not in self.pen_reports:
            return None
        r = self.decoder.decode(report)
        invert = r.any(DG_INVERT)
        eraser_bits = r.values.get(DG_ERASER, [])
        contact = r.any(DG_TIP) or (invert and any(eraser_bits)) or r.any(BUTTON_1)
        second = (
            r.any(DG_BARREL2) or r.any(DG_TABLET_PICK) or r.any(BUTTON_3)
            or (not invert and any(eraser_bits))
        )
        buttons = (1 if contact else 0) | (2 if r.any(DG_BARREL) or r.any(BUTTON_2) else 0)
        buttons |= 4 if second else 0
        buttons |= 8 if r.any(DG_TIP2) else 0
        proximity = bool(r.get(DG_IN_RANGE, 1))
        fields = self.descriptor.fields_for(report_id)
        puck = any(DG_PUCK in map(canonical_usage, f.collections) for f in fields)
        tool = "eraser" if invert else "puck" if puck else "pen"
        return TabletEvent(
            r.get(GD_X, 0) or 0, r.get(GD_Y, 0) or 0, proximity, buttons,
            r.get(DG_TIP_PRESSURE), r.get(DG_TILT_X), r.get(DG_TILT_Y), tool, timestamp,
        )


def encode_report(descriptor: ReportDescriptor, report_id: int,
                  values: dict[int, int | list[int]]) -> bytes:
    """Build an input report from usage values (for computed test vectors and emulation)."""
    length = (descriptor.report_bits(report_id) + 7) // 8
    payload = bytearray(length)
    used: dict[int, int] = {}
    for f in descriptor.fields_for(report_id):
        if f.constant or not f.variable:
            continue
        for k in range(f.count):
            usage = canonical_usage(f.usage_at(k))
            if usage not in values:
                continue
            wanted = values[usage]
            if isinstance(wanted, list):
                n = used.get(usage, 0)
                if n >= len(wanted):
                    continue
                value, used[usage] = wanted[n], n + 1
            else:
                value = wanted
            insert(payload, f.bit_offset + k * f.size, f.size, value)
    prefix = bytes((report_id,)) if descriptor.uses_report_ids else b""
    return prefix + bytes(payload)
