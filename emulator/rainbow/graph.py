"""The pad graph: pads (leaves), clusters (internal nodes) and the arcs that map them.

The root, node 0, is the screen: a 768 x 576 cluster. A node may be mapped any number of
times; a map that would close a cycle is refused. Every edit bumps ``version`` so the
compiler knows to recompile before the next frame.
"""

from __future__ import annotations

import operator
from dataclasses import dataclass, field
from typing import TypeVar

from camlab88.emulator.rainbow.errors import GraphError, RainbowError
from camlab88.emulator.rainbow.memory import Allocation

SCREEN = 0
SCREEN_W, SCREEN_H = 768, 576
MAX_COORD = 1 << 20  # positions and sizes beyond this are certainly a program error
MAX_INSTANCES = 200_000  # mapping nodes many times multiplies paths; bound the work
MAX_VISITS = 1_000_000  # paths through clusters, counted even when they reach no pad
T = TypeVar("T")


@dataclass
class Pad:
    id: int
    width: int
    height: int
    depth: int
    plane: int
    lut_page: int
    alloc: Allocation | None  # None for a virtual (depth 0) pad


@dataclass
class Cluster:
    id: int
    width: int
    height: int
    arcs: list[int] = field(default_factory=list)  # arcs out of this cluster, in map order


@dataclass
class Arc:
    id: int
    parent: int
    child: int
    x: int
    y: int
    priority: int
    on: bool


@dataclass(frozen=True)
class Instance:
    """One path screen -> ... -> pad through arcs that are on, with its clipped rectangle."""

    path: tuple[int, ...]  # arc ids
    key: tuple[int, ...]  # arc priorities from the screen down
    pad: int
    x0: int
    y0: int
    x1: int
    y1: int
    ox: int  # screen position of the pad's (0, 0)
    oy: int


def _as_int(name: str, v: object) -> int:
    if isinstance(v, bool):
        raise RainbowError(f"{name} {v!r} is not an integer")
    try:
        return operator.index(v)  # ints and numpy integers
    except TypeError:
        raise RainbowError(f"{name} {v!r} is not an integer") from None


def _check_coord(name: str, v: int) -> int:
    v = _as_int(name, v)
    if not -MAX_COORD <= v <= MAX_COORD:
        raise RainbowError(f"{name} {v!r} out of range (|value| <= {MAX_COORD})")
    return v


def _check_size(name: str, v: int) -> int:
    v = _as_int(name, v)
    if not 1 <= v <= MAX_COORD:
        raise RainbowError(f"{name} {v!r} must be an integer 1..{MAX_COORD}")
    return v


def _find(table: dict[int, T], key: int, what: str) -> T:
    """``table[key]``, or a GraphError naming the ``what`` that is not there (a key that
    cannot be one, a list say, is not there either)."""
    try:
        return table[key]
    except (KeyError, TypeError):
        raise GraphError(f"no {what} {key!r}") from None


def _new_id(chosen: int | None, next_free: int, table: dict[int, object], what: str,
            note: str = "") -> int:
    """The id of a new node or arc (``what``): the next free one, or the one the program
    chose, which must be a 31-bit id not in ``table``."""
    if chosen is None:
        return next_free
    if not isinstance(chosen, int) or chosen <= 0 or chosen >= 1 << 31:
        raise GraphError(f"{what} id {chosen!r} must be 1..2^31-1{note}")
    if chosen in table:
        raise GraphError(f"{what} {chosen} already exists")
    return chosen


