"""Which hidapi backend reads USB tablets, and the messages for what goes wrong opening one.

The ``hidapi`` 0.15 wheel holds two modules.  On Linux ``import hid`` is its **libusb**
backend: it talks raw USB, does not see ``/dev/hidrawN`` at all, and must detach the kernel
driver to claim a tablet; ``import hidraw`` is the **hidraw** backend, which opens
``/dev/hidrawN`` beside the kernel driver (the desktop pointer keeps working) -- what a Wacom
or Huion on a Linux desktop goes through.  So on Linux hidraw comes first and libusb is the
fallback where hidraw cannot be imported.  On macOS and Windows ``hid`` is hidapi's native
backend (IOHIDManager, the Windows HID API); there is no ``hidraw``.

``CAMLAB88_HID_BACKEND=hidraw|hid`` forces one module (a machine where one misbehaves).
"""

from __future__ import annotations

import importlib
import os
import sys
from dataclasses import dataclass
from typing import Any

BACKEND_ENV = "CAMLAB88_HID_BACKEND"
UDEV_RULES = "/etc/udev/rules.d/70-camlab88-tablets.rules"


class NoBackend(ImportError):
    """No hidapi module could be imported (the message says which were tried and why)."""


@dataclass(frozen=True)
class HidBackend:
    module: Any
    name: str  # "hidraw", "libusb", "native"

    def describe(self) -> str:
        what = {
            "hidraw": "hidraw: /dev/hidrawN through the kernel",
            "libusb": "libusb fallback: raw USB, no /dev/hidrawN",
            "native": f"hidapi's native backend on {sys.platform}",
        }
        return what.get(self.name, self.name)


def _order() -> tuple[str, ...]:
    forced = os.environ.get(BACKEND_ENV, "").strip()
    if forced:
        return (forced,)
    return ("hidraw", "hid") if sys.platform.startswith("linux") else ("hid",)


def hid_backend() -> HidBackend:
    """The first hidapi module that imports, in the order above; NoBackend if none does."""
    problems = []
    for name in _order():
        if name not in ("hidraw", "hid"):
            problems.append(f"{BACKEND_ENV}={name!r} is not hidraw or hid")
            continue
        try:
            module = importlib.import_module(name)
        except ImportError as exc:
            problems.append(f"import {name}: {exc}")
            continue
        if name == "hidraw":
            return HidBackend(module, "hidraw")
        return HidBackend(module, "libusb" if sys.platform.startswith("linux") else "native")
    raise NoBackend("hidapi is not usable (" + "; ".join(problems)
                    + "); pip install hidapi==0.15.0")


def udev_rule(vid: int, pid: int) -> str:
    """The udev rule that gives the logged-in user a tablet's hidraw nodes."""
    return (f'KERNEL=="hidraw*", ATTRS{{idVendor}}=="{vid:04x}", '
            f'ATTRS{{idProduct}}=="{pid:04x}", MODE="0660", TAG+="uaccess"')


def permission_message(path: str, vid: int, pid: int) -> str:
    return (f"permission denied on {path}: add the udev rule\n    {udev_rule(vid, pid)}\n"
            f"  to {UDEV_RULES}, then run 'sudo udevadm control --reload && "
            "sudo udevadm trigger' and replug the tablet (docs/tablets.md)")


def cannot_open_message(path: str, vid: int, pid: int, exc: BaseException) -> str:
    """Why opening ``path`` failed: hidapi says only 'open failed', so look at the node."""
    if path.startswith("/dev/") and os.path.exists(path) and not os.access(
            path, os.R_OK | os.W_OK):
        return permission_message(path, vid, pid)
    return f"cannot open {path or f'{vid:04x}:{pid:04x}'}: {exc}"


def absent_message(vid: int, pid: int, rows: list[dict]) -> str:
    """'no device 056a:0010 (found: ...)' with what hidapi does see."""
    seen: list[str] = []
    for d in rows:
        vp = f"{int(d.get('vendor_id', 0)):04x}:{int(d.get('product_id', 0)):04x}"
        name = (d.get("product_string") or "").strip()
        item = f"{vp} {name}".strip()
        if item not in seen:
            seen.append(item)
    found = ", ".join(seen) if seen else "no HID devices at all"
    return (f"no device {vid:04x}:{pid:04x} (found: {found}); is it plugged in? "
            "'camlab88 tablet list' shows what can be opened")
