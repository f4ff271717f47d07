"""A USB tablet on /dev/hidrawN without hardware: an umockdev test bed, then a command in it.

Run with the *system* Python (it has python3-gi and umockdev's GI bindings; the venv does not):

    /usr/bin/python3 tests/support/umockdev_hidraw.py SCENARIO.json -- python -m camlab88 ...

This process is the parent: it builds the fake sysfs tree hidapi's hidraw backend enumerates
(usb_device -> usb_interface -> hid device with its ``report_descriptor`` -> hidraw node, one
per interface), answers the hidraw ioctls (HIDIOCGRDESCSIZE, HIDIOCGRDESC, HIDIOCGRAWINFO) and
the reads of the command, which runs as its child under ``libumockdev-preload``.  A read with
nothing due is answered EAGAIN after IDLE_READ s (below).  The handler
must live in a parent: in the same process hidapi would hold the GIL while the handler waits
for it.  umockdev 0.17 does not emulate ``poll`` on the node, so reads are the only way a
report arrives: a read waits (as on a real blocking hidraw node) until a report is due.

SCENARIO (JSON, written by the test):
  vid, pid (hex strings), manufacturer, product,
  interfaces: [{descriptor: hex, reports: [hex, ...]}, ...]  -> /dev/hidraw0, 1, ...
  interval: s between reports (default 0.01); first_after: s after the first read (0.2)
  unplug_after: remove every node after this many reports of the pen interface (optional)
  replug_after: s after the unplug to add them again; then ``reports_after_replug`` follow
  limit: s before the child is killed (default 60)
Exit status: the child's.
"""

from __future__ import annotations

import errno
import json
import os
import struct
import subprocess
import sys
import threading
import time

import gi

gi.require_version("UMockdev", "1.0")
from gi.repository import GLib, UMockdev  # noqa: E402

HIDIOCGRDESCSIZE = 0x80044801
HIDIOCGRDESC = 0x90044802  # struct hidraw_report_descriptor: u32 size + 4096 bytes
HIDIOCGRAWINFO = 0x80084803  # struct hidraw_devinfo: u32 bustype, s16 vendor, s16 product
BUS_USB = 3
# A read with no report due is answered EAGAIN after this long (hidraw's answer to a read
# that would block, as if hidapi had timed out): the reader thread gets a chance to see it is
# being closed, so the child exits without a read still waiting on umockdev's socket.
IDLE_READ = 0.02
USB = "/devices/pci0000:00/0000:00:14.0/usb1/1-1"


class Tablet:
    """Every interface's hidraw node, its descriptor and its reports."""

    def __init__(self, testbed, scenario: dict) -> None:
        self.tb = testbed
        self.s = scenario
        self.vid, self.pid = int(scenario["vid"], 16), int(scenario["pid"], 16)
        self.interfaces = [bytes.fromhex(i["descriptor"]) for i in scenario["interfaces"]]
        self.queues = [[bytes.fromhex(r) for r in i.get("reports", [])]
                       for i in scenario["interfaces"]]
        self.pen = next((k for k, q in enumerate(self.queues) if q), 0)
        self.pending: list[tuple[int, object, float]] = []  # reads waiting: (iface, client, t)
        self.delivered = 0
        self.plugged = False
        self.generation = 0
        self.handlers: list[object] = []
        self.next_due: float | None = None
        self.unplugged_at: float | None = None

    def plug(self) -> None:
        tb, vid, pid = self.tb, self.vid, self.pid
        self.added = [USB]
        tb.add_from_string(
            f"P: {USB}\nE: SUBSYSTEM=usb\nE: DEVTYPE=usb_device\n"
            f"A: idVendor={vid:04x}\nA: idProduct={pid:04x}\n"
            f"A: manufacturer={self.s.get('manufacturer', '')}\n"
            f"A: product={self.s.get('product', '')}\nA: bcdDevice=0100\n")
        self.handlers = []
        self.nodes = []
        for k, descriptor in enumerate(self.interfaces):
            # as the kernel does on a replug: a new hid sequence number and hidraw minor
            # (umockdev 0.17 also cannot re-create a node it has removed)
            n = self.generation * len(self.interfaces) + k
            hid = f"{USB}/1-1:1.{k}/0003:{vid:04X}:{pid:04X}.{n + 1:04X}"
            tb.add_from_string(f"P: {USB}/1-1:1.{k}\nE: SUBSYSTEM=usb\n"
                               f"E: DEVTYPE=usb_interface\nA: bInterfaceNumber={k:02x}\n")
            tb.add_from_string(
                f"P: {hid}\nE: SUBSYSTEM=hid\nE: HID_ID=0003:{vid:08X}:{pid:08X}\n"
                f"E: HID_NAME={self.s.get('manufacturer', '')} {self.s.get('product', '')}\n"
                f"E: HID_PHYS=usb-0000:00:14.0-1/input{k}\nE: HID_UNIQ=\n"
                f"H: report_descriptor={descriptor.hex().upper()}\n")
            raw = f"{hid}/hidraw/hidraw{n}"
            self.added += [f"{USB}/1-1:1.{k}", hid, raw]
            self.nodes.append(f"/dev/hidraw{n}")
            tb.add_from_string(f"P: {raw}\nN: hidraw{n}\nE: SUBSYSTEM=hidraw\n"
                               f"E: DEVNAME=/dev/hidraw{n}\nA: dev=247:{n}\n")
            link = tb.get_root_dir() + "/sys" + raw + "/device"
            if not os.path.lexists(link):
                os.symlink("../..", link)  # hidapi reads device/report_descriptor
            handler = Handler(self, k)
            tb.attach_ioctl(f"/dev/hidraw{n}", handler)
            self.handlers.append(handler)
        self.plugged = True

    def unplug(self) -> None:
        self.plugged = False
        self.unplugged_at = time.monotonic()
        for _k, client, _since in self.pending:
            client.complete(-1, errno.EIO)  # the kernel's answer on a vanished hidraw node
        self.pending = []
        for node in self.nodes:
            self.tb.detach_ioctl(node)
        self.generation += 1
        for path in reversed(self.added):  # children first: each has its bus/class links
            self.tb.remove_device("/sys" + path)

    def tick(self) -> bool:
        now = time.monotonic()
        if self.plugged:
            self._deliver(now)
        elif self.unplugged_at is not None and "replug_after" in self.s and \
                now - self.unplugged_at >= self.s["replug_after"]:
            self.unplugged_at = None
            self.queues[self.pen] = [bytes.fromhex(r)
                                     for r in self.s.get("reports_after_replug", [])]
            self.next_due = None
            self.plug()
        return True

    def _deliver(self, now: float) -> None:
        for k, client, since in list(self.pending):
            if not self.queues[k] and now - since > IDLE_READ:
                self.pending.remove((k, client, since))
                client.complete(-1, errno.EAGAIN)
        waiting = [p for p in self.pending if self.queues[p[0]]]
        if not waiting:
            return
        if self.next_due is None:
            self.next_due = now + self.s.get("first_after", 0.2)
        if now < self.next_due:
            return
        k, client, since = waiting[0]
        self.pending.remove((k, client, since))
        report = self.queues[k].pop(0)
        client.get_arg().update(0, list(report))
        client.complete(len(report), 0)
        self.next_due = now + self.s.get("interval", 0.01)
        if k == self.pen:
            self.delivered += 1
            if self.delivered == self.s.get("unplug_after"):
                self.unplug()


