"""Only the machines and the harness run a device on its line: nothing else in apps/,
camlab88/ or emulator/ feeds a Sigma terminal, plays the device's end of a line, advances a
line's clock, ticks a machine or builds a line and clock of its own.  Host programs get a port
(protocols.link.port.HostPort); commands build a machine and hand the harness the run.

An AST scan, by the shape of the call: ``<term|terminal>.feed(...)`` and
``Terminal(...).feed(...)``; ``<...>.device.write/read/read_timed(...)``;
``<...clock...>.advance/advance_to(...)``; ``<machine>.tick/run_until/take(...)``;
``SerialLine(...)`` / ``VirtualClock(...)``.
"""

from __future__ import annotations

import ast
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SCANNED = ("apps", "camlab88", "emulator")
# the owners: the machines, the harness that ticks them, and the public test bench, which is
# the machines' public face (camlab88.Sigma)
OWNERS = ("emulator/machine/", "emulator/harness/", "camlab88/bench/")
# the device packages themselves (a terminal warming its own kernels, a tracer's decoder)
DEVICE = ("emulator/sigma/", "emulator/rainbow/", "emulator/tablet/")


def _name(node: ast.AST) -> str:
    """The last name of a receiver: ``a.b.clock`` -> ``clock``, ``term`` -> ``term``."""
    if isinstance(node, ast.Attribute):
        return node.attr
    if isinstance(node, ast.Name):
        return node.id
    if isinstance(node, ast.Call):
        return _name(node.func)
    return ""


def _kind(call: ast.Call) -> str | None:
    """What a call does to a device, line or clock (None: nothing of that)."""
    f = call.func
    if isinstance(f, ast.Name) and f.id in ("SerialLine", "VirtualClock"):
        return f"builds a {f.id}"
    if not isinstance(f, ast.Attribute):
        return None
    recv, what = f.value, f.attr
    name = _name(recv).lower()
    if what == "feed" and (name in ("term", "terminal") or (
            isinstance(recv, ast.Call) and _name(recv.func) == "Terminal")):
        return "feeds a terminal"
    if what in ("write", "read", "read_timed") and name == "device":
        return "plays the device end of a line"
    if what in ("advance", "advance_to") and "clock" in name:
        return "advances a clock"
    if what in ("tick", "run_until", "take") and "machine" in name:
        return "runs a machine"
    return None


def violations() -> dict[tuple[str, str], int]:
    found: dict[tuple[str, str], int] = {}
    for top in SCANNED:
        for path in sorted((ROOT / top).rglob("*.py")):
            rel = path.relative_to(ROOT).as_posix()
            if rel.startswith(OWNERS + DEVICE):
                continue
            for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"), rel)):
                kind = _kind(node) if isinstance(node, ast.Call) else None
                if kind is not None:
                    found[(rel, kind)] = found.get((rel, kind), 0) + 1
    return found


def test_only_machines_and_the_harness_run_a_device_on_its_line() -> None:
    found = violations()
    assert not found, "runs a device, line or clock outside emulator/machine and " \
        "emulator/harness (give the program a port; let the harness run the machine):\n" + \
        "\n".join(f"  {path}: {kind} ({n}x)" for (path, kind), n in sorted(found.items()))


def test_the_scan_sees_each_kind_of_call() -> None:
    src = ("term.feed(b'x')\nTerminal('t5684').feed(b'')\nself.line.device.write(b'')\n"
           "line.device.read()\nself.clock.advance(1)\nclock.advance_to(2)\n"
           "machine.run_until(3)\nself.machine.tick()\nSerialLine(s, c)\nVirtualClock()\n"
           "port.write(b'')\nself.editor.feed(ev)\nport.read()\nsession.advance(m)\n")
    kinds = [_kind(n) for n in ast.walk(ast.parse(src)) if isinstance(n, ast.Call)]
    assert sorted(k for k in kinds if k) == sorted(
        ["feeds a terminal"] * 2 + ["plays the device end of a line"] * 2
        + ["advances a clock"] * 2 + ["runs a machine"] * 2
        + ["builds a SerialLine", "builds a VirtualClock"])
