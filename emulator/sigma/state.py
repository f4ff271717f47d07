"""Save / load a terminal's state: a versioned header (JSON registers) + the arrays (npz).

Decoder state kept: mode, coordinate width, GH, line start. A partly received order is not
kept (save between whole orders, as any front-end does between feeds).
"""

from __future__ import annotations

import io
import json
from dataclasses import asdict, fields
from typing import TYPE_CHECKING

import numpy as np

from protocols.sigma.orders import Mode

if TYPE_CHECKING:
    from emulator.sigma.terminal import Terminal

MAGIC = b"CAMLAB88-SIGMA-STATE\n"
VERSION = 1


def save(t: Terminal) -> bytes:
    from emulator.sigma.terminal import Registers

    d = t.decoder
    header = {
        "version": VERSION,
        "model": t.model.name,
        "registers": asdict(t.reg),
        "register_names": [f.name for f in fields(Registers)],
        "decoder": {"mode": d.mode.value, "coord_digits": d.coord_digits, "gh": d.gh,
                    "line_start": d._line_start},
        "alpha_cursor": [t.alpha.row, t.alpha.col],
        "errors": t.errors,
    }
    buf = io.BytesIO()
    np.savez_compressed(buf, planes=t.planes, lut=t.lut, alpha=t.alpha.chars)
    head = json.dumps(header, sort_keys=True).encode("utf-8")
    return MAGIC + len(head).to_bytes(4, "big") + head + buf.getvalue()


def load(t: Terminal, data: bytes) -> None:
    from emulator.sigma.terminal import Registers

    if not data.startswith(MAGIC):
        raise ValueError("not a camlab88 Sigma state (bad magic at byte 0)")
    off = len(MAGIC)
    n = int.from_bytes(data[off:off + 4], "big")
    try:
        header = json.loads(data[off + 4:off + 4 + n].decode("utf-8"))
    except (UnicodeDecodeError, json.JSONDecodeError) as exc:
        raise ValueError(f"Sigma state header is corrupt (byte {off + 4}): {exc}") from None
    if header.get("version") != VERSION:
        raise ValueError(f"Sigma state version {header.get('version')} is not {VERSION}")
    if header.get("model") != t.model.name:
        raise ValueError(f"Sigma state is for {header.get('model')}, terminal is {t.model.name}")
    try:
        arrays = np.load(io.BytesIO(data[off + 4 + n:]), allow_pickle=False)
        planes, lut, alpha = arrays["planes"], arrays["lut"], arrays["alpha"]
    except Exception as exc:  # noqa: BLE001 - any damage to the array part
        raise ValueError(f"Sigma state arrays are corrupt (byte {off + 4 + n}): {exc}") from None
    if planes.shape != t.planes.shape or lut.shape != t.lut.shape or alpha.shape != \
            t.alpha.chars.shape:
        raise ValueError("Sigma state arrays have the wrong shapes for this model")
    t.planes = planes.astype(np.uint8)
    t.lut = lut.astype(np.uint8)
    t.alpha.chars = alpha.astype(np.uint8)
    t.alpha.row, t.alpha.col = header["alpha_cursor"]
    t.alpha._mask = None
    t.reg = Registers(**header["registers"])
    dec = header["decoder"]
    t.decoder._clear_partial()
    t.decoder.mode = Mode(dec["mode"])
    t.decoder.coord_digits = dec["coord_digits"]
    t.decoder.gh = dec["gh"]
    t.decoder._line_start = dec["line_start"]
    t.errors = header["errors"]
