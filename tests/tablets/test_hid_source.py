"""HidSource through a stand-in ``hid`` module that replays a real capture, then 'unplugs'."""

from __future__ import annotations

import sys
import threading
import time
import types

import pytest

from camlab88.protocols.tablets.input_layer import InputLayer, MouseSample
from camlab88.protocols.tablets.sources import SourceLost, open_source
from tests.tablets.helpers import DIGIMEND, SELFTESTS, load_descriptor, load_dump


class FakeDevice:
    """A stand-in for ``hid.device()``.  ``unplug_when_empty``: once the queued reports are
    read the device is gone (read raises); otherwise it is a pen held still: like hidapi 0.15
    on a blocking device, ``read`` then waits until a report comes -- here until
    ``release()``."""

    def __init__(self, descriptor: bytes, reports: list[bytes],
                 unplug_when_empty: bool = True) -> None:
        self.descriptor = descriptor
        self.reports = list(reports)
        self.unplug_when_empty = unplug_when_empty
        self.features: list[list[int]] = []
        self.opened: object = None
        self.nonblocking = False
        self.timeouts: list[int] = []
        self.closed = False
        self.still = threading.Event()
        self.blocked = threading.Event()  # a read is waiting for a report

    def release(self) -> None:
        self.still.set()

    def set_nonblocking(self, value: int) -> int:
        self.nonblocking = bool(value)
        return 0

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
        self.timeouts.append(timeout_ms)
        if not self.reports:
            if self.unplug_when_empty:
                raise OSError("read error (device unplugged)")
            if timeout_ms == 0 and not self.nonblocking:
                self.blocked.set()
                self.still.wait()
            return []
        return list(self.reports.pop(0))

    def close(self) -> None:
        self.closed = True


def _install(monkeypatch, device: FakeDevice, rows: list[dict]) -> None:
    module = types.SimpleNamespace(device=lambda: device, enumerate=lambda *a: rows)
    install_hid(monkeypatch, module)


def install_hid(monkeypatch, module) -> None:
    """The stand-in as both hidapi modules (hidraw is tried first on Linux)."""
    monkeypatch.setitem(sys.modules, "hid", module)
    monkeypatch.setitem(sys.modules, "hidraw", module)


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
    for _ in range(5):  # reports come from the read thread: a poll may wait for them
        out += layer.poll([MouseSample(0, 0, 0, (10, 10))], timeout=0.2)
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
    (event,) = source.read(1.0)
    assert (event.x, event.y, event.pressure, event.tip) == (0x1234, 0x567, 16, True)
    assert source.model.name == "Wacom Graphire4 4x5"


def test_a_still_pen_never_blocks_the_poll(monkeypatch) -> None:
    desc = load_descriptor(DIGIMEND / "Huion_H610/rd/original0.txt")
    reports = load_dump(DIGIMEND / "Huion_H610/dumps/pen_coords.txt")[:2]
    device = FakeDevice(desc.data, reports, unplug_when_empty=False)
    _install(monkeypatch, device, [{"usage_page": 0x0D, "path": b"/dev/hidraw7"}])
    layer = InputLayer(source=open_source("hid:256c:006e"))
    out = []
    for _ in range(5):  # two reports, then the pen holds still: poll() must come back
        out += layer.poll([], timeout=0.1)
    assert device.blocked.wait(5)  # the read thread is waiting in a blocking read ...
    assert len(out) == 2 and layer.active == "tablet"
    start = time.monotonic()
    assert layer.poll([], timeout=0.05) == []  # ... and the poll still comes back
    assert time.monotonic() - start < 1
    layer.close()
    assert not device.closed  # never freed under the blocked read
    device.release()  # the next report (here: none) ends the read; then it is closed
    for _ in range(100):
        if device.closed:
            break
        time.sleep(0.01)
    assert device.closed


class MultiInterfaceHid:
    """``hid`` with one fake device per hidraw path (a tablet with several interfaces)."""

    def __init__(self, rows: list[dict], devices: dict[bytes, FakeDevice]) -> None:
        self.rows = rows
        self.devices = devices
        self.opened: list[bytes] = []

    def enumerate(self, vid: int = 0, pid: int = 0) -> list[dict]:
        return [r for r in self.rows if vid in (0, r["vendor_id"]) and pid in (0, r["product_id"])]

    def device(self):
        hid = self

        class Handle:
            def open_path(self, path: bytes) -> None:
                hid.opened.append(path)
                self.dev = hid.devices[path]

            def open(self, vid: int, pid: int) -> None:  # hidapi: the first matching interface
                self.open_path(hid.enumerate(vid, pid)[0]["path"])

            def __getattr__(self, name: str):
                return getattr(self.dev, name)

        return Handle()


