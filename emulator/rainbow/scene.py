"""Scene files for ``camlab88 rainbow render``: a pad graph, pad contents and a LUT as JSON.

    {"lut": [[index, "#rrggbb"], ...],
     "nodes": {NAME: {"type": "pad", "width": W, "height": H, "depth": D,
                      "plane": P, "lut_page": L, "pixels": BASE64 | "fill": V}
                     | {"type": "cluster", "width": W, "height": H}},
     "arcs": [{"parent": NAME, "child": NAME, "x": X, "y": Y, "priority": P, "on": B}]}

"screen" is the predefined root. Defaults: plane 0, lut_page 0, x 0, y 0, priority 0,
on true, fill 0; unlisted LUT entries are black. Every error names the JSON path at fault.
"""

from __future__ import annotations

import base64
import binascii
import json
import re
from pathlib import Path
from typing import Any

import numpy as np

from camlab88.base.textinput import quote, read_json
from camlab88.emulator.rainbow.colour import parse_hex
from camlab88.emulator.rainbow.device import Rainbow
from camlab88.emulator.rainbow.errors import RainbowError
from camlab88.emulator.rainbow.graph import SCREEN


class SceneError(ValueError):
    pass


INT32_MIN, INT32_MAX = -(1 << 31), (1 << 31) - 1


def _int(obj: dict, key: str, path: str, default: int | None = None,
         lo: int | None = None, hi: int | None = None) -> int:
    if key not in obj:
        if default is None:
            raise SceneError(f"{path}.{key}: missing")
        return default
    v = obj[key]
    if not isinstance(v, int) or isinstance(v, bool):
        raise SceneError(f"{path}.{key}: must be an integer, got {json.dumps(v)[:40]}")
    # the command stream carries every number as an int32 (protocols.rainbow.stream)
    lo = INT32_MIN if lo is None else lo
    hi = INT32_MAX if hi is None else hi
    if not lo <= v <= hi:
        raise SceneError(f"{path}.{key}: {v} is outside {lo}..{hi}")
    return v


def _obj(v: Any, path: str) -> dict:
    if not isinstance(v, dict):
        raise SceneError(f"{path}: must be an object")
    return v


PAD_KEYS = ("type", "width", "height", "depth", "plane", "lut_page", "pixels", "fill")
CLUSTER_KEYS = ("type", "width", "height")
ARC_KEYS = ("parent", "child", "x", "y", "priority", "on")


def _known_keys(obj: dict, allowed: tuple[str, ...], path: str) -> None:
    """A misspelt key ("prio", "lutpage") would silently fall back to a default: refuse it."""
    for key in obj:
        if key not in allowed:
            raise SceneError(f"{path}.{key}: unknown key (want {', '.join(allowed)})")


_NODE_REF = re.compile(r"\b(node|pad|cluster) (\d+)\b|\binto (\d+)\b")


def _named(msg: str, ids: dict[int, str]) -> str:
    """Rewrite the device's internal node ids in an error message as the scene's names."""
    def sub(m: re.Match) -> str:
        if m.group(3) is not None:
            n = int(m.group(3))
            return f"into {ids[n]!r}" if n in ids else m.group(0)
        n = int(m.group(2))
        return f"{m.group(1)} {ids[n]!r}" if n in ids else m.group(0)

    return _NODE_REF.sub(sub, msg)


def build_scene(scene: Any, device: Rainbow | None = None, where: str = "scene") -> Rainbow:
    """A device holding the scene (LUT already latched, so a frame shows it at once)."""
    r = device or Rainbow()
    top = _obj(scene, "$")
    for key in top:
        if key not in ("lut", "nodes", "arcs"):
            raise SceneError(f"{where}: $.{key}: unknown key (want lut, nodes, arcs)")
    try:
        _build(r, top)
    except SceneError as exc:
        raise SceneError(f"{where}: {exc}") from None
    r.lut[:] = r.lut_pending
    return r


