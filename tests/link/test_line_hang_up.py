"""Endpoint.hang_up: the line between two sessions of a listener — what is queued either way
and what arrived unread at the hanging-up end is dropped, XON/XOFF is back to running,
characters already on the wire complete; queued() counts what has not yet started."""

from __future__ import annotations

from fractions import Fraction

from camlab88.protocols.link import XOFF, LineSettings, SerialLine


def test_hang_up_drops_both_queues_and_what_arrived_unread() -> None:
    line = SerialLine(LineSettings())
    line.host.write(b"A" * 100)
    line.device.write(b"d" * 50)
    line.clock.advance_to(Fraction(10, 960))  # eleven characters each way have started
    assert line.host.queued() == 89 and line.device.queued() == 39
    dropped = line.host.hang_up()
    assert line.host.queued() == line.device.queued() == 0
    assert dropped == 89 + 39 + 11  # both queues, and the device's 11 for the host end
    line.clock.advance_to(1)
    assert line.host.read() == b""
    assert line.device.read() == b"A" * 11  # what the host end had started completes


def test_hang_up_resumes_a_transmitter_paused_by_the_old_client() -> None:
    line = SerialLine(LineSettings())
    line.host.write(bytes([XOFF]))  # the client pauses the device's output, then leaves
    line.clock.advance_to(Fraction(2, 960))
    line.device.write(b"hello")
    line.clock.advance_to(1)
    assert line.host.read() == b""  # paused
    line.host.hang_up()
    line.device.write(b"next")
    line.clock.advance_to(2)
    assert line.host.read() == b"next"
