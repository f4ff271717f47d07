"""The Sigma terminal's line as the ledger (docs/fidelity/link.md) says: attached to the host
by a serial line (thesis §3.1.4), 9600 baud, 10-bit characters (8N1), XON/XOFF flow
control (the RAL GKS driver's log)."""

from __future__ import annotations

from fractions import Fraction

from camlab88.emulator.machine.sigma import SigmaMachine


def test_the_sigma_takes_the_hosts_bytes_at_9600_baud_one_10_bit_character_each() -> None:
    m = SigmaMachine("t5684")
    assert str(m.settings) == "9600 8N1"
    m.host.write(b"A" * 96)  # 96 characters of 10 bits at 9600 baud: 0.1 s
    assert m.idle_time() == Fraction(1, 10)
    assert m.tick(Fraction(1, 20)) == b"A" * 48  # half the line time: half the bytes
    assert m.tick(Fraction(1, 20)) == b"A" * 48


def test_a_dc3_from_the_sigmas_end_holds_the_host_until_a_dc1() -> None:
    m = SigmaMachine("t5684")
    m.line.device.write(b"\x13")  # the terminal's end asks the host to stop
    m.tick(Fraction(1, 100))
    m.host.write(b"A" * 10)
    assert m.tick(Fraction(1, 10)) == b""  # held
    m.line.device.write(b"\x11")
    assert m.tick(Fraction(1, 10)) == b"A" * 10  # sent on once the DC1 arrived
    assert m.host.read() == b""  # the flow characters are the line's, not the host's data