def _pth660_rows() -> list[dict]:
    common = {"vendor_id": 0x056A, "product_id": 0x0357, "manufacturer_string": "Wacom Co.,Ltd.",
              "product_string": "Intuos Pro M", "usage": 1}
    return [
        {**common, "path": b"/dev/hidraw3", "usage_page": 0xFF0D, "interface_number": 0},
        {**common, "path": b"/dev/hidraw4", "usage_page": 0x01, "usage": 2,
         "interface_number": 1},
        {**common, "path": b"/dev/hidraw4", "usage_page": 0xFF0D, "interface_number": 1},
        {"vendor_id": 0x046D, "product_id": 0xC52B, "path": b"/dev/hidraw0", "usage_page": 0x01,
         "usage": 2, "interface_number": 0},
    ]


def test_newer_wacom_on_the_vendor_page_is_listed_and_its_pen_interface_found(monkeypatch):
    from camlab88.protocols.tablets.hid_decode import DG_TIP_PRESSURE, GD_X, GD_Y, encode_report
    from camlab88.protocols.tablets.hid_source import list_digitizers

    pth660 = load_descriptor(SELFTESTS / "wacom_pth660_v145.hex")
    no_pen = load_descriptor(DIGIMEND / "Huion_H610/rd/original2.txt")  # an interface without
    report = encode_report(pth660, 0x10, {GD_X: 22400, GD_Y: 14800, DG_TIP_PRESSURE: 4000,
                                          0x0D0042: 1, 0x0D0032: 1})
    devices = {b"/dev/hidraw3": FakeDevice(no_pen.data, [], unplug_when_empty=False),
               b"/dev/hidraw4": FakeDevice(pth660.data, [report], unplug_when_empty=False)}
    hid = MultiInterfaceHid(_pth660_rows(), devices)
    install_hid(monkeypatch, hid)
    listed, note = list_digitizers()
    assert note is None
    assert [(d.source, d.path, d.usage_page) for d in listed] == [
        ("hid:056a:0357", b"/dev/hidraw3", 0xFF0D), ("hid:056a:0357", b"/dev/hidraw4", 0xFF0D)]
    source = open_source("hid:056a:0357")
    assert hid.opened == [b"/dev/hidraw3", b"/dev/hidraw4"]  # tried in turn
    assert devices[b"/dev/hidraw3"].closed and not devices[b"/dev/hidraw4"].closed
    (event,) = source.read(0.0)
    assert (event.x, event.y, event.pressure, event.tip) == (22400, 14800, 4000, True)
    assert source.model.max_x == 44800


def test_no_interface_with_a_pen_says_which_were_tried(monkeypatch) -> None:
    no_pen = load_descriptor(DIGIMEND / "Huion_H610/rd/original2.txt")
    devices = {p: FakeDevice(no_pen.data, []) for p in (b"/dev/hidraw3", b"/dev/hidraw4")}
    install_hid(monkeypatch, MultiInterfaceHid(_pth660_rows(), devices))
    with pytest.raises(SourceLost, match="hidraw3.*no pen report.*hidraw4.*no pen report"):
        open_source("hid:056a:0357")


def test_intuos_1_and_2_pid_table_is_complete() -> None:
    from camlab88.protocols.tablets.hid_profiles import profile_for

    for pids in ((0x20, 0x21, 0x22, 0x23, 0x24), (0x41, 0x42, 0x43, 0x44, 0x45)):
        sizes = [(profile_for(0x56A, p).max_x, profile_for(0x56A, p).max_y) for p in pids]
        assert sizes[0] == (12700, 10600) and sizes[-1] == (45720, 31680)
        assert sizes == sorted(sizes, key=lambda s: s[0] * s[1])  # 4x5 ... 12x18
    assert profile_for(0x56A, 0x47).family == "intuos"


def test_permission_denied_names_the_node_and_the_udev_rule(monkeypatch) -> None:
    """A hidraw node the user may not open (tests run as root, which may open anything, so
    the node's access check is stood in for)."""
    from camlab88.protocols.tablets import hid_backend

    class Refusing(FakeDevice):
        def open_path(self, path: bytes) -> None:
            raise OSError("open failed")  # all hidapi says

    device = Refusing(b"", [])
    _install(monkeypatch, device, [{"usage_page": 0x0D, "path": b"/dev/hidraw7"}])
    monkeypatch.setattr(hid_backend.os.path, "exists", lambda p: p == "/dev/hidraw7")
    monkeypatch.setattr(hid_backend.os, "access", lambda p, mode: False)
    with pytest.raises(SourceLost) as info:
        open_source("hid:256c:006e")
    text = str(info.value)
    assert "permission denied on /dev/hidraw7" in text
    assert 'ATTRS{idVendor}=="256c", ATTRS{idProduct}=="006e", MODE="0660"' in text
    assert "udevadm control --reload" in text


def test_absent_device_lists_what_hidapi_sees(monkeypatch) -> None:
    rows = [{"vendor_id": 0x046D, "product_id": 0xC077, "path": b"/dev/hidraw0",
             "product_string": "USB Optical Mouse"}]
    module = types.SimpleNamespace(device=lambda: None,
                                   enumerate=lambda vid=0, pid=0: [] if vid else rows)
    install_hid(monkeypatch, module)
    with pytest.raises(SourceLost, match=r"no device 056a:0010 \(found: 046d:c077 USB Optical "
                       r"Mouse\)"):
        open_source("hid:056a:0010")
