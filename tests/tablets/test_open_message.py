"""A serial port that does not open is named once with the OS's reason (the repeat newcomer
trial saw pyserial's "cannot open X: [Errno 2] could not open port X: [Errno 2] No such
file or directory: 'X'")."""

from __future__ import annotations

from pathlib import Path

import pytest

from camlab88.protocols.tablets.serial_source import SerialSource
from camlab88.protocols.tablets.sources import SourceLost, parse_source


def test_a_missing_port_is_one_plain_line(tmp_path: Path) -> None:
    port = tmp_path / "ttyUSB9"
    with pytest.raises(SourceLost) as err:
        SerialSource(parse_source(f"serial:{port}?protocol=wacom4"))
    text = str(err.value)
    assert text.endswith(f"cannot open {port}: No such file or directory"), text
    assert "Errno" not in text and text.count(str(port)) == 2  # the source text and the port
