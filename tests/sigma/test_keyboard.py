"""The Sigma keyboard is one table (protocols.sigma.keyboard): the terminal sends what it
says for every key, and the KAS programs hear back the key that was struck."""

from __future__ import annotations

import pytest

from camlab88.emulator.machine import SigmaMachine
from camlab88.emulator.sigma import Terminal
from camlab88.protocols.sigma.keyboard import KEY_BYTES, bytes_to_keys, key_to_bytes


def test_every_key_sends_its_code_and_is_heard_as_itself() -> None:
    t = Terminal("t5684")
    sent: list[bytes] = []
    t.on_output = sent.append
    for name, code in KEY_BYTES.items():
        t.press(name)
        assert sent[-1] == code, name
        heard = bytes_to_keys(code)
        if name == "delete":  # DEL is heard as the erase key, as LF is heard as return
            assert heard == ["backspace"]
        else:
            assert len(heard) == 1 and KEY_BYTES.get(heard[0], code) == code, (name, heard)
    t.press("f9")  # a key the keyboard has not: nothing
    t.press("x")
    assert sent[-1] == b"x" and len(sent) == len(KEY_BYTES) + 1


def test_the_machine_sends_a_struck_key_up_its_line() -> None:
    m = SigmaMachine()
    m.press("up")
    m.tick(1)
    assert m.host.read() == KEY_BYTES["up"]


def test_names_and_characters_to_bytes_and_back() -> None:
    assert bytes_to_keys(b"ab,.\n\x7f\x01") == ["a", "b", ",", ".", "return", "backspace"]
    assert key_to_bytes("up") == b"\x10" and key_to_bytes("q") == b"q"
    with pytest.raises(ValueError, match="no Sigma key"):
        key_to_bytes("f13")
    codes = b"".join(KEY_BYTES.values())
    assert 0x11 not in codes and 0x13 not in codes  # DC1/DC3 are the line's XON/XOFF
