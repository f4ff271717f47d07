"""Pen+touch screens: finger reports are never pen input (issue 42 item 2).

Three real descriptors from the Linux kernel's HID selftests (tests/data/tablets/SOURCES.md):
Atmel 03eb:840b, N-Trig 1b96:0c01 and Goodix 27c6:0113, each with a Touch Screen application
of Finger collections beside a Pen.  Reports are computed from the descriptors (no captures
exist).  Decoded directly, then through hidapi's real hidraw backend under umockdev with
`tablet monitor`: its header names the pen report and says the touch report is ignored, and
only the pen's reports come out, a finger between them drawing nothing.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from camlab88.protocols.tablets.events import TabletEvent
from camlab88.protocols.tablets.hid_decode import PenDecoder, encode_report
from tests.tablets.helpers import SELFTESTS, load_descriptor
from tests.tablets.umockdev_bed import descriptor_hex, run_in_bed, skip_reason

X, Y, TIP, IN_RANGE, PRESSURE = 0x010030, 0x010031, 0x0D0042, 0x0D0032, 0x0D0030
BARREL, INVERT, ERASER, TILT_X, TILT_Y = 0x0D0044, 0x0D003C, 0x0D0045, 0x0D003D, 0x0D003E
CONTACT_ID, CONTACT_COUNT = 0x0D0051, 0x0D0054

# file, vid, pid, pen report, touch report, what the pen carries
DEVICES = [
    ("atmel_03eb_840b", "03eb", "840b", 0x03, 0x01, {"invert": False, "tilt": False}),
    ("n_trig_1b96_0c01", "1b96", "0c01", 0x01, 0x03, {"invert": True, "tilt": False}),
    ("gxtp_27c6_0113", "27c6", "0113", 0x08, 0x01, {"invert": True, "tilt": True}),
]


def _finger(desc, rid: int, x: int, y: int) -> bytes:
    """One finger down at (x, y): the first contact of the touch report."""
    return encode_report(desc, rid, {TIP: [1], CONTACT_ID: [0], X: [x], Y: [y],
                                     CONTACT_COUNT: 1})


def _pen_reports(desc, rid: int, carries: dict) -> list[tuple[bytes, TabletEvent]]:
    """A hover, a press with pressure, the barrel button, an eraser touch, out of range."""
    out = []
    tilt = {TILT_X: -1200, TILT_Y: 900} if carries["tilt"] else {}
    steps = [  # (values, expected buttons, proximity, pressure, tool)
        ({IN_RANGE: 1, X: 1000, Y: 800, PRESSURE: 0}, 0, True, 0, "pen"),
        ({IN_RANGE: 1, TIP: 1, X: 1010, Y: 805, PRESSURE: 200}, 1, True, 200, "pen"),
        ({IN_RANGE: 1, TIP: 1, BARREL: 1, X: 1020, Y: 810, PRESSURE: 150}, 3, True, 150,
         "pen"),
        ({IN_RANGE: 0, X: 1020, Y: 810, PRESSURE: 0}, 0, False, 0, "pen"),
    ]
    if carries["invert"]:
        steps.insert(3, ({IN_RANGE: 1, INVERT: 1, ERASER: 1, X: 1030, Y: 815, PRESSURE: 90},
                         1, True, 90, "eraser"))
    for values, buttons, prox, pressure, tool in steps:
        report = encode_report(desc, rid, {**values, **tilt})
        t = tilt.get(TILT_X), tilt.get(TILT_Y)
        out.append((report, TabletEvent(values[X], values[Y], prox, buttons, pressure, *t,
                                        tool=tool)))
    return out


@pytest.mark.parametrize(("name", "vid", "pid", "pen", "touch", "carries"), DEVICES,
                         ids=[d[0] for d in DEVICES])
def test_finger_reports_are_not_pen_reports(name: str, vid: str, pid: str, pen: int,
                                            touch: int, carries: dict) -> None:
    desc = load_descriptor(SELFTESTS / f"{name}.hex")
    decoder = PenDecoder(desc)
    assert list(decoder.pen_reports) == [pen] and decoder.touch_reports == [touch]
    assert decoder.pen_reports[pen].name == f"HID pen report {pen:#04x}"
    assert decoder.decode(_finger(desc, touch, 2000, 1500)) is None  # a finger draws nothing
    for report, want in _pen_reports(desc, pen, carries):
        assert decoder.decode(report) == want


_WHY = skip_reason()


@pytest.mark.skipif(_WHY is not None, reason=_WHY or "")
@pytest.mark.parametrize(("name", "vid", "pid", "pen", "touch", "carries"), DEVICES,
                         ids=[d[0] for d in DEVICES])
def test_monitor_names_the_pen_report_and_shows_no_finger(tmp_path: Path, name: str,
                                                          vid: str, pid: str, pen: int,
                                                          touch: int, carries: dict) -> None:
    path = SELFTESTS / f"{name}.hex"
    desc = load_descriptor(path)
    pens = _pen_reports(desc, pen, carries)
    reports: list[bytes] = []
    for k, (report, _) in enumerate(pens):  # a finger before every pen report
        reports += [_finger(desc, touch, 3000 + 10 * k, 2000), report]
    scenario = {"vid": vid, "pid": pid, "manufacturer": "selftest", "product": name,
                "interfaces": [{"descriptor": descriptor_hex(path),
                                "reports": [r.hex() for r in reports]}]}
    done = run_in_bed(tmp_path, scenario, ["tablet", "monitor", f"hid:{vid}:{pid}",
                                           "--count", str(len(pens))])
    assert done.returncode == 0, done.stderr
    lines = done.stdout.splitlines()
    assert lines[0].startswith(f"# hid:{vid}:{pid}: HID pen report {pen:#04x}, "), lines[0]
    assert f"# touch report {touch:#04x} (fingers on a touch screen or pad): not pen " \
           "input, ignored" in lines
    events = [x.split(None, 1)[1] for x in lines if re.match(r"\s+\d+\.\d{3} x=", x)]
    assert events == [want.describe().split(None, 1)[1] for _, want in pens]


@pytest.mark.skipif(_WHY is not None, reason=_WHY or "")
def test_a_failed_mode_switch_is_reported_in_one_line_with_what_to_try(tmp_path: Path) -> None:
    """A legacy Wacom (Graphire, 056a:0010) is switched to tablet mode with a feature report;
    the bed refuses it (ENOTTY, as a node without the ioctl would) and the user is told."""
    path = SELFTESTS / "wacom_pth460_v105.hex"  # any descriptor on Wacom's page will do
    scenario = {"vid": "056a", "pid": "0010", "manufacturer": "Wacom", "product": "Graphire",
                "interfaces": [{"descriptor": descriptor_hex(path), "reports": []}]}
    done = run_in_bed(tmp_path, scenario, ["tablet", "monitor", "hid:056a:0010",
                                           "--seconds", "1"])
    said = [s for s in done.stderr.splitlines() if "tablet mode" in s]
    assert len(said) == 1, done.stderr
    assert said[0].startswith("camlab88 tablet: hid:056a:0010: could not switch the tablet to "
                              "tablet mode (")
    assert "unplug it and plug it in again" in said[0] and "/dev/hidraw" in said[0]
