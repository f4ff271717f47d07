"""Wacom vendor profiles (computed reports from the kernel's layouts) and hidapi enumeration."""

from __future__ import annotations

import sys
import types

from camlab88.protocols.tablets import hid_source
from camlab88.protocols.tablets.events import TabletEvent
from camlab88.protocols.tablets.hid_profiles import (
    MODE_SWITCH,
    encode_bamboo_pen,
    encode_graphire,
    profile_for,
)


def test_mode_switch_is_feature_report_2_value_2() -> None:
    profile = profile_for(0x056A, 0x10)
    assert profile is not None and profile.family == "graphire"
    assert profile.init_feature_report == MODE_SWITCH == b"\x02\x02"
    assert profile_for(0x256C, 0x006E) is None


def test_graphire_layout() -> None:
    decode = profile_for(0x056A, 0x15).make_decoder()
    # computed from wacom_graphire_irq: prox, pen, tip, X 0x1234, Y 0x0567, pressure 0x1FF
    report = bytes((2, 0x81, 0x34, 0x12, 0x67, 0x05, 0xFF, 0x01))
    event = decode(report, 0.0)
    assert (event.x, event.y, event.pressure, event.tip, event.tool) == (
        0x1234, 0x567, 511, True, "pen")
    eraser = TabletEvent(10, 20, True, 1, 300, tool="eraser")
    assert decode(encode_graphire(eraser), 0.0) == eraser
    assert decode(b"\x01" + bytes(7), 0.0) is None  # not the pen report


def test_bamboo_pen_layout() -> None:
    decode = profile_for(0x056A, 0x30E).make_decoder()
    event = TabletEvent(15200, 9500, True, 0b011, 1023, tool="pen")
    assert decode(encode_bamboo_pen(event), 0.0) == event


def test_intuos_enter_then_general_packet() -> None:
    decode = profile_for(0x056A, 0x20).make_decoder()
    enter = bytes((2, 0xC2, 0x82, 0x20, 0, 0, 0, 0, 0, 0))  # tool id 0x822 = pen
    assert decode(enter, 0.0) is None
    x, y = 5000, 4000
    general = bytes((2, 0x00, x >> 8, x & 0xFF, y >> 8, y & 0xFF, 0x40, 0x00, 0x40, 0x00))
    event = decode(general, 0.0)
    assert (event.x, event.y, event.tool) == (5000, 4000, "pen")
    assert event.pressure == (0x40 << 3) >> 1 and event.tip
    out = decode(bytes((2, 0x80, 0, 0, 0, 0, 0, 0, 0, 0)), 0.0)
    assert out is not None and not out.proximity


def test_list_digitizers_never_raises(monkeypatch) -> None:
    devices, note = hid_source.list_digitizers()  # the real hidapi, whatever this machine has
    assert isinstance(devices, list)

    def broken(*a, **k):
        raise OSError("no hidraw access")

    fake = types.SimpleNamespace(enumerate=broken)
    monkeypatch.setitem(sys.modules, "hid", fake)
    monkeypatch.setitem(sys.modules, "hidraw", fake)
    devices, note = hid_source.list_digitizers()
    assert devices == [] and "no hidraw access" in note


def test_list_digitizers_filters_usage_page(monkeypatch) -> None:
    rows = [
        {"vendor_id": 0x256C, "product_id": 0x6E, "path": b"/dev/hidraw3", "usage_page": 0x0D,
         "usage": 2, "interface_number": 1, "manufacturer_string": "Huion",
         "product_string": "H610"},
        {"vendor_id": 0x046D, "product_id": 0xC077, "path": b"/dev/hidraw0", "usage_page": 1,
         "usage": 2, "interface_number": 0, "manufacturer_string": "Logitech",
         "product_string": "Mouse"},
        {"vendor_id": 0x056A, "product_id": 0x10, "path": b"/dev/hidraw5", "usage_page": 1,
         "usage": 2, "interface_number": 0, "manufacturer_string": "Wacom",
         "product_string": "Graphire"},
    ]
    fake = types.SimpleNamespace(enumerate=lambda *a: rows)
    monkeypatch.setitem(sys.modules, "hid", fake)
    monkeypatch.setitem(sys.modules, "hidraw", fake)
    devices, note = hid_source.list_digitizers()
    assert [d.source for d in devices] == ["hid:256c:006e", "hid:056a:0010"]
    assert note is None and "Huion H610" in devices[0].describe()