class Handler(UMockdev.IoctlBase):
    def __init__(self, tablet: Tablet, interface: int) -> None:
        super().__init__()
        self.tablet, self.k = tablet, interface

    def do_handle_ioctl(self, client) -> bool:
        request, arg = client.get_request(), client.get_arg()
        descriptor = self.tablet.interfaces[self.k]
        if request == HIDIOCGRDESCSIZE:
            arg.resolve(0, 4).update(0, list(struct.pack("<i", len(descriptor))))
        elif request == HIDIOCGRDESC:
            arg.resolve(0, 4100).update(4, list(descriptor))
        elif request == HIDIOCGRAWINFO:
            info = struct.pack("<Ihh", BUS_USB, *(v - 65536 if v > 32767 else v for v in (
                self.tablet.vid, self.tablet.pid)))
            arg.resolve(0, 8).update(0, list(info))
        else:
            client.complete(-1, errno.ENOTTY)
            return True
        client.complete(0, 0)
        return True

    def do_handle_read(self, client) -> bool:
        if not self.tablet.plugged:
            client.complete(-1, errno.EIO)
        else:
            # answered when a report is due (or EAGAIN after IDLE_READ s without one)
            self.tablet.pending.append((self.k, client, time.monotonic()))
        return True

    def do_handle_write(self, client) -> bool:
        client.complete(len(client.get_arg().data), 0)  # output reports: taken, ignored
        return True


def _die_with_parent() -> None:
    """In the child: SIGKILL when this helper dies (a test's timeout kills only us)."""
    import ctypes
    import signal

    ctypes.CDLL(None).prctl(1, signal.SIGKILL)  # PR_SET_PDEATHSIG


def main() -> int:
    scenario = json.loads(open(sys.argv[1]).read())
    command = sys.argv[sys.argv.index("--") + 1:]
    testbed = UMockdev.Testbed.new()
    tablet = Tablet(testbed, scenario)
    tablet.plug()
    env = dict(os.environ, UMOCKDEV_DIR=testbed.get_root_dir(),
               LD_PRELOAD="libumockdev-preload.so.0")
    loop = GLib.MainLoop()
    result = {"status": 1}

    def child() -> None:
        proc = subprocess.Popen(command, env=env, preexec_fn=_die_with_parent)
        try:
            result["status"] = proc.wait(timeout=scenario.get("limit", 60))
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.wait()
            print("umockdev_hidraw: the command ran past the limit; killed", file=sys.stderr)
        GLib.idle_add(loop.quit)

    GLib.timeout_add(2, tablet.tick)
    threading.Thread(target=child, daemon=True).start()
    loop.run()
    return result["status"]


if __name__ == "__main__":
    status = main()
    sys.stdout.flush()
    sys.stderr.flush()
    os._exit(status)  # not through GI's finalisers (they complain about open client streams)
