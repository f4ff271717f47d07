"""The Sigma keyboard as KAS hears it: bytes the terminal sends up the line <-> key names.

Printable keys send their character.  Return, backspace, tab and escape send CR, BS, HT and
ESC.  The cursor keys and F2 are given single control codes here (reconstructed: the T5684's
function-key codes are not known) - Ctrl-P/N/B/F as in many editors, Ctrl-W for "write";
DC1 and DC3 are avoided because the line uses them for XON/XOFF.
"""

from __future__ import annotations

KEY_BYTES: dict[str, bytes] = {
    "return": b"\r", "backspace": b"\x08", "tab": b"\t", "escape": b"\x1b", "space": b" ",
    "up": b"\x10", "down": b"\x0e", "left": b"\x02", "right": b"\x06", "f2": b"\x17",
}
_NAMES = {v[0]: k for k, v in KEY_BYTES.items()}
_NAMES[0x0A] = "return"
_NAMES[0x7F] = "backspace"


def key_to_bytes(key: str) -> bytes:
    """A key name (as in docs/kas.md) or a single printable character -> its byte."""
    if key in KEY_BYTES:
        return KEY_BYTES[key]
    if len(key) == 1 and 0x20 <= ord(key) <= 0x7E:
        return key.encode("ascii")
    raise ValueError(f"no Sigma key {key!r} (a printable character or one of "
                     f"{', '.join(KEY_BYTES)})")


def bytes_to_keys(data: bytes) -> list[str]:
    """Key names for bytes from the terminal; unknown control bytes are ignored."""
    out = []
    for b in data:
        if b in _NAMES:
            out.append(_NAMES[b])
        elif 0x20 < b <= 0x7E:
            out.append(chr(b))
    return out
