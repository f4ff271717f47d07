"""Run a camlab88 command beside an umockdev hidraw tablet (tests/support/umockdev_hidraw.py).

The tablets are the real captures in tests/data/tablets: their report descriptors, one
hidraw node per interface, and their recorded pen reports, read by hidapi's real hidraw
backend in the child.  ``skip_reason()`` says why the bed cannot run here (then the tests
skip with that message: CI installs umockdev, gir1.2-umockdev-1.0 and python3-gi).
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

from camlab88.protocols.tablets.hid_descriptor import parse_hex_text
from tests.tablets.helpers import DIGIMEND, load_dump

ROOT = Path(__file__).resolve().parents[2]
HELPER = ROOT / "tests" / "support" / "umockdev_hidraw.py"
SYSTEM_PYTHON = "/usr/bin/python3"


def skip_reason() -> str | None:
    if not sys.platform.startswith("linux"):
        return "umockdev needs Linux"
    if not os.path.exists(SYSTEM_PYTHON):
        return f"{SYSTEM_PYTHON} (the system Python with python3-gi) is missing"
    probe = subprocess.run(
        [SYSTEM_PYTHON, "-c", "import gi; gi.require_version('UMockdev', '1.0'); "
         "from gi.repository import UMockdev; print(UMockdev.Testbed)"],
        capture_output=True, text=True, timeout=30)
    if probe.returncode != 0:
        return ("umockdev's GI bindings are missing for the system Python (apt-get install "
                f"umockdev gir1.2-umockdev-1.0 python3-gi): {probe.stderr.strip()[-200:]}")
    return None


def descriptor_hex(path: Path) -> str:
    return parse_hex_text(path.read_text(), str(path)).hex()


def huion_h610(reports: list[bytes] | None = None, **extra) -> dict:
    """Huion H610: three interfaces, the pen (report 9) on interface 0."""
    d = DIGIMEND / "Huion_H610"
    ifs = [{"descriptor": descriptor_hex(d / f"rd/original{k}.txt")} for k in range(3)]
    if reports is None:
        reports = load_dump(d / "dumps/pen_pressure.txt")
    ifs[0]["reports"] = [r.hex() for r in reports]
    return {"vid": "256c", "pid": "006e", "manufacturer": "HUION", "product": "PenTablet",
            "interfaces": ifs, **extra}


def gaomon_m106k(reports: list[bytes]) -> dict:
    """Gaomon M106K: interface 0 (no pen), the pen (report 0x0A) on interface 1."""
    d = DIGIMEND / "Gaomon_M106K"
    return {"vid": "256c", "pid": "006d", "manufacturer": "GAOMON", "product": "Tablet",
            "interfaces": [{"descriptor": descriptor_hex(d / "rd/original0.txt")},
                           {"descriptor": descriptor_hex(d / "rd/original1.txt"),
                            "reports": [r.hex() for r in reports]}]}


def run_in_bed(tmp_path: Path, scenario: dict, args: list[str], timeout: float = 60,
               env: dict | None = None) -> subprocess.CompletedProcess[str]:
    """``python -m camlab88 ARGS`` (the venv's Python) as the bed's child."""
    path = tmp_path / "scenario.json"
    path.write_text(json.dumps(dict(scenario, limit=timeout)))
    child_env = dict(os.environ, **(env or {}))
    child_env["PYTHONPATH"] = os.pathsep.join(
        [str(ROOT)] + [p for p in child_env.get("PYTHONPATH", "").split(os.pathsep) if p])
    return subprocess.run([SYSTEM_PYTHON, str(HELPER), str(path), "--", sys.executable, "-m",
                           "camlab88", *args],
                          capture_output=True, text=True, timeout=timeout + 30, env=child_env,
                          cwd=tmp_path)
