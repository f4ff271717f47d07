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
from dataclasses import asdict
from typing import TYPE_CHECKING

import numpy as np

from camlab88.protocols.sigma.decoder_state import DecoderState

if TYPE_CHECKING:
    from camlab88.emulator.sigma.terminal import Terminal

MAGIC = b"CAMLAB88-SIGMA-STATE\n"
VERSION = 2
READABLE = (1, 2)


def save(t: Terminal, compress: bool = True) -> bytes:
    """The file: each part of the terminal gives its own state (PyBoy's mb.save_state)."""
    reg, planes, lut, errors = t.own_state()
    cursor, chars = t.alpha.save_state()
    header = {
        "arrays": "zlib" if compress else "raw",
        "version": VERSION,
        "model": t.model.name,
        "registers": asdict(reg),
        "decoder": t.decoder.get_state(),
        "alpha_cursor": [cursor["row"], cursor["col"]],
        "errors": errors,
    }
    raw = b"".join(np.ascontiguousarray(a, dtype=np.uint8).tobytes()
                   for a in (planes, lut, chars))
    head = json.dumps(header, sort_keys=True).encode("utf-8")
    return MAGIC + len(head).to_bytes(4, "big") + head + (zlib.compress(raw, 1) if compress
                                                          else raw)


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
    except Exception as exc:  # any damage to the array part
        raise ValueError(f"Sigma state arrays are corrupt (byte {off + 4 + n}): {exc}") from None
    if planes.shape != t.planes.shape or lut.shape != t.lut.shape or alpha.shape != \
            t.alpha.chars.shape:
        raise ValueError("Sigma state arrays have the wrong shapes for this model")
    for key in ("registers", "decoder", "alpha_cursor", "errors"):
        if key not in header:
            raise ValueError(f"Sigma state header lacks {key!r}")
    _restore(t, header, version, planes, lut, alpha)


def _restore(t: Terminal, header: dict, version: int, planes: np.ndarray, lut: np.ndarray,
             alpha: np.ndarray) -> None:
    """Check every part's state first, then hand each part its own."""
    from camlab88.emulator.sigma.alpha import AlphaScreen
    from camlab88.emulator.sigma.terminal import Registers

    reg = Registers.from_json(header["registers"])
    c = header["alpha_cursor"]
    cursor = {"row": c[0], "col": c[1]} if isinstance(c, list) and len(c) == 2 else c
    AlphaScreen.check_state(cursor, alpha)
    if type(header["errors"]) is not int or header["errors"] < 0:
        raise ValueError(f"Sigma state 'errors'={header['errors']!r} is not a count")
    dec = (DecoderState.from_json(header["decoder"], t.decoder.MAX_TEXT) if version >= 2
           else DecoderState.from_v1(header["decoder"]))
    t.restore_own(reg, planes, lut, header["errors"])
    t.alpha.load_state(cursor, alpha)
    t.decoder.resume(dec)
