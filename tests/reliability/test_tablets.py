"""A HID descriptor asking for 2^31 values and a tablet on a dead port: bounded, with a
message."""

from __future__ import annotations

import pytest
import serial

from camlab88.protocols.tablets import serial_source
from camlab88.protocols.tablets.hid_descriptor import HidDescriptorError, parse_descriptor
from camlab88.protocols.tablets.sources import SourceLost, parse_source

# Usage Page (Digitizer), Usage (Pen), Collection (Application), Usage (Tip Pressure),
# Report Size 8, Report Count 0x7fffffff, Input (Data, Var, Abs), End Collection
HUGE_COUNT = bytes.fromhex("05 0d 09 02 a1 01 09 30 75 08 97 ff ff ff 7f 81 02 c0")
# the same with 2049 values of 64 bits: just past hid-core's buffer
HUGE_REPORT = bytes.fromhex("05 0d 09 02 a1 01 09 30 75 40 96 01 08 81 02 c0")


def test_a_report_count_of_2_to_the_31_is_refused_at_once() -> None:
    with pytest.raises(HidDescriptorError, match=r"byte 10: Report Count 2147483647 > 12288"):
        parse_descriptor(HUGE_COUNT, "d.bin")


def test_a_report_past_hid_cores_buffer_is_refused() -> None:
    with pytest.raises(HidDescriptorError, match="over 16384 bytes"):
        parse_descriptor(HUGE_REPORT, "d.bin")


class _DeadPort:
    """A port whose transmitter never drains (no UART behind it, CTS never raised)."""

    baudrate = 9600
    in_waiting = 0

    def __init__(self, **kw: object) -> None:
        self.kw = kw

    def write(self, data: bytes) -> int:
        raise serial.SerialTimeoutException("Write timeout")

    def read(self, n: int = 1) -> bytes:
        return b""

    def reset_input_buffer(self) -> None:
        pass

    def fileno(self) -> int:
        raise AttributeError

    def close(self) -> None:
        pass


def test_a_dead_port_is_reported_not_waited_on_for_ever(monkeypatch) -> None:
    opened: list[dict] = []

    def fake_open(url: str, **kw: object) -> _DeadPort:
        opened.append(kw)
        return _DeadPort(**kw)

    monkeypatch.setattr(serial, "serial_for_url", fake_open)
    with pytest.raises(SourceLost, match="took no bytes for 2 s"):
        serial_source.SerialSource(parse_source("serial:/dev/ttyS9?protocol=summa-mm"),
                                   sleep=lambda s: None)
    assert opened[0]["write_timeout"] == serial_source.WRITE_TIMEOUT
