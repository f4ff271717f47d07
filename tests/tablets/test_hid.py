"""HID descriptor parsing and pen-report decoding on REAL descriptors and captured reports.

Expected values come from the decoding notes in tests/data/tablets/SOURCES.md (written from
the descriptors by hand); each capture is checked report by report against a small struct-
based reading of those notes, independent of the descriptor-driven decoder under test.
"""

from __future__ import annotations

import struct

import pytest

from camlab88.protocols.tablets.hid_decode import (
    DG_TIP_PRESSURE,
    GD_X,
    GD_Y,
    HidReportError,
    PenDecoder,
    ReportDecoder,
    encode_report,
)
from camlab88.protocols.tablets.hid_descriptor import HidDescriptorError, parse_descriptor
from tests.tablets.helpers import DIGIMEND, SELFTESTS, load_descriptor, load_dump

# --- descriptors ---------------------------------------------------------------------------

ALL_DESCRIPTORS = sorted(DIGIMEND.glob("*/rd/*.txt")) + sorted(SELFTESTS.glob("*.hex"))
SIZES = {"Huion_H610/rd/original0.txt": 179, "Huion_H610/rd/original1.txt": 244,
         "Huion_H610/rd/original2.txt": 92, "Gaomon_M106K/rd/original0.txt": 18,
         "Gaomon_M106K/rd/original1.txt": 83, "10moons_10x6/rd/original1.txt": 89,
         "10moons_10x6/rd/original2.txt": 244, "Aiptek_APT-2/rd/original.txt": 328,
         "wacom_pth660_v145.hex": 949, "wacom_pth860_v145.hex": 948,
         "wacom_pth460_v105.hex": 1027}


@pytest.mark.parametrize("path", ALL_DESCRIPTORS, ids=lambda p: f"{p.parent.parent.name}/{p.name}")
def test_every_real_descriptor_parses(path) -> None:
    desc = load_descriptor(path)
    key = next((k for k in SIZES if str(path).endswith(k)), None)
    if key:
        assert len(desc.data) == SIZES[key]  # = wDescriptorLength / the kernel's array size
    assert desc.fields


def test_huion_h610_descriptor_push_pop_and_units() -> None:
    desc = load_descriptor(DIGIMEND / "Huion_H610/rd/original0.txt")
    assert desc.report_ids() == [7, 9]
    (x,) = [f for f in desc.fields_for(7) if GD_X in f.usages]
    (y,) = [f for f in desc.fields_for(7) if GD_Y in f.usages]
    assert (x.logical_max, x.physical_max, x.unit, x.unit_exponent) == (40000, 10000, 0x13, -3)
    assert round(x.resolution_per_mm() * 25.4) == 4000  # 4000 lpi, as index.md says
    assert (y.logical_max, y.physical_max) == (25000, 6250)
    (pressure,) = [f for f in desc.fields_for(7) if DG_TIP_PRESSURE in f.usages]
    assert (pressure.logical_max, pressure.unit, pressure.unit_exponent) == (2047, 0xE111, 0)
    assert desc.report_length(9) == 8


def test_push_pop_restores_globals() -> None:
    # Usage Page GD, Collection, Report Size 8, Count 1, Logical Max 10, Push, Logical Max 99,
    # Usage X, Input, Pop, Usage Y, Input, End Collection
    data = bytes.fromhex("05 01 09 02 a1 01 75 08 95 01 25 0a a4 25 63 09 30 81 02 b4"
                         " 09 31 81 02 c0")
    x, y = parse_descriptor(data).fields
    assert (x.logical_max, y.logical_max, y.bit_offset) == (99, 10, 8)


def test_10moons_logical_max_ff_reads_unsigned_and_63_bit_field() -> None:
    desc = load_descriptor(DIGIMEND / "10moons_10x6/rd/original2.txt")
    vendor = desc.fields_for(1)
    assert vendor and all(f.logical_max == 255 for f in vendor)  # "25 FF" with min 0
    odd = load_descriptor(DIGIMEND / "10moons_10x6/rd/original1.txt")
    assert any(f.size == 63 for f in odd.fields_for(6))


def test_wacom_pth660_vendor_page_pen() -> None:
    desc = load_descriptor(SELFTESTS / "wacom_pth660_v145.hex")
    assert desc.report_length(0x10) == 27
    fields = {f.bit_offset: f for f in desc.fields_for(0x10)}
    x, y, p = fields[8], fields[32], fields[56]
    assert (x.size, x.logical_max, x.physical_max, x.unit, x.unit_exponent) == (
        24, 44800, 22400, 0x11, -3)
    assert x.resolution_per_mm() == pytest.approx(200.0)
    assert (y.logical_max, p.logical_max) == (29600, 8191)
    tilt = fields[72]
    assert (tilt.count, tilt.logical_min, tilt.logical_max) == (2, -64, 63)
    assert (fields[88].logical_min, fields[88].logical_max) == (-900, 899)  # twist


