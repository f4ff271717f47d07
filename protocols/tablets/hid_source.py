"""USB HID tablets through hidapi (``import hid`` from the ``hidapi`` package)."""

from __future__ import annotations

import time
from collections.abc import Callable
from dataclasses import dataclass

from protocols.tablets.events import TabletEvent
from protocols.tablets.hid_decode import PenDecoder
from protocols.tablets.hid_descriptor import parse_descriptor
from protocols.tablets.hid_profiles import profile_for
from protocols.tablets.sources import SourceLost, SourceSpec, TabletSource

DIGITIZER_PAGE = 0x0D
READ_SIZE = 256


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


def list_digitizers() -> tuple[list[HidDeviceInfo], str | None]:
    """HID digitizer interfaces (usage page 0x0D, or any Wacom/known-profile device).

    Never raises: no hidapi, no hidraw access or no devices give an empty list and a note.
    """
    try:
        import hid
    except ImportError as exc:
        return [], f"hidapi is not installed ({exc}); pip install hidapi==0.15.0"
    try:
        found = hid.enumerate()
    except Exception as exc:  # hidapi raises plain OSError/IOError variants per platform
        return [], f"cannot enumerate HID devices: {exc}"
    out: list[HidDeviceInfo] = []
    for d in found:
        vid, pid = int(d.get("vendor_id", 0)), int(d.get("product_id", 0))
        page = int(d.get("usage_page", 0))
        if page != DIGITIZER_PAGE and profile_for(vid, pid) is None:
            continue
        out.append(HidDeviceInfo(
            vid, pid, d.get("path", b"") or b"", page, int(d.get("usage", 0)),
            int(d.get("interface_number", -1)), d.get("manufacturer_string") or "",
            d.get("product_string") or "",
        ))
    return out, None


class HidSource(TabletSource):
    """Reads pen reports; the descriptor decides the layout unless a vendor profile does."""

    def __init__(self, spec: SourceSpec, on_raw: Callable[[bytes], None] | None = None) -> None:
        try:
            import hid
        except ImportError as exc:
            raise SourceLost(f"{spec.text}: hidapi is not installed: {exc}") from exc
        self.name = spec.text
        self.on_raw = on_raw
        self._t0 = time.monotonic()
        vid, pid = spec.vid_pid
        self.device = hid.device()
        try:
            path = self._pen_interface(hid, vid, pid)
            if path is not None:
                self.device.open_path(path)
            else:
                self.device.open(vid, pid)
        except (OSError, ValueError) as exc:
            raise SourceLost(f"{spec.text}: cannot open (check permissions, see docs/tablets.md):"
                             f" {exc}") from exc
        self.profile = profile_for(vid, pid)
        self._profile_decode = self.profile.make_decoder() if self.profile else None
        self.pen: PenDecoder | None = None
        if self.profile is not None:
            try:  # legacy Wacoms start in mouse mode: switch to tablet reports
                self.device.send_feature_report(list(self.profile.init_feature_report))
            except (OSError, ValueError):
                pass
            self.model = self.profile.model
        else:
            try:
                descriptor = parse_descriptor(bytes(self.device.get_report_descriptor()),
                                              spec.text)
            except (OSError, ValueError, AttributeError) as exc:
                self.device.close()
                raise SourceLost(f"{spec.text}: cannot read the report descriptor: {exc}"
                                 ) from exc
            self.pen = PenDecoder(descriptor)
            if not self.pen.pen_reports:
                self.device.close()
                raise SourceLost(f"{spec.text}: this interface has no pen report")
            self.model = next(iter(self.pen.pen_reports.values()))

    @staticmethod
    def _pen_interface(hid, vid: int, pid: int) -> bytes | None:
        for d in hid.enumerate(vid, pid):
            if int(d.get("usage_page", 0)) == DIGITIZER_PAGE:
                return d.get("path")
        return None

    def read(self, timeout: float = 0.0) -> list[TabletEvent]:
        try:
            data = self.device.read(READ_SIZE, int(timeout * 1000))
        except (OSError, ValueError) as exc:
            raise SourceLost(f"{self.name}: {exc}") from exc
        if not data:
            return []
        report = bytes(data)
        if self.on_raw is not None:
            self.on_raw(report)
        now = time.monotonic() - self._t0
        if self._profile_decode is not None:
            event = self._profile_decode(report, now)
        else:
            assert self.pen is not None
            try:
                event = self.pen.decode(report, now)
            except ValueError:
                return []  # a report the descriptor does not describe: skip it
            if event is not None:  # tablets with two pen reports (Huion: 7 and 9) differ
                report_id, _ = self.pen.decoder.split(report)
                self.model = self.pen.pen_reports[report_id]
        return [] if event is None else [event]

    def close(self) -> None:
        try:
            self.device.close()
        except (OSError, ValueError):
            pass
