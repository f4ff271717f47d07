"""The Sigma keyboard: what each key sends up the line, the one table the terminal
(camlab88.emulator.sigma.Terminal.press), its window and the programs that hear the keys
(the KAS fronts) all read.

It lives among the wire formats, not in the device package, because it is a wire format
(bytes on the line) and the programs may not import the emulator (the import contracts in
pyproject.toml): protocols/ is what both sides may reach.

Printable keys send their character. Return (and keypad Enter), backspace, delete, tab and
escape send CR, BS, DEL, HT and ESC. The cursor keys and F2 send single control codes
(reconstructed: the T5684's function-key codes are not known) - Ctrl-P/N/B/F as in many
editors, Ctrl-W for "write"; DC1 and DC3 are avoided because the line uses them for
XON/XOFF. While a cursor read is armed with the crosshair on the keys (``HF`` after ``CF``)
the cursor keys move the crosshair instead (``CURSOR_STEPS``; the terminal decides).
docs/fidelity/sigma.md lists which codes are documented and which reconstructed.
"""

from __future__ import annotations

KEY_BYTES: dict[str, bytes] = {
    "return": b"\r", "backspace": b"\x08", "tab": b"\t", "escape": b"\x1b", "space": b" ",
    "up": b"\x10", "down": b"\x0e", "left": b"\x02", "right": b"\x06", "f2": b"\x17",
    "kp_enter": b"\r", "delete": b"\x7f",
}
# the crosshair's move for a cursor key during a cursor read (device units, y up)
CURSOR_STEPS: dict[str, tuple[int, int]] = {
    "left": (-1, 0), "right": (1, 0), "up": (0, 1), "down": (0, -1)}
_NAMES: dict[int, str] = {}
for _name, _code in KEY_BYTES.items():
    _NAMES.setdefault(_code[0], _name)  # the first name of a code is the one heard
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
