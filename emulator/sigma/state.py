"""Save / load a terminal's state: a versioned header (JSON) + the arrays.

Version 2 keeps ALL of the decoder's partial state (Decoder.get_state: a half-read order or
coordinate pair, the abbreviated-mode registers HiY/EB/LoY/HiX and the first-point-is-a-move
flag, a held DJ dot, BA text so far, the counters), so a state saved between any two bytes
of a stream continues to exactly the same picture. The arrays (planes, LUT, alpha cells;
shapes fixed by the model) follow the header as raw uint8 bytes, deflated at level 1 unless
the caller asks for speed over size (``compress=False``: a T5688 state is then 1.5 MB).
Version 1 files (no partial state, compressed npz) still load, their decoder starting
between orders.
"""

from __future__ import annotations

import io
import json
import zlib
from dataclasses import asdict, fields
from typing import TYPE_CHECKING

import numpy as np

from protocols.sigma.orders import Mode

if TYPE_CHECKING:
    from emulator.sigma.terminal import Terminal

MAGIC = b"CAMLAB88-SIGMA-STATE\n"
VERSION = 2
READABLE = (1, 2)


def save(t: Terminal, compress: bool = True) -> bytes:
    header = {
        "arrays": "zlib" if compress else "raw",
        "version": VERSION,
        "model": t.model.name,
        "registers": asdict(t.reg),
        "decoder": t.decoder.get_state(),
        "alpha_cursor": [t.alpha.row, t.alpha.col],
        "errors": t.errors,
    }
    raw = b"".join(np.ascontiguousarray(a, dtype=np.uint8).tobytes()
                   for a in (t.planes, t.lut, t.alpha.chars))
    head = json.dumps(header, sort_keys=True).encode("utf-8")
    return MAGIC + len(head).to_bytes(4, "big") + head + (zlib.compress(raw, 1) if compress
                                                          else raw)


def _registers(t: Terminal, regs: object):  # noqa: ANN202 - a terminal.Registers
    from emulator.sigma.terminal import Registers

    if not isinstance(regs, dict):
        raise ValueError("Sigma state 'registers' is not a mapping")
    known = {f.name: f for f in fields(Registers)}
    for name in regs:
        if name not in known:
            raise ValueError(f"Sigma state has an unknown register {name!r}")
    for name in known:
        if name not in regs:
            raise ValueError(f"Sigma state lacks the register {name!r}")
    defaults = Registers()
    for name, v in regs.items():
        want = type(getattr(defaults, name))
        if type(v) is not want or (want is int and not -(1 << 31) <= v < 1 << 31):
            raise ValueError(f"Sigma state register {name!r}={v!r} is not a {want.__name__}")
    return Registers(**regs)


def _split(raw: bytes, t: Terminal) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    shapes = (t.planes.shape, t.lut.shape, t.alpha.chars.shape)
    sizes = [int(np.prod(s)) for s in shapes]
    if len(raw) != sum(sizes):
        raise ValueError(f"{len(raw)} array bytes, the model needs {sum(sizes)}")
    out, k = [], 0
    for shape, size in zip(shapes, sizes, strict=True):
        out.append(np.frombuffer(raw, dtype=np.uint8, count=size, offset=k).reshape(shape))
        k += size
    return out[0], out[1], out[2]


def load(t: Terminal, data: bytes) -> None:
    if not data.startswith(MAGIC):
        raise ValueError("not a camlab88 Sigma state (bad magic at byte 0)")
    off = len(MAGIC)
    n = int.from_bytes(data[off:off + 4], "big")
    try:
        header = json.loads(data[off + 4:off + 4 + n].decode("utf-8"))
    except (UnicodeDecodeError, json.JSONDecodeError) as exc:
        raise ValueError(f"Sigma state header is corrupt (byte {off + 4}): {exc}") from None
    if not isinstance(header, dict):
        raise ValueError(f"Sigma state header is corrupt (byte {off + 4}): not a mapping")
    version = header.get("version")
    if version not in READABLE:
        raise ValueError(f"Sigma state version {version} is not one of {READABLE}")
    if header.get("model") != t.model.name:
        raise ValueError(f"Sigma state is for {header.get('model')}, terminal is {t.model.name}")
    try:
        raw = data[off + 4 + n:]
        if version >= 2:
            packing = header.get("arrays")
            if packing not in ("zlib", "raw"):
                raise ValueError(f"array packing {packing!r} is not 'zlib' or 'raw'")
            planes, lut, alpha = _split(zlib.decompress(raw) if packing == "zlib" else raw, t)
        else:
            arrays = np.load(io.BytesIO(raw), allow_pickle=False)
            planes, lut, alpha = arrays["planes"], arrays["lut"], arrays["alpha"]
    except Exception as exc:  # noqa: BLE001 - any damage to the array part
        raise ValueError(f"Sigma state arrays are corrupt (byte {off + 4 + n}): {exc}") from None
    if planes.shape != t.planes.shape or lut.shape != t.lut.shape or alpha.shape != \
            t.alpha.chars.shape:
        raise ValueError("Sigma state arrays have the wrong shapes for this model")
    for key in ("registers", "decoder", "alpha_cursor", "errors"):
        if key not in header:
            raise ValueError(f"Sigma state header lacks {key!r}")
    reg = _registers(t, header["registers"])
    cursor = header["alpha_cursor"]
    rows, cols = t.alpha.chars.shape
    if not (isinstance(cursor, list) and len(cursor) == 2 and all(type(v) is int for v in cursor)
            and 0 <= cursor[0] < rows and 0 <= cursor[1] < cols):
        raise ValueError(f"Sigma state 'alpha_cursor'={cursor!r} is not a cell of the screen")
    if type(header["errors"]) is not int or header["errors"] < 0:
        raise ValueError(f"Sigma state 'errors'={header['errors']!r} is not a count")
    dec = header["decoder"]
    if version >= 2:
        t.decoder.set_state(dec)  # validates everything before changing anything
    else:
        try:
            t.decoder._clear_partial()
            t.decoder.mode = Mode(dec["mode"])
            t.decoder.coord_digits = int(dec["coord_digits"])
            t.decoder.gh = bool(dec["gh"])
            t.decoder._line_start = bool(dec["line_start"])
        except (KeyError, TypeError, ValueError) as exc:
            raise ValueError(f"Sigma state 'decoder' is corrupt: {exc!r}") from None
    t.planes = planes.astype(np.uint8)
    t.lut = lut.astype(np.uint8)
    t.alpha.chars = alpha.astype(np.uint8)
    t.alpha.row, t.alpha.col = cursor
    t.alpha._mask = None
    t.reg = reg
    t.errors = header["errors"]
