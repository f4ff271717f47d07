"""The Rainbow device's state as JSON values + arrays: the pad graph (pads with their video
memory allocations, clusters with their arcs in map order, ids handed out), the video
memory words and allocation map, both LUTs, the clock, and the input controller's queue.

The band structure is not saved: it is recompiled from the graph (a compile from scratch
equals the incremental one, emulator/rainbow/compiler.py).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from emulator.rainbow.device import Rainbow
from emulator.rainbow.graph import SCREEN, Arc, Cluster, Pad
from emulator.rainbow.memory import Allocation
from protocols.rainbow.events import decode_events, encode_event

ARRAYS = ("words", "used", "lut", "lut_pending")


def save(dev: Rainbow) -> tuple[dict[str, Any], dict[str, bytes]]:
    g, m, i = dev.graph, dev.memory, dev.inputs
    nodes = []
    for n in g.nodes.values():
        if isinstance(n, Pad):
            a = n.alloc
            alloc = None if a is None else [a.x, a.y, a.width, a.height, a.plane_mask]
            nodes.append(["pad", n.id, n.width, n.height, n.depth, n.plane, n.lut_page, alloc])
        else:
            nodes.append(["cluster", n.id, n.width, n.height, list(n.arcs)])
    head = {
        "memory": [m.width, m.height],
        "nodes": nodes,
        "arcs": [[a.id, a.parent, a.child, a.x, a.y, a.priority, a.on] for a in g.arcs.values()],
        "graph_ids": [g.version, g._next_node, g._next_arc],
        "clock": [dev.frame_count, dev.time_ms],
        "inputs": {"queue": [encode_event(e).hex() for e in i.queue],
                   "pointer": [i.mouse_x, i.mouse_y, i.buttons], "dropped": i.dropped},
    }
    arrays = {"words": m.words, "used": m._used, "lut": dev.lut, "lut_pending": dev.lut_pending}
    return head, {k: np.ascontiguousarray(v).tobytes() for k, v in arrays.items()}


def load(head: dict[str, Any], blobs: dict[str, bytes], strict: bool) -> Rainbow:
    """A new device from save()'s parts (ValueError/KeyError/TypeError on damage)."""
    dev = Rainbow(strict=strict)
    m = dev.memory
    if head["memory"] != [m.width, m.height]:
        raise ValueError(f"state has {head['memory']} video memory, this device "
                         f"{[m.width, m.height]}")
    for name, arr in (("words", m.words), ("used", m._used), ("lut", dev.lut),
                      ("lut_pending", dev.lut_pending)):
        raw = blobs[name]
        if len(raw) != arr.nbytes:
            raise ValueError(f"state array {name!r} is {len(raw)} bytes, expected {arr.nbytes}")
        arr[...] = np.frombuffer(raw, dtype=arr.dtype).reshape(arr.shape)
    g = dev.graph
    g.nodes = {}
    for entry in head["nodes"]:
        kind, nid, w, h = entry[:4]
        if kind == "pad":
            depth, plane, page, alloc = entry[4:]
            a = None if alloc is None else Allocation(*(int(v) for v in alloc))
            g.nodes[int(nid)] = Pad(int(nid), int(w), int(h), int(depth), int(plane),
                                    int(page), a)
        elif kind == "cluster":
            g.nodes[int(nid)] = Cluster(int(nid), int(w), int(h), [int(v) for v in entry[4]])
        else:
            raise ValueError(f"state node kind {kind!r} is not pad or cluster")
    if SCREEN not in g.nodes:
        raise ValueError("state graph has no screen node")
    g.arcs = {int(a[0]): Arc(int(a[0]), int(a[1]), int(a[2]), int(a[3]), int(a[4]),
                             int(a[5]), bool(a[6])) for a in head["arcs"]}
    g.version, g._next_node, g._next_arc = (int(v) for v in head["graph_ids"])
    dev.frame_count, dev.time_ms = (int(v) for v in head["clock"])
    inputs = head["inputs"]
    dev.inputs.queue.extend(decode_events(bytes.fromhex("".join(inputs["queue"])), "state"))
    dev.inputs.mouse_x, dev.inputs.mouse_y, dev.inputs.buttons = (
        int(v) for v in inputs["pointer"])
    dev.inputs.dropped = int(inputs["dropped"])
    return dev
