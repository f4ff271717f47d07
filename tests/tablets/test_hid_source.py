"""HidSource through a stand-in ``hid`` module that replays a real capture, then 'unplugs'."""

from __future__ import annotations

import sys
import types

import pytest

from protocols.tablets.input_layer import InputLayer, MouseSample
from protocols.tablets.sources import SourceLost, open_source
from tests.tablets.helpers import DIGIMEND, load_descriptor, load_dump


class FakeDevice:
    def __init__(self, descriptor: bytes, reports: list[bytes]) -> None:
        self.descriptor = descriptor
        self.reports = list(reports)
        self.features: list[list[int]] = []
        self.opened: object = None

    def open_path(self, path: bytes) -> None:
        self.opened = path

    def open(self, vid: int, pid: int) -> None:
        self.opened = (vid, pid)

    def get_report_descriptor(self) -> list[int]:
        return list(self.descriptor)

    def send_feature_report(self, data: list[int]) -> int:
        self.features.append(list(data))
        return len(data)

    def read(self, size: int, timeout_ms: int = 0) -> list[int]:
        if not self.reports:
            raise OSError("read error (device unplugged)")
        return list(self.reports.pop(0))

    def close(self) -> None:
        pass


def _install(monkeypatch, device: FakeDevice, rows: list[dict]) -> None:
    module = types.SimpleNamespace(device=lambda: device, enumerate=lambda *a: rows)
    monkeypatch.setitem(sys.modules, "hid", module)


def test_huion_capture_through_hid_source_then_unplug(monkeypatch) -> None:
    desc = load_descriptor(DIGIMEND / "Huion_H610/rd/original0.txt")
    reports = load_dump(DIGIMEND / "Huion_H610/dumps/pen_coords.txt")
    device = FakeDevice(desc.data, reports)
    _install(monkeypatch, device, [{"usage_page": 0x0D, "path": b"/dev/hidraw7"}])
    raw: list[bytes] = []
    source = open_source("hid:256c:006e", on_raw=raw.append)
    assert device.opened == b"/dev/hidraw7"
    events = []
    with pytest.raises(SourceLost, match="unplugged"):
        while True:
            events += source.read(0.01)
    assert len(events) == len(reports) == len(raw)
    assert (events[0].x, events[0].y) == (0x0433, 0x0339)
    assert source.model.max_x == 2048  # the model of report 9, the one this tablet sends


def test_input_layer_falls_back_when_the_hid_tablet_goes(monkeypatch) -> None:
    desc = load_descriptor(DIGIMEND / "Gaomon_M106K/rd/original1.txt")
    contact = [r for r in load_dump(DIGIMEND / "Gaomon_M106K/dumps/pen_cords.txt")
               if r[1] == 0xC1][:3]
    device = FakeDevice(desc.data, contact)
    _install(monkeypatch, device, [{"usage_page": 0x0D, "path": b"/dev/hidraw2"}])
    notes: list[str] = []
    layer = InputLayer(source=open_source("hid:256c:006e"), notify=notes.append)
    out = []
    for _ in range(5):
        out += layer.poll([MouseSample(0, 0, 0, (10, 10))])
    kinds = [(e.kind, e.source) for e in out]
    assert kinds[:3] == [("press", "tablet"), ("move", "tablet"), ("move", "tablet")]
    assert kinds[3] == ("release", "tablet") and len(notes) == 1
    assert ("move", "mouse") in kinds[4:]


def test_legacy_wacom_gets_the_mode_switch(monkeypatch) -> None:
    report = bytes((2, 0x81, 0x34, 0x12, 0x67, 0x05, 0x10, 0x00))
    device = FakeDevice(b"", [report])
    _install(monkeypatch, device, [{"usage_page": 0x01, "path": b"/dev/hidraw1"}])
    source = open_source("hid:056a:0015")
    assert device.features == [[2, 2]] and device.opened == (0x56A, 0x15)
    (event,) = source.read(0.01)
    assert (event.x, event.y, event.pressure, event.tip) == (0x1234, 0x567, 16, True)
    assert source.model.name == "Wacom Graphire4 4x5"