class PadGraph:
    def __init__(self) -> None:
        self.nodes: dict[int, Pad | Cluster] = {SCREEN: Cluster(SCREEN, SCREEN_W, SCREEN_H)}
        self.arcs: dict[int, Arc] = {}
        self.version = 0
        self._next_node = 1
        self._next_arc = 1

    # -- state -----------------------------------------------------------------------------
    def save_state(self) -> dict:
        """Nodes (pads with their allocations, clusters with their arcs in map order), arcs
        and the ids handed out, as JSON values."""
        nodes = []
        for n in self.nodes.values():
            if isinstance(n, Pad):
                a = n.alloc
                alloc = None if a is None else [a.x, a.y, a.width, a.height, a.plane_mask]
                nodes.append(["pad", n.id, n.width, n.height, n.depth, n.plane, n.lut_page,
                              alloc])
            else:
                nodes.append(["cluster", n.id, n.width, n.height, list(n.arcs)])
        arcs = [[a.id, a.parent, a.child, a.x, a.y, a.priority, a.on] for a in self.arcs.values()]
        return {"nodes": nodes, "arcs": arcs,
                "ids": [self.version, self._next_node, self._next_arc]}

    def load_state(self, state: dict) -> None:
        """Put back save_state()'s values (ValueError/KeyError/TypeError if damaged; checked
        before anything changes)."""
        nodes: dict[int, Pad | Cluster] = {}
        for entry in state["nodes"]:
            kind, nid, w, h = entry[0], int(entry[1]), int(entry[2]), int(entry[3])
            if kind == "pad":
                depth, plane, page, alloc = entry[4:]
                a = None if alloc is None else Allocation(*(int(v) for v in alloc))
                nodes[nid] = Pad(nid, w, h, int(depth), int(plane), int(page), a)
            elif kind == "cluster":
                nodes[nid] = Cluster(nid, w, h, [int(v) for v in entry[4]])
            else:
                raise ValueError(f"graph state node kind {kind!r} is not pad or cluster")
        if SCREEN not in nodes:
            raise ValueError("graph state has no screen node")
        arcs = {int(a[0]): Arc(int(a[0]), int(a[1]), int(a[2]), int(a[3]), int(a[4]),
                               int(a[5]), bool(a[6])) for a in state["arcs"]}
        version, next_node, next_arc = (int(v) for v in state["ids"])
        self.nodes, self.arcs = nodes, arcs
        self.version, self._next_node, self._next_arc = version, next_node, next_arc

    # -- nodes -----------------------------------------------------------------------------
    def _new_node_id(self, node: int | None) -> int:
        # Ids are never reused (a stale id held by a program must not name a new node):
        # automatic ids count up past every id handed out or chosen explicitly.
        return _new_id(node, self._next_node, self.nodes, "node", " (0 is the screen)")

    def _taken_node(self, nid: int) -> None:
        self._next_node = max(self._next_node, nid + 1)

    def add_pad(
        self, width: int, height: int, depth: int, plane: int, lut_page: int,
        alloc: Allocation | None, node: int | None = None,
    ) -> Pad:
        nid = self._new_node_id(node)
        pad = Pad(nid, width, height, depth, plane, lut_page, alloc)
        self.nodes[nid] = pad
        self._taken_node(nid)
        self.version += 1
        return pad

    def add_cluster(self, width: int, height: int, node: int | None = None) -> Cluster:
        nid = self._new_node_id(node)
        _check_size("cluster width", width)
        _check_size("cluster height", height)
        c = Cluster(nid, width, height)
        self.nodes[nid] = c
        self._taken_node(nid)
        self.version += 1
        return c

    def node(self, nid: int) -> Pad | Cluster:
        return _find(self.nodes, nid, "node")

    def pad(self, nid: int) -> Pad:
        return self._node_of_kind(nid, Pad, "a cluster, not a pad")

    def cluster(self, nid: int) -> Cluster:
        return self._node_of_kind(nid, Cluster, "a pad, not a cluster")

    def _node_of_kind(self, nid: int, kind: type[T], otherwise: str) -> T:
        n = self.node(nid)
        if not isinstance(n, kind):
            raise GraphError(f"node {nid} is {otherwise}")
        return n

    def remove_node(self, nid: int) -> Pad | Cluster:
        if nid == SCREEN:
            raise GraphError("the screen cannot be destroyed")
        n = self.node(nid)
        for a in [a for a in self.arcs.values() if a.parent == nid or a.child == nid]:
            self.remove_arc(a.id)
        del self.nodes[nid]
        self.version += 1
        return n

    def resize(self, nid: int, width: int, height: int) -> None:
        if nid == SCREEN:
            raise GraphError("the screen's size is fixed at 768x576")
        c = self.cluster(nid)
        c.width = _check_size("cluster width", width)
        c.height = _check_size("cluster height", height)
        self.version += 1

    # -- arcs ------------------------------------------------------------------------------
    def reaches(self, start: int, target: int) -> bool:
        """Is ``target`` ``start`` or below it (so mapping start into target is a cycle)?"""
        self.node(start)
        self.node(target)
        return self._reaches(start, target)

    def _reaches(self, start: int, target: int) -> bool:
        stack, seen = [start], set()
        while stack:
            n = stack.pop()
            if n == target:
                return True
            if n in seen:
                continue
            seen.add(n)
            node = self.nodes[n]
            if isinstance(node, Cluster):
                stack.extend(self.arcs[a].child for a in node.arcs)
        return False

    def add_arc(
        self, parent: int, child: int, x: int, y: int, priority: int, on: bool,
        arc: int | None = None,
    ) -> Arc:
        p = self.cluster(parent)
        self.node(child)
        if child == SCREEN:
            raise GraphError("the screen cannot be mapped into anything")
        if self._reaches(child, parent):
            raise GraphError(f"mapping node {child} into {parent} would make a cycle")
        arc = _new_id(arc, self._next_arc, self.arcs, "arc")
        a = Arc(arc, parent, child, _check_coord("x", x), _check_coord("y", y),
                _check_coord("priority", priority), bool(on))
        self.arcs[arc] = a
        self._next_arc = max(self._next_arc, arc + 1)
        p.arcs.append(arc)
        self.version += 1
        return a

    def arc(self, aid: int) -> Arc:
        return _find(self.arcs, aid, "arc")

    def remove_arc(self, aid: int) -> None:
        a = self.arc(aid)
        self.cluster(a.parent).arcs.remove(aid)
        del self.arcs[aid]
        self.version += 1

    def move(self, aid: int, x: int, y: int) -> None:
        a = self.arc(aid)
        a.x, a.y = _check_coord("x", x), _check_coord("y", y)
        self.version += 1

    def set_priority(self, aid: int, priority: int) -> None:
        self.arc(aid).priority = _check_coord("priority", priority)
        self.version += 1

    def set_on(self, aid: int, on: bool) -> None:
        self.arc(aid).on = bool(on)
        self.version += 1

    # -- instances -------------------------------------------------------------------------
    def instances(self) -> list[Instance]:
        """Every path to a pad through arcs that are on, clipped by each cluster on the way."""
        out: list[Instance] = []
        # (node, origin x, origin y, clip rect, path, key)
        stack = [(SCREEN, 0, 0, (0, 0, SCREEN_W, SCREEN_H), (), ())]
        visits = 0
        while stack:
            nid, ox, oy, clip, path, key = stack.pop()
            visits += 1
            if visits > MAX_VISITS:
                raise GraphError(f"the graph has more than {MAX_VISITS} paths from the screen")
            node = self.nodes[nid]
            if isinstance(node, Pad):
                x0 = max(clip[0], ox)
                y0 = max(clip[1], oy)
                x1 = min(clip[2], ox + node.width)
                y1 = min(clip[3], oy + node.height)
                if x0 < x1 and y0 < y1:
                    out.append(Instance(path, key, nid, x0, y0, x1, y1, ox, oy))
                    if len(out) > MAX_INSTANCES:
                        raise GraphError(
                            f"the graph maps pads more than {MAX_INSTANCES} times"
                        )
                continue
            if nid != SCREEN:
                clip = (max(clip[0], ox), max(clip[1], oy),
                        min(clip[2], ox + node.width), min(clip[3], oy + node.height))
            if clip[0] >= clip[2] or clip[1] >= clip[3]:
                continue
            for aid in node.arcs:
                a = self.arcs[aid]
                if a.on:
                    stack.append((a.child, ox + a.x, oy + a.y, clip, path + (aid,),
                                  key + (a.priority,)))
        return out