def _build(r: Rainbow, top: dict) -> None:
    lut = top.get("lut", [])
    if not isinstance(lut, list):
        raise SceneError("$.lut: must be a list of [index, \"#rrggbb\"]")
    for n, entry in enumerate(lut):
        p = f"$.lut[{n}]"
        if not (isinstance(entry, list) and len(entry) == 2):
            raise SceneError(f"{p}: must be [index, \"#rrggbb\"]")
        idx, colour = entry
        if not isinstance(idx, int) or isinstance(idx, bool) or not 0 <= idx < 4096:
            raise SceneError(f"{p}[0]: index must be an integer 0..4095")
        try:
            r.set_lut(idx, [parse_hex(colour)])
        except ValueError as exc:
            raise SceneError(f"{p}[1]: {exc}") from None
    names: dict[str, int] = {"screen": SCREEN}
    ids: dict[int, str] = {SCREEN: "screen"}
    for name, spec in _obj(top.get("nodes", {}), "$.nodes").items():
        p = f"$.nodes.{name}"
        if name == "screen":
            raise SceneError(f"{p}: 'screen' is the predefined root")
        spec = _obj(spec, p)
        kind = spec.get("type")
        if kind in ("pad", "cluster"):
            _known_keys(spec, PAD_KEYS if kind == "pad" else CLUSTER_KEYS, p)
        w = _int(spec, "width", p, lo=1)
        h = _int(spec, "height", p, lo=1)
        try:
            if kind == "cluster":
                names[name] = r.create_cluster(w, h)
            elif kind == "pad":
                depth = _int(spec, "depth", p, lo=0, hi=8)
                plane = _int(spec, "plane", p, 0, 0, 7)
                page = _int(spec, "lut_page", p, 0, 0, 15)
                names[name] = pid = r.create_pad(w, h, depth, plane, page)
                _fill(r, pid, spec, p, w, h, depth)
            else:
                raise SceneError(f"{p}.type: must be \"pad\" or \"cluster\", got {quote(kind)}")
        except RainbowError as exc:
            raise SceneError(f"{p}: {_named(str(exc), ids)}") from None
        ids[names[name]] = name
    arcs = top.get("arcs", [])
    if not isinstance(arcs, list):
        raise SceneError("$.arcs: must be a list")
    for n, spec in enumerate(arcs):
        p = f"$.arcs[{n}]"
        spec = _obj(spec, p)
        _known_keys(spec, ARC_KEYS, p)
        ends = []
        for end in ("parent", "child"):
            if not isinstance(spec.get(end), str) or spec[end] not in names:
                raise SceneError(f"{p}.{end}: no node named {json.dumps(spec.get(end))}")
            ends.append(names[spec[end]])
        parent, child = spec["parent"], spec["child"]
        if r.node_kind(ends[0]) == "pad":
            raise SceneError(f"{p}.parent: {quote(parent)} is a pad, not a cluster")
        if ends[1] == SCREEN:
            raise SceneError(f"{p}.child: the screen cannot be mapped into anything")
        if r.graph.reaches(ends[1], ends[0]):
            raise SceneError(f"{p}: mapping {quote(child)} into {quote(parent)} would make a cycle")
        on = spec.get("on", True)
        if not isinstance(on, bool):
            raise SceneError(f"{p}.on: must be true or false")
        try:
            r.map(ends[0], ends[1], _int(spec, "x", p, 0), _int(spec, "y", p, 0),
                  _int(spec, "priority", p, 0), on)
        except RainbowError as exc:
            raise SceneError(f"{p}: {_named(str(exc), ids)}") from None


def _fill(r: Rainbow, pid: int, spec: dict, p: str, w: int, h: int, depth: int) -> None:
    if "pixels" in spec and "fill" in spec:
        raise SceneError(f"{p}: give either pixels or fill, not both")
    if depth == 0:
        if spec.get("pixels") or spec.get("fill", 0):
            raise SceneError(f"{p}: a virtual (depth 0) pad has no pixels")
        return
    if "pixels" in spec:
        if not isinstance(spec["pixels"], str):
            raise SceneError(f"{p}.pixels: must be a base64 string")
        try:
            # base64 tools wrap lines: whitespace is layout, anything else must be base64
            data = base64.b64decode("".join(spec["pixels"].split()), validate=True)
        except (binascii.Error, ValueError) as exc:
            raise SceneError(f"{p}.pixels: bad base64 ({exc})") from None
        if len(data) != w * h:
            raise SceneError(f"{p}.pixels: {len(data)} bytes, want width*height = {w * h}")
        a = np.frombuffer(data, np.uint8).reshape(h, w)
        if a.max(initial=0) >= 1 << depth:
            bad = int(np.flatnonzero(a.ravel() >= 1 << depth)[0])
            raise SceneError(f"{p}.pixels: byte {bad} = {a.ravel()[bad]} does not fit depth "
                             f"{depth}")
        r.canvas(pid).put(0, 0, a)
    else:
        r.canvas(pid).clear(_int(spec, "fill", p, 0, 0, (1 << depth) - 1))


def load_scene(path: str | Path, device: Rainbow | None = None) -> Rainbow:
    """Read a scene file; any bad byte, bad JSON, deep nesting or huge number raises
    SceneError naming the file (and line:column where there is one)."""
    scene = read_json(path, SceneError)
    return build_scene(scene, device, str(path))
