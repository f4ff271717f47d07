"""A real pseudo-terminal, opened by pyserial as a serial port."""

from __future__ import annotations

import serial

from camlab88.protocols.link import SerialLine
from camlab88.protocols.link.pty import PtyPort
from tests.link.exactly import read_exactly


def test_pyserial_opens_the_slave_and_all_256_byte_values_pass_both_ways() -> None:
    with PtyPort() as pty:
        client = serial.Serial(pty.slave_path, baudrate=9600, timeout=2)
        try:
            everything = bytes(range(256))
            client.write(everything)  # includes CR, LF, DC1, DC3, ^C: raw mode keeps them
            got = b""
            while len(got) < 256:
                more = pty.read(timeout=2)
                assert more
                got += more
            assert got == everything
            pty.write(everything[::-1])
            assert read_exactly(client.read, 256) == everything[::-1]
        finally:
            client.close()


def test_client_may_reconnect_and_nobody_reading_never_blocks() -> None:
    with PtyPort() as pty:
        serial.Serial(pty.slave_path, timeout=1).close()
        pty.write(b"x" * 200_000)  # no reader: the master never blocks
        assert 0 < pty.backlog < 200_000  # the kernel took some, the rest waits, bounded
        again = serial.Serial(pty.slave_path, timeout=2)
        try:
            again.reset_input_buffer()
            assert pty.discard_backlog() > 0  # what a cable nobody listened to would lose
            pty.write(b"ping")
            assert read_exactly(again.read, 4) == b"ping"
        finally:
            again.close()
    assert pty.closed


def test_read_times_out_with_nothing() -> None:
    with PtyPort() as pty:
        assert pty.read(timeout=0.01) == b""


def test_pty_bridge_end_to_end_with_pyserial() -> None:
    from camlab88.protocols.link.transports import PtyBridge

    line = SerialLine()
    with PtyBridge(line.host) as bridge:  # an outside program plays the host
        client = serial.Serial(bridge.slave_path, timeout=2)
        try:
            client.write(b"+-*/HELLO")
            got = b""
            while len(got) < 9:
                bridge.poll(timeout=1)  # outside bytes enter the line at clock.now
                line.clock.advance(0.04)
                got += line.device.read()
            assert got == b"+-*/HELLO"
            line.device.write(b"REPORT\r")  # the device answers up the line
            line.clock.advance(1)
            bridge.poll()
            assert read_exactly(client.read, 7) == b"REPORT\r"
        finally:
            client.close()


def test_a_program_opening_the_slave_without_setting_it_up_gets_the_bytes_raw() -> None:
    # the pty itself is raw: a program that opens it as it is (as `cat` would, no termios
    # calls of its own) sees CR, DC1 and DC3 as sent, with no line editing or flow control
    import os
    import select

    with PtyPort() as pty:
        fd = os.open(pty.slave_path, os.O_RDWR | os.O_NOCTTY | os.O_NONBLOCK)
        try:
            data = b"a\rb\x11\x13c"  # no newline: a line-buffered tty would hold it back
            pty.write(data)
            got = b""
            for _ in range(40):
                if len(got) >= len(data) or not select.select([fd], [], [], 0.05)[0]:
                    if got:
                        break
                    continue
                got += os.read(fd, 64)
            assert got == data
        finally:
            os.close(fd)