def test_wacom_pen_report_computed_from_descriptor_decodes() -> None:
    # No captured reports exist for these Wacoms: build one from the descriptor (computed).
    desc = load_descriptor(SELFTESTS / "wacom_pth660_v145.hex")
    pen = PenDecoder(desc)
    assert 0x10 in pen.pen_reports
    model = pen.pen_reports[0x10]
    assert (model.max_x, model.max_y, model.pressure_max) == (44800, 29600, 8191)
    report = encode_report(desc, 0x10, {GD_X: 22400, GD_Y: 14800, DG_TIP_PRESSURE: 4000,
                                        0x0D0042: 1, 0x0D0032: 1, 0x0D003D: -20,
                                        0x0D003E: 31})
    assert len(report) == 27 and report[0] == 0x10
    event = pen.decode(report)
    assert (event.x, event.y, event.pressure, event.tip, event.proximity) == (
        22400, 14800, 4000, True, True)
    assert (event.tilt_x, event.tilt_y, event.tool) == (-20, 31, "pen")
    eraser = pen.decode(encode_report(desc, 0x10, {GD_X: 1, GD_Y: 2, 0x0D003C: 1,
                                                   0x0D0045: 1, 0x0D0032: 1}))
    assert eraser.tool == "eraser" and eraser.tip


# --- captured reports ------------------------------------------------------------------------


def _notes_huion(r: bytes):
    x, y, p = struct.unpack_from("<HHH", r, 2)
    return x, y, p, r[1] & 1, True


def _notes_gaomon(r: bytes):
    x, y, p = struct.unpack_from("<HHH", r, 2)
    return x, y, p, r[1] & 1, bool(r[1] & 0x40)


def _notes_10moons(r: bytes):
    x, y, p = struct.unpack_from("<HHH", r, 2)
    return x, y, p, r[1] & 1, bool(r[1] & 0x40)


def _notes_aiptek(r: bytes):
    x, y = struct.unpack_from("<HH", r, 1)
    (p,) = struct.unpack_from("<H", r, 6)
    return x, y, p, r[5] >> 2 & 1, bool(r[5] & 1)


CAPTURES = [
    ("Huion_H610", "original0", ["pen_coords", "pen_pressure"], 0x09, _notes_huion),
    ("Gaomon_M106K", "original1", ["pen_cords", "pen_pressure", "pen_buttons"], 0x0A,
     _notes_gaomon),
    ("10moons_10x6", "original2", ["pen_coords", "pen_pressure"], 0x05, _notes_10moons),
    ("Aiptek_APT-2", "original", ["pen_coords", "pen_pressure", "pen_buttons"], 0x02,
     _notes_aiptek),
]


@pytest.mark.parametrize(("tablet", "rd", "dumps", "pen_id", "notes"), CAPTURES,
                         ids=[c[0] for c in CAPTURES])
def test_captured_reports_decode_as_the_notes_say(tablet, rd, dumps, pen_id, notes) -> None:
    pen = PenDecoder(load_descriptor(DIGIMEND / tablet / "rd" / f"{rd}.txt"))
    decoded = 0
    contacts = 0
    for dump in dumps:
        for report in load_dump(DIGIMEND / tablet / "dumps" / f"{dump}.txt"):
            event = pen.decode(report)
            if report[0] != pen_id:
                continue  # vendor/mouse/keyboard reports of the same interface
            assert event is not None
            x, y, p, tip, prox = notes(report)
            assert (event.x, event.y, event.pressure, event.tip, event.proximity) == (
                x, y, p, bool(tip), prox), report.hex(" ")
            decoded += 1
            contacts += event.tip
    assert decoded > 60 and contacts > 0


def test_huion_first_reports() -> None:
    pen = PenDecoder(load_descriptor(DIGIMEND / "Huion_H610/rd/original0.txt"))
    first = pen.decode(bytes.fromhex("09 00 33 04 39 03 00 00"))
    assert (first.x, first.y, first.pressure, first.buttons) == (0x0433, 0x0339, 0, 0)
    touching = [e for e in map(pen.decode, load_dump(DIGIMEND / "Huion_H610/dumps/"
                                                     "pen_pressure.txt")) if e.tip]
    assert touching and max(e.pressure for e in touching) > 0


def test_gaomon_side_buttons() -> None:
    pen = PenDecoder(load_descriptor(DIGIMEND / "Gaomon_M106K/rd/original1.txt"))
    reports = load_dump(DIGIMEND / "Gaomon_M106K/dumps/pen_buttons.txt")
    seen = {r[1]: pen.decode(r).buttons for r in reports}
    assert seen[0xC0] == 0  # hovering (padding bit sent as 1 is ignored)
    assert seen[0xC2] == 0b010  # side button 1 = Barrel Switch
    assert seen[0xC4] == 0b100  # side button 2, sent as the Eraser usage without Invert
    assert all(pen.decode(r).tool == "pen" for r in reports)


