"""USB HID tablets through hidapi (``camlab88.protocols.tablets.hid_backend`` picks its module:
hidraw on Linux, libusb only as a fallback); reports come through a blocking-read pump
(``camlab88.protocols.tablets.hid_pump``)."""

from __future__ import annotations

import sys
import time
from collections.abc import Callable
from dataclasses import dataclass

from camlab88.protocols.tablets.events import TabletEvent
from camlab88.protocols.tablets.hid_backend import (
    NoBackend,
    absent_message,
    cannot_open_message,
    hid_backend,
)
from camlab88.protocols.tablets.hid_decode import PenDecoder
from camlab88.protocols.tablets.hid_descriptor import parse_descriptor
from camlab88.protocols.tablets.hid_profiles import profile_for
from camlab88.protocols.tablets.hid_pump import ReportPump
from camlab88.protocols.tablets.sources import SourceLost, SourceSpec, TabletSource

DIGITIZER_PAGE = 0x0D
WACOM_PAGE = 0xFF0D  # newer Wacoms mirror the digitizer usages on this vendor page
WACOM_VID = 0x056A


@dataclass(frozen=True)
class HidDeviceInfo:
    vendor_id: int
    product_id: int
    path: bytes
    usage_page: int
    usage: int
    interface: int
    manufacturer: str
    product: str

    @property
    def source(self) -> str:
        return f"hid:{self.vendor_id:04x}:{self.product_id:04x}"

    def describe(self) -> str:
        who = " ".join(s for s in (self.manufacturer, self.product) if s) or "(no name)"
        return (f"{self.source}  {who}  usage {self.usage_page:#06x}:{self.usage:#04x}  "
                f"interface {self.interface}  {self.path.decode(errors='replace')}")


def backend_name() -> str:
    """What ``tablet list`` prints: the backend in use, or why there is none."""
    try:
        return hid_backend().describe()
    except NoBackend as exc:
        return f"none ({exc})"


def list_digitizers() -> tuple[list[HidDeviceInfo], str | None]:
    """HID digitizer interfaces: usage page 0x0D or Wacom's 0xFF0D, and any Wacom device.

    Never raises: no hidapi, no hidraw access or no devices give an empty list and a note.
    """
    try:
        hid = hid_backend().module
    except NoBackend as exc:
        return [], str(exc)
    try:
        found = hid.enumerate()
    except Exception as exc:  # hidapi raises plain OSError/IOError variants per platform
        return [], f"cannot enumerate HID devices: {exc}"
    out: list[HidDeviceInfo] = []
    # hidapi lists each top-level collection; one line per interface, its pen page first
    found = sorted(found, key=lambda d: int(d.get("usage_page", 0)) not in (DIGITIZER_PAGE,
                                                                             WACOM_PAGE))
    seen: set[bytes] = set()
    for d in found:
        path = d.get("path", b"") or b""
        if path and path in seen:
            continue
        vid, pid = int(d.get("vendor_id", 0)), int(d.get("product_id", 0))
        page = int(d.get("usage_page", 0))
        if page not in (DIGITIZER_PAGE, WACOM_PAGE) and vid != WACOM_VID:
            continue
        seen.add(path)
        out.append(HidDeviceInfo(
            vid, pid, path, page, int(d.get("usage", 0)),
            int(d.get("interface_number", -1)), d.get("manufacturer_string") or "",
            d.get("product_string") or "",
        ))
    return out, None


def mode_switch_failed(name: str, why: str) -> str:
    """One line: the tablet stays in mouse mode, so no pen reports will come; what to try."""
    return (f"camlab88 tablet: {name}: could not switch the tablet to tablet mode ({why}); "
            "it may send no pen reports. Try: unplug it and plug it in again; check you may "
            "write to its /dev/hidraw node (a udev rule or the plugdev group, docs/tablets.md)")


class HidReportDecoder:
    """Pen reports -> events: a vendor profile's fixed layout, else the report descriptor's
    (a tablet with two pen reports, Huion's 7 and 9, switches ``model`` with the report)."""

    def __init__(self, vid: int, pid: int, descriptor: bytes | None, where: str) -> None:
        self.profile = profile_for(vid, pid)
        self._profile_decode = self.profile.make_decoder() if self.profile else None
        self.pen: PenDecoder | None = None
        if self.profile is not None:
            self.model = self.profile.model
        else:
            if descriptor is None:
                raise ValueError(f"{where}: no report descriptor and no vendor profile")
            self.pen = PenDecoder(parse_descriptor(descriptor, where))
            if not self.pen.pen_reports:
                raise ValueError(f"{where}: no pen report")
            self.model = next(iter(self.pen.pen_reports.values()))

    @property
    def header_notes(self) -> list[str]:
        """What the monitor says after its header: touch reports are left alone."""
        touch = self.pen.touch_reports if self.pen is not None else []
        if not touch:
            return []
        ids = ", ".join(f"{r:#04x}" for r in touch)
        return [f"touch report{'s' if len(touch) > 1 else ''} {ids} (fingers on a touch "
                "screen or pad): not pen input, ignored"]

    def decode(self, report: bytes, now: float) -> TabletEvent | None:
        if self._profile_decode is not None:
            return self._profile_decode(report, now)
        assert self.pen is not None
        try:
            event = self.pen.decode(report, now)
        except ValueError:
            return None  # a report the descriptor does not describe: skip it
        if event is not None:
            report_id, _ = self.pen.decoder.split(report)
            self.model = self.pen.pen_reports[report_id]
        return event

    # the replay's interface (protocols.tablets.tape): one recorded report at a time
    def feed(self, report: bytes) -> list[TabletEvent]:
        event = self.decode(report, 0.0)
        return [] if event is None else [event]

    def flush(self) -> list[TabletEvent]:
        return []


