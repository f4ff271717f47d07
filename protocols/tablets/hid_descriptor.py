"""USB HID report-descriptor parser: items, usages, ranges, units, report IDs, push/pop.

Follows the HID 1.11 item encoding and the Linux ``hid-core.c`` readings where devices bend
the spec (facts §4.2): Logical/Physical Maximum is read unsigned unless the minimum is
negative; a Unit Exponent that fits in 4 bits is a 4-bit two's-complement nibble; 1- and
2-byte usages take the Usage Page in force at the main item.
"""

from __future__ import annotations

from dataclasses import dataclass, field

MAIN_INPUT, MAIN_OUTPUT, MAIN_COLLECTION, MAIN_FEATURE, MAIN_END = 8, 9, 10, 11, 12
KINDS = {MAIN_INPUT: "input", MAIN_OUTPUT: "output", MAIN_FEATURE: "feature"}
# Linux hid-core's limits: a descriptor beyond them is refused by the kernel too, and a
# Report Count of 0x7fffffff would otherwise mean a 2-billion-entry usage table
MAX_REPORT_COUNT = 12288  # HID_MAX_USAGES
MAX_REPORT_BITS = 16384 * 8  # HID_MAX_BUFFER_SIZE bytes
FLAG_CONSTANT, FLAG_VARIABLE, FLAG_RELATIVE = 0x01, 0x02, 0x04
VENDOR_WACOM_PAGE = 0xFF0D


class HidDescriptorError(ValueError):
    """A malformed descriptor; the message names the source and byte offset."""


def canonical_usage(usage: int) -> int:
    """Map Wacom's vendor page 0xFF0Dxxyy onto the standard usage it mirrors (kernel rule)."""
    if usage >> 16 == VENDOR_WACOM_PAGE:
        sub, uid = usage >> 8 & 0xFF, usage & 0xFF
        return (0x0D if sub == 0 else sub) << 16 | uid
    return usage


def _signed(value: int, size_bytes: int) -> int:
    bits = size_bytes * 8
    if bits and value & (1 << (bits - 1)):
        return value - (1 << bits)
    return value


@dataclass(frozen=True)
class HidField:
    kind: str  # "input", "output" or "feature"
    report_id: int
    bit_offset: int  # from the first byte after the report ID
    size: int  # bits per value
    count: int
    usages: tuple[int, ...]  # 32-bit usages; per value for variable fields, choices for arrays
    flags: int
    logical_min: int
    logical_max: int
    physical_min: int
    physical_max: int
    unit: int
    unit_exponent: int
    collections: tuple[int, ...]  # usages of enclosing collections, outermost first
    item_offset: int  # byte offset of the main item in the descriptor

    @property
    def constant(self) -> bool:
        return bool(self.flags & FLAG_CONSTANT)

    @property
    def variable(self) -> bool:
        return bool(self.flags & FLAG_VARIABLE)

    @property
    def signed(self) -> bool:
        return self.logical_min < 0

    def usage_at(self, index: int) -> int:
        if not self.usages:
            return 0
        return self.usages[min(index, len(self.usages) - 1)]

    def resolution_per_mm(self) -> float | None:
        """Units per millimetre, as hid-input's ``hidinput_calc_abs_res`` computes it."""
        logical = self.logical_max - self.logical_min
        pmin, pmax = self.physical_min, self.physical_max
        if pmin == pmax == 0:
            return None
        physical = float(pmax - pmin)
        if self.unit == 0x11:  # centimetre
            physical *= 10.0 ** (self.unit_exponent + 1)
        elif self.unit == 0x13:  # inch
            physical *= 25.4 * 10.0 ** self.unit_exponent
        else:
            return None
        return logical / physical if physical > 0 else None


@dataclass
class _Globals:
    usage_page: int = 0
    logical_min: int = 0
    logical_max: int = 0
    physical_min: int = 0
    physical_max: int = 0
    unit_exponent: int = 0
    unit: int = 0
    report_size: int = 0
    report_id: int = 0
    report_count: int = 0

    def copy(self) -> _Globals:
        return _Globals(**self.__dict__)


@dataclass
class ReportDescriptor:
    data: bytes
    fields: list[HidField] = field(default_factory=list)
    applications: list[int] = field(default_factory=list)
    uses_report_ids: bool = False

    def report_ids(self, kind: str = "input") -> list[int]:
        return sorted({f.report_id for f in self.fields if f.kind == kind})

    def fields_for(self, report_id: int, kind: str = "input") -> list[HidField]:
        return [f for f in self.fields if f.report_id == report_id and f.kind == kind]

    def report_bits(self, report_id: int, kind: str = "input") -> int:
        return max((f.bit_offset + f.size * f.count for f in self.fields_for(report_id, kind)),
                   default=0)

    def report_length(self, report_id: int, kind: str = "input") -> int:
        """Bytes including the report-ID byte (when the device numbers its reports)."""
        return (self.report_bits(report_id, kind) + 7) // 8 + (1 if self.uses_report_ids else 0)

    def find(self, usage: int, kind: str = "input") -> list[HidField]:
        return [f for f in self.fields if f.kind == kind
                and any(canonical_usage(u) == usage for u in f.usages)]