def test_aiptek_buttons_and_hover_pressure() -> None:
    pen = PenDecoder(load_descriptor(DIGIMEND / "Aiptek_APT-2/rd/original.txt"))
    reports = [r for r in load_dump(DIGIMEND / "Aiptek_APT-2/dumps/pen_buttons.txt")
               if r[0] == 2]
    by_status = {r[5]: pen.decode(r) for r in reports}
    assert by_status[0x0B].buttons == 0b010  # barrel
    assert by_status[0x13].buttons == 0b100  # Tablet Pick = second button
    hover = [pen.decode(r) for r in reports if r[5] == 0x03]
    assert any(e.pressure for e in hover) and not any(e.tip for e in hover)


def test_aiptek_report_4_is_longer_than_described() -> None:
    desc = load_descriptor(DIGIMEND / "Aiptek_APT-2/rd/original.txt")
    report = bytes.fromhex("04 07 02 0C 84 01 84 01")
    assert desc.report_length(4) == 6
    decoded = ReportDecoder(desc).decode(report)
    assert decoded.extra_bytes == 2 and decoded.get(DG_TIP_PRESSURE) == 0x0184
    assert PenDecoder(desc).decode(report) is None  # no X/Y: not a pen position report
    with pytest.raises(HidReportError, match="report ID 0x04"):
        ReportDecoder(desc).decode(report[:4])


def test_10moons_vendor_reports_are_not_pen_events() -> None:
    pen = PenDecoder(load_descriptor(DIGIMEND / "10moons_10x6/rd/original2.txt"))
    reports = load_dump(DIGIMEND / "10moons_10x6/dumps/pen_coords.txt")
    assert {r[0] for r in reports} == {1, 5}
    assert all(pen.decode(r) is None for r in reports if r[0] == 1)


# --- bad input ------------------------------------------------------------------------------


def test_truncated_descriptor_names_the_offset() -> None:
    data = load_descriptor(DIGIMEND / "Huion_H610/rd/original0.txt").data
    with pytest.raises(HidDescriptorError, match=r"x\.rd: byte \d+"):
        parse_descriptor(data[:-3] + b"\x26", "x.rd")
    with pytest.raises(HidDescriptorError, match="not closed"):
        parse_descriptor(data[:40], "x.rd")
    with pytest.raises(HidDescriptorError, match="Pop without Push"):
        parse_descriptor(bytes.fromhex("b4"), "x.rd")
    with pytest.raises(HidDescriptorError, match="End Collection"):
        parse_descriptor(bytes.fromhex("c0"), "x.rd")


def test_unknown_report_id() -> None:
    desc = load_descriptor(DIGIMEND / "Huion_H610/rd/original0.txt")
    with pytest.raises(HidReportError, match="0x63"):
        ReportDecoder(desc).decode(b"\x63\x00")


PEN_DESCRIPTORS = [
    (DIGIMEND / "Huion_H610/rd/original0.txt", 0x07),
    (DIGIMEND / "Gaomon_M106K/rd/original1.txt", 0x0A),
    (DIGIMEND / "10moons_10x6/rd/original2.txt", 0x05),
    (DIGIMEND / "Aiptek_APT-2/rd/original.txt", 0x02),
    (SELFTESTS / "wacom_pth660_v145.hex", 0x10),
    (SELFTESTS / "wacom_pth460_v105.hex", 0x10),
]


@pytest.mark.parametrize(("path", "rid"), PEN_DESCRIPTORS, ids=lambda v: getattr(v, "name", v))
def test_descriptor_driven_round_trip(path, rid) -> None:
    from hypothesis import given, settings
    from hypothesis import strategies as st

    desc = load_descriptor(path)
    pen = PenDecoder(desc)
    model = pen.pen_reports[rid]

    @settings(max_examples=30, deadline=None)
    @given(st.integers(0, model.max_x), st.integers(0, model.max_y),
           st.integers(0, model.pressure_max or 0), st.booleans(), st.booleans())
    def check(x, y, p, tip, barrel) -> None:
        report = encode_report(desc, rid, {GD_X: x, GD_Y: y, DG_TIP_PRESSURE: p,
                                           0x0D0042: int(tip), 0x0D0044: int(barrel),
                                           0x0D0032: 1})
        assert len(report) == desc.report_length(rid)
        event = pen.decode(report)
        assert (event.x, event.y, event.tip, bool(event.buttons & 2)) == (x, y, tip, barrel)
        assert event.pressure == (p if model.pressure_max else None)

    check()