class HidSource(TabletSource):
    """Reads pen reports; the descriptor decides the layout unless a vendor profile does."""

    def __init__(self, spec: SourceSpec, on_raw: Callable[[bytes], None] | None = None) -> None:
        try:
            self.backend = hid_backend()
        except NoBackend as exc:
            raise SourceLost(f"{spec.text}: {exc}") from exc
        hid = self.backend.module
        self.name = spec.text
        self.on_raw = on_raw
        self._t0 = time.monotonic()
        vid, pid = self.vid_pid = spec.vid_pid
        self.profile = profile_for(vid, pid)
        self.descriptor: bytes | None = None  # the pen interface's (None: a vendor profile)
        rows = self._enumerate(hid, spec, vid, pid)
        if self.profile is not None:  # the vendor profile knows the layout: one interface
            pen_pages = (DIGITIZER_PAGE, WACOM_PAGE)
            paths = [d["path"] for d in rows if int(d.get("usage_page", 0)) in pen_pages]
            self.device = self._open(hid, spec, paths[:1], vid, pid)
            failed = self._switch_mode(list(self.profile.init_feature_report))
            if failed is not None:  # the user must learn why no pen reports come
                print(mode_switch_failed(spec.text, failed), file=sys.stderr, flush=True)
        else:
            self._open_pen_interface(hid, spec, rows, vid, pid)
        self.decoder = HidReportDecoder(vid, pid, self.descriptor, spec.text)
        self.pump = ReportPump(self.device, spec.text)

    @property
    def model(self):  # TabletModel
        return self.decoder.model

    @property
    def header_notes(self) -> list[str]:
        return self.decoder.header_notes

    def _switch_mode(self, report: list[int]) -> str | None:
        """Legacy Wacoms start in mouse mode: the feature report switches them to tablet
        reports.  Why it failed, or None.  hidapi raises on some backends and returns -1 on
        others (hidraw), so both are failures."""
        try:
            sent = self.device.send_feature_report(report)
        except (OSError, ValueError) as exc:
            return str(exc) or type(exc).__name__
        if isinstance(sent, int) and sent < 0:
            error = getattr(self.device, "error", None)
            why = error() if callable(error) else None
            return str(why) if why else "the device refused the feature report"
        return None

    @staticmethod
    def _enumerate(hid, spec: SourceSpec, vid: int, pid: int) -> list[dict]:
        """The device's interfaces; absent: 'no device VID:PID (found: ...)'."""
        try:
            rows = [d for d in hid.enumerate(vid, pid) if d.get("path")]
            if rows:
                return rows
            everything = list(hid.enumerate())
        except Exception as exc:  # hidapi raises plain OSError/IOError variants per platform
            raise SourceLost(f"{spec.text}: cannot enumerate HID devices: {exc}") from exc
        raise SourceLost(f"{spec.text}: {absent_message(vid, pid, everything)}")

    @staticmethod
    def _ranked(rows: list[dict]) -> list[bytes]:
        """Interface paths, digitizer page first, then Wacom's page, then the rest."""
        order = {DIGITIZER_PAGE: 0, WACOM_PAGE: 1}
        ranked = sorted(rows, key=lambda d: order.get(int(d.get("usage_page", 0)), 2))
        paths: list[bytes] = []
        for d in ranked:
            if d["path"] not in paths:
                paths.append(d["path"])
        return paths

    @staticmethod
    def _open(hid, spec: SourceSpec, paths: list[bytes], vid: int, pid: int):
        device = hid.device()
        try:
            if paths:
                device.open_path(paths[0])
            else:
                device.open(vid, pid)
        except (OSError, ValueError) as exc:
            path = paths[0].decode(errors="replace") if paths else ""
            raise SourceLost(f"{spec.text}: {cannot_open_message(path, vid, pid, exc)}") from exc
        return device  # blocking: reads run on the pump's thread

    def _open_pen_interface(self, hid, spec: SourceSpec, rows: list[dict], vid: int,
                            pid: int) -> None:
        """A tablet has several interfaces (pen, pad, keyboard); use the first whose
        descriptor has a pen report."""
        paths: list[bytes | None] = list(self._ranked(rows)) or [None]
        problems: list[str] = []
        for path in paths:
            where = spec.text + (f" ({path.decode(errors='replace')})" if path else "")
            try:
                device = self._open(hid, spec, [path] if path else [], vid, pid)
            except SourceLost as exc:
                problems.append(str(exc))
                continue
            try:
                raw = bytes(device.get_report_descriptor())
                pen = PenDecoder(parse_descriptor(raw, where))
            except (OSError, ValueError, AttributeError) as exc:
                problems.append(f"{where}: cannot read the report descriptor: {exc}")
                device.close()
                continue
            if not pen.pen_reports:
                problems.append(f"{where}: no pen report")
                device.close()
                continue
            self.device, self.descriptor = device, raw
            return
        raise SourceLost(f"{spec.text}: no interface with a pen report: " + "; ".join(problems))

    def read(self, timeout: float = 0.0) -> list[TabletEvent]:
        """Events from the reports that have come, waiting up to ``timeout`` s for one."""
        reports = self.pump.take(timeout)
        if not reports and self.pump.error is not None:
            raise SourceLost(f"{self.name}: {self.pump.error} (unplugged?)")
        events: list[TabletEvent] = []
        for report in reports:
            events += self.decode(report)
        return events

    def decode(self, report: bytes) -> list[TabletEvent]:
        """One report as the tablet sent it (also what a replay feeds back)."""
        if self.on_raw is not None:
            self.on_raw(report)
        event = self.decoder.decode(report, time.monotonic() - self._t0)
        return [] if event is None else [event]

    def close(self) -> None:
        self.pump.close()
