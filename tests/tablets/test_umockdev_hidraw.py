"""Real tablets' descriptors and pen reports through hidapi's real hidraw backend, no hardware.

Each test runs ``camlab88`` as the child of an umockdev test bed (tests/support/
umockdev_hidraw.py) in which /dev/hidrawN are the captured tablets' interfaces.
"""

from __future__ import annotations

import re
import time
from pathlib import Path

import pytest

from camlab88.protocols.tablets.hid_decode import PenDecoder
from tests.tablets.helpers import DIGIMEND, load_descriptor, load_dump
from tests.tablets.umockdev_bed import gaomon_m106k, huion_h610, run_in_bed, skip_reason

_WHY = skip_reason()
pytestmark = pytest.mark.skipif(_WHY is not None, reason=_WHY or "")


def _fields(line: str) -> str:
    """A monitor line without its time stamp (wall-clock dependent)."""
    return line.split(None, 1)[1]


def _expected(descriptor_path: Path, reports: list[bytes]) -> list[str]:
    pen = PenDecoder(load_descriptor(descriptor_path))
    out = []
    for r in reports:
        event = pen.decode(r, 0.0)
        if event is not None:
            out.append(_fields(event.describe()))
    return out


def test_tablet_list_shows_the_umockdev_tablet_with_the_hidraw_backend(tmp_path: Path) -> None:
    done = run_in_bed(tmp_path, huion_h610([]), ["tablet", "list"])
    assert done.returncode == 0, done.stderr
    assert "backend: hidraw" in done.stdout
    assert re.search(r"hid:256c:006e\s+HUION PenTablet\s+usage 0x000d:0x02\s+interface 0\s+"
                     r"/dev/hidraw0", done.stdout), done.stdout


def test_libusb_fallback_does_not_see_hidraw_nodes(tmp_path: Path) -> None:
    """Why hidraw comes first: the libusb backend ('import hid') finds no hidraw tablet."""
    done = run_in_bed(tmp_path, huion_h610([]), ["tablet", "list"],
                      env={"CAMLAB88_HID_BACKEND": "hid"})
    assert "backend: libusb" in done.stdout and "/dev/hidraw0" not in done.stdout


def test_monitor_prints_the_captured_pen_reports_of_the_pen_interface(tmp_path: Path) -> None:
    reports = [r for r in load_dump(DIGIMEND / "Gaomon_M106K/dumps/pen_cords.txt")
               if r[0] == 0x0A][:12]
    want = _expected(DIGIMEND / "Gaomon_M106K/rd/original1.txt", reports)
    assert len(want) == 12
    done = run_in_bed(tmp_path, gaomon_m106k(reports),
                      ["tablet", "monitor", "hid:256c:006d", "--count", "12", "--raw"])
    assert done.returncode == 0, done.stderr
    lines = done.stdout.splitlines()
    events = [_fields(x) for x in lines if re.match(r"\s+\d+\.\d{3} x=", x)]
    assert events == want
    assert [x for x in lines if x.startswith("raw ")][:2] == [
        "raw " + r.hex(" ") for r in reports[:2]]


def test_monitor_keeps_running_through_an_unplug_and_picks_the_tablet_up_again(
        tmp_path: Path) -> None:
    reports = load_dump(DIGIMEND / "Huion_H610/dumps/pen_pressure.txt")
    scenario = huion_h610(reports[:6], unplug_after=6, replug_after=1.0,
                          reports_after_replug=[r.hex() for r in reports[6:12]])
    start = time.monotonic()
    done = run_in_bed(tmp_path, scenario, ["tablet", "monitor", "hid:256c:006e", "--count",
                                           "12"], timeout=30)
    assert time.monotonic() - start < 20
    assert done.returncode == 0, done.stderr
    assert "lost hid:256c:006e" in done.stderr and "waiting for it to come back" in done.stderr
    assert "hid:256c:006e: back" in done.stderr
    events = [_fields(x) for x in done.stdout.splitlines() if " x=" in x]
    assert events == _expected(DIGIMEND / "Huion_H610/rd/original0.txt", reports[:12])


def test_absent_device_names_what_is_there(tmp_path: Path) -> None:
    start = time.monotonic()
    done = run_in_bed(tmp_path, huion_h610([]), ["tablet", "monitor", "hid:056a:0010"])
    assert time.monotonic() - start < 10
    assert done.returncode == 2
    assert "no device 056a:0010 (found: 256c:006e PenTablet)" in done.stderr, done.stderr
