"""Serial line settings and start-up sequences per protocol (facts §1.1, §2.1, §2.3, §3.2).

``wire_*`` is how the port is opened.  A 7-data-bit line with parity has the same 10-bit frame
as 8N1, so it is opened 8N1 and the parity bit (bit 7) is checked in software: that works
identically on a real UART, a pty and a socket.  An 8-bit line with parity (Summagraphics 8O1)
is opened with that parity and, on a POSIX port, PARMRK so errors reach the parser.

Flow control is per direction.  Every protocol here sends binary reports whose data bytes
may be 0x11 or 0x13, so software flow control on what the tablet sends (IXON) is never on:
the tty driver would swallow those bytes as XON/XOFF.  ``xoff_to_tablet`` says the tablet
obeys XOFF/XON from the host (IXOFF: the driver sends XOFF when its input buffer fills);
only the Summagraphics line uses it ("FlowControl Xoff", facts §2.1).
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class InitStep:
    data: bytes
    wait: float = 0.0  # seconds to wait after sending
    baud: int | None = None  # switch the port to this baud before sending
    expect_reply: bool = False  # a ~/CR-terminated reply is expected (read up to ``wait``)
    flush: bool = False  # after the wait, discard whatever the tablet sent so far
    size_reply: bool = False  # the reply is a report whose X/Y are the maximum X/Y


@dataclass(frozen=True)
class LineSetup:
    protocol: str
    baud: int
    data_bits: int
    parity: str  # "N", "E", "O"
    stop_bits: int
    xoff_to_tablet: bool  # IXOFF: the host may pause the tablet; IXON is never set
    rtscts: bool
    init: tuple[InitStep, ...]
    source: str  # where these settings come from

    @property
    def software_parity(self) -> str:
        return self.parity if self.data_bits == 7 and self.stop_bits == 1 else "N"

    @property
    def wire(self) -> tuple[int, str, int]:
        """(bytesize, parity, stopbits) to open the port with."""
        if self.data_bits == 7 and self.parity != "N" and self.stop_bits == 1:
            return 8, "N", 1
        return self.data_bits, self.parity, self.stop_bits

    def describe(self) -> str:
        flow = ("RTS/CTS" if self.rtscts else "XOFF to the tablet" if self.xoff_to_tablet
                else "none")
        return f"{self.baud} {self.data_bits}{self.parity}{self.stop_bits}, flow {flow}"


def _wacom_reset() -> tuple[InitStep, ...]:
    steps: list[InitStep] = []
    for baud in (38400, 19200, 9600):
        steps.append(InitStep(b"\r$", 0.25, baud))
        steps.append(InitStep(b"\r#", 0.075))
    steps.append(InitStep(b"SP\r", 0.03))
    steps.append(InitStep(b"~#", 1.0, expect_reply=True))
    steps.append(InitStep(b"~R\r", 1.0, expect_reply=True))
    steps.append(InitStep(b"~C\r", 1.0, expect_reply=True))
    return tuple(steps)


SETUPS: dict[str, LineSetup] = {
    "wacom4": LineSetup(
        "wacom4", 9600, 8, "N", 1, False, True, _wacom_reset(),
        "inputattach --wacom_iv + wacom_serial4.c; the model setup string follows ~#",
    ),
    "summa-mm": LineSetup(
        "summa-mm", 9600, 8, "O", 1, True, False,
        (
            InitStep(b" " * 10 + b"\x00", 0.4),
            # Prompt mode first: a streaming tablet would otherwise answer "a" among its
            # ordinary reports; drop what is already in flight (as inputattach's EasyPen init).
            InitStep(b"B", 0.05, flush=True),
            InitStep(b"0b", 0.0),
            InitStep(b"zb", 0.0),
            InitStep(b"h", 0.0),
            InitStep(b"a", 0.5, expect_reply=True, size_reply=True),
            InitStep(b"@", 0.0),  # stream mode
            InitStep(b"I" + bytes((32 + 0,)), 0.0),  # increment 0
            InitStep(b"F", 0.0),  # absolute
        ),
        "XFree86 summa driver xf86SumOpen / gpm I_summa",
    ),
    "bitpad2": LineSetup(
        "bitpad2", 9600, 7, "E", 1, False, False, (),
        "Bit Pad Two Users Guide: 7 data bits, parity by DIP switch (E chosen); command "
        "letters are not recovered, so nothing is sent",
    ),
    "bitpad1": LineSetup(
        "bitpad1", 9600, 8, "N", 1, False, False, (),
        "reconstructed: the PERQ's Bit Pad One was on GPIB; serial settings by DIP switch",
    ),
    "calcomp": LineSetup(
        "calcomp", 9600, 8, "N", 1, False, False,
        (
            InitStep(b"\x1b%^23\r", 0.05),
            InitStep(b"\x1b%VA0\r", 0.05),
            InitStep(b"\x1b%JR1000,0\r", 0.05),  # 1000 lpi, the model's resolution
            InitStep(b"\x1b%H\r", 0.05, flush=True),  # stop streaming before asking
            InitStep(b"\x1b%__V\r", 0.5, expect_reply=True),
            InitStep(b"\x1b%VS\r", 0.5, expect_reply=True, size_reply=True),
            InitStep(b"\x1b%IR\r", 0.05),
        ),
        "XFree86 calcomp driver defaults (9600 8N1, no flow control) and commands",
    ),
}


def line_setup(protocol: str) -> LineSetup:
    try:
        return SETUPS[protocol]
    except KeyError:
        raise ValueError(
            f"unknown tablet protocol {protocol!r} (known: {', '.join(SETUPS)})"
        ) from None