def parse_descriptor(data: bytes, source: str = "<descriptor>") -> ReportDescriptor:
    desc = ReportDescriptor(bytes(data))
    g = _Globals()
    stack: list[_Globals] = []
    usages: list[tuple[int, int]] = []  # (value, size in bytes)
    usage_min: tuple[int, int] | None = None
    usage_max_seen: tuple[int, int] | None = None
    collections: list[int] = []
    offsets: dict[tuple[str, int], int] = {}
    i = 0

    def fail(at: int, message: str) -> HidDescriptorError:
        return HidDescriptorError(f"{source}: byte {at}: {message}")

    def resolve(value: int, size: int) -> int:
        return value if size == 4 else g.usage_page << 16 | value

    while i < len(data):
        at = i
        prefix = data[i]
        if prefix == 0xFE:  # long item: skip its data
            if i + 2 >= len(data):
                raise fail(at, "truncated long item")
            i += 3 + data[i + 1]
            if i > len(data):
                raise fail(at, "long item runs past the end")
            continue
        size = (0, 1, 2, 4)[prefix & 3]
        kind, tag = prefix >> 2 & 3, prefix >> 4
        if i + 1 + size > len(data):
            raise fail(at, f"item {prefix:#04x} needs {size} data bytes, descriptor ends")
        value = int.from_bytes(data[i + 1 : i + 1 + size], "little")
        i += 1 + size
        if kind == 0:  # main
            if tag in KINDS:
                local_usages = [resolve(v, s) for v, s in usages]
                if usage_min is not None and usage_max_seen is not None:
                    lo, hi = resolve(*usage_min), resolve(*usage_max_seen)
                    if hi < lo or hi - lo > 0xFFFF:
                        raise fail(at, f"usage range {lo:#x}..{hi:#x} is not usable")
                    local_usages.extend(range(lo, hi + 1))
                if g.report_size == 0 and g.report_count:
                    raise fail(at, "Report Size is 0")
                if g.report_size > 256:  # hid-core's limit; 10moons declares 63 bits
                    raise fail(at, f"Report Size {g.report_size} > 256 bits")
                kind_name = KINDS[tag]
                key = (kind_name, g.report_id)
                offset = offsets.get(key, 0)
                if value & FLAG_VARIABLE and local_usages:
                    per_value = tuple(local_usages[min(k, len(local_usages) - 1)]
                                      for k in range(g.report_count))
                else:
                    per_value = tuple(local_usages)
                desc.fields.append(HidField(
                    kind_name, g.report_id, offset, g.report_size, g.report_count, per_value,
                    value, g.logical_min, g.logical_max, g.physical_min, g.physical_max,
                    g.unit, g.unit_exponent, tuple(collections), at,
                ))
                offsets[key] = offset + g.report_size * g.report_count
                if offsets[key] > MAX_REPORT_BITS:
                    raise fail(at, f"{kind_name} report {g.report_id} is over "
                                   f"{MAX_REPORT_BITS // 8} bytes (hid-core's buffer)")
            elif tag == MAIN_COLLECTION:
                first = resolve(*usages[0]) if usages else 0
                collections.append(first)
                if value == 1:
                    desc.applications.append(first)
            elif tag == MAIN_END:
                if not collections:
                    raise fail(at, "End Collection without a Collection")
                collections.pop()
            else:
                raise fail(at, f"unknown main item tag {tag}")
            usages, usage_min, usage_max_seen = [], None, None
        elif kind == 1:  # global
            if tag == 0:
                g.usage_page = value
            elif tag == 1:
                g.logical_min = _signed(value, size)
            elif tag == 2:
                g.logical_max = _signed(value, size) if g.logical_min < 0 else value
            elif tag == 3:
                g.physical_min = _signed(value, size)
            elif tag == 4:
                g.physical_max = _signed(value, size) if g.physical_min < 0 else value
            elif tag == 5:
                raw = _signed(value, size)
                g.unit_exponent = (raw - 16 if raw & 8 else raw) if 0 <= raw < 16 else raw
            elif tag == 6:
                g.unit = value
            elif tag == 7:
                g.report_size = value
            elif tag == 8:
                if value == 0:
                    raise fail(at, "Report ID 0 is reserved")
                g.report_id = value
                desc.uses_report_ids = True
            elif tag == 9:
                if value > MAX_REPORT_COUNT:
                    raise fail(at, f"Report Count {value} > {MAX_REPORT_COUNT} (hid-core's "
                                   "HID_MAX_USAGES)")
                g.report_count = value
            elif tag == 10:
                stack.append(g.copy())
            elif tag == 11:
                if not stack:
                    raise fail(at, "Pop without Push")
                g = stack.pop()
            else:
                raise fail(at, f"unknown global item tag {tag}")
        elif kind == 2:  # local
            if tag == 0:
                usages.append((value, size))
            elif tag == 1:
                usage_min = (value, size)
            elif tag == 2:
                usage_max_seen = (value, size)
            # designators, strings and delimiters carry nothing a pen decoder needs
        else:
            raise fail(at, f"reserved item type in prefix {prefix:#04x}")
    if collections:
        raise HidDescriptorError(f"{source}: byte {len(data)}: {len(collections)} collection(s) "
                                 "not closed")
    return desc


def parse_hex_text(text: str, source: str = "<hex>") -> bytes:
    """Hex bytes from usbhid-dump / kernel-selftest text; header lines with ``:`` are skipped."""
    out = bytearray()
    for lineno, line in enumerate(text.splitlines(), 1):
        stripped = line.strip()
        if not stripped or ":" in stripped:
            continue
        for word in stripped.split():
            try:
                out.append(int(word, 16))
            except ValueError:
                raise HidDescriptorError(f"{source}: line {lineno}: not a hex byte: {word!r}"
                                         ) from None
    return bytes(out)
