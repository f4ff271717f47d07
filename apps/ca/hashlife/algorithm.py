"""HashLife as an engine strategy: advance an :class:`~apps.ca.engine.Engine` by any number
of generations in jumps of powers of two (the binary digits of the count, largest first).

The tree of the plane is kept on the engine between jumps (``engine.tree``), so a run of
jumps converts cells to a tree once and back only when cells are looked at.  The node
table belongs to the rule set (results depend only on the rules) and is shared by every
engine running it; its garbage collection renumbers nodes, which voids the trees of other
engines (they rebuild theirs from their cells).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from apps.ca.hashlife import census, convert, evolve
from apps.ca.hashlife.bits.run import MAX_JUMP, BitRun, BitTree
from apps.ca.hashlife.leaf import deterministic_reason, order_matters, pack
from apps.ca.hashlife.plane import frame
from apps.ca.hashlife.store import TOP_LEVEL, NodeStore
from apps.ca.rules import RuleSet

# Leaves are this many levels above the smallest possible (2**(s+2) cells square, one
# generation): bigger leaves run more generations directly per memoised result.
LEAF_EXTRA = 0
# Generations the direct engine takes at a time while order-dependent rules have live cells
# at the wrapping plane's seam.
SEAM_DIRECT_BATCH = 16

Progress = Callable[[int, int], None]  # (generations done, generations asked)


def reason_against(rules: RuleSet | None, advance_area: object = None) -> str | None:
    """Why HashLife cannot run these rules on this plane (None: it can)."""
    if rules is None:
        return "no rules loaded"
    if advance_area is not None and (advance_area.width, advance_area.height) != (65536,
                                                                                   65536):
        return "an advance area is set (HashLife steps the whole plane)"
    return deterministic_reason(rules)


@dataclass(eq=False)  # hashed by identity: the store keeps its live trees in a WeakSet
class Tree:
    """A plane's state as a node of a rule set's table (valid while the epoch matches;
    collections renumber every live tree, NodeStore.make_room)."""

    store: NodeStore
    epoch: int
    node: int
    _census: dict = field(default_factory=dict, repr=False, compare=False)

    def valid(self, store: NodeStore) -> bool:
        return self.store is store and self.epoch == store.epoch

    def by_type(self, forms: int) -> dict[int, int]:
        """{life-form: cells} for life-forms 1..forms, without listing the cells."""
        key = ("by_type", forms)
        if key not in self._census:
            self._census[key] = census.counts(self.node, forms, self.store.nodes,
                                              self.store.count)
        return dict(self._census[key])

    def occupied(self, axis: int) -> np.ndarray:
        """Sorted rows (axis 0) or columns (axis 1) that hold a live cell."""
        key = ("occupied", axis)
        if key not in self._census:
            self._census[key] = census.occupied(self.node, axis, self.store.nodes,
                                                self.store.empty, self.store.count)
        return self._census[key]

    def cells(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(ys, xs, types) of the live cells, row by row."""
        rows = convert.cells(np.int64(self.node), self.store.nodes, self.store.empty)
        return rows[:, 0].copy(), rows[:, 1].copy(), rows[:, 2].copy()


@dataclass
class _Run:
    """What one rule set's jumps need: its node table and packed rules."""

    store: NodeStore
    packed: np.ndarray
    params: np.ndarray  # int64 (leaf level, s, reach)
    grids: np.ndarray  # the leaf's scratch grids: cells, next cells, node ids, messages
    order_matters: bool

    @classmethod
    def of(cls, rules: RuleSet, memory: int) -> _Run:
        run = rules._tables.get("hashlife_run")
        if run is None:
            ry, rx = rules.reach
            reach = max(ry, rx, 1)
            shift = (reach - 1).bit_length()  # 2**shift >= the reach
            leaf = shift + 2 + LEAF_EXTRA
            run = cls(NodeStore(limit_bytes=memory), pack(rules),
                      np.array([leaf, shift, reach], np.int64),
                      np.zeros((4, 1 << leaf, 1 << leaf), np.int64), order_matters(rules))
            rules._tables["hashlife_run"] = run
        run.store.limit_bytes = int(memory)
        return run

    @property
    def max_j(self) -> int:
        return TOP_LEVEL - 2 - int(self.params[1])


class HashLife:
    """The strategy: deterministic rules, no advance area; both edge modes exactly.  Two-state
    rules on a plane of 1s take the binary path (apps/ca/hashlife/bits), the rest the
    generic one."""

    name = "hashlife"

    def unsupported(self, engine) -> str | None:  # an Engine
        """Why this engine's state cannot be advanced by HashLife (None: it can)."""
        return reason_against(engine.rules, engine.advance_area)

    def advance(self, engine, generations: int, progress: Progress | None = None) -> None:
        reason = self.unsupported(engine)
        if reason is not None:
            raise ValueError(f"HashLife cannot step this plane: {reason}")
        bits = self.binary(engine)
        if bits is not None:
            self._advance_bits(engine, bits, int(generations), progress)
            return
        run = _Run.of(engine.rules, engine.hashlife_memory)
        seam = engine.edges == "wrap" and run.order_matters
        done, total = 0, int(generations)
        while done < total:
            node = self._plane(engine, run)
            j = min(run.max_j, (total - done).bit_length() - 1)
            if seam:
                j = self._seam_safe(run, node, j)
            if j < 0:  # live cells at the seam, where the order of messages is absolute
                n = min(SEAM_DIRECT_BATCH, total - done)
                engine.step_direct(n)
                done += n
            else:
                node = self._jump(run, node, j, engine.edges)
                done += 1 << j
                engine.generation += 1 << j
                tree = Tree(run.store, run.store.epoch, node)
                run.store.trees.add(tree)  # renumbered if a later collection moves it
                engine.adopt_tree(tree)
            if progress is not None:
                progress(done, total)

    @staticmethod
    def binary(engine) -> BitRun | None:
        """The binary path for this engine's rules and plane (None: the generic path)."""
        bits = BitRun.of(engine.rules, engine.hashlife_memory)
        if bits is None or isinstance(engine.tree, BitTree):
            return bits
        if engine.tree is not None:  # a generic tree: its census says which forms it holds
            return bits if set(engine.by_type()) <= {1} else None
        window = engine.dense_window
        ts = window[2] if window is not None else engine.ts
        return bits if ts.size == 0 or int(ts.max()) <= 1 else None

    @staticmethod
    def _advance_bits(engine, bits: BitRun, total: int,
                      progress: Progress | None) -> None:
        """Jumps of up to MAX_JUMP generations, each any length (one pass of the tree)."""
        done = 0
        while done < total:
            n = min(MAX_JUMP, total - done)
            node = bits.jump(bits.plane(engine), n, engine.edges)
            done += n
            engine.generation += n
            engine.adopt_tree(bits.tree(node))
            if progress is not None:
                progress(done, total)

    def _seam_safe(self, run: _Run, node: int, j: int) -> int:
        """The longest jump, at most 2**j, in which no message can reach a cell within
        the reach of the seam (-1: none can)."""
        r = int(run.params[2])
        while j >= 0 and convert.near_seam(node, r * ((1 << j) + 1), run.store.nodes,
                                           run.store.empty):
            j -= 1
        return j

    def _plane(self, engine, run: _Run) -> int:
        tree = engine.tree
        if tree is not None and tree.valid(run.store):
            return tree.node
        ys, xs, ts = engine.ys, engine.xs, engine.ts
        keys = convert.morton(xs, ys)
        order = np.argsort(keys)
        s = run.store
        for _ in range(3):
            node = int(convert.build(keys[order], ts[order], s.nodes, s.slots, s.meta,
                                     s.empty))
            if node >= 0:
                return node
            if not s.grow_if_full():
                s.make_room([])
        raise MemoryError("the plane does not fit the HashLife memory limit "
                          f"({s.limit_bytes >> 20} MB)")

    def _jump(self, run: _Run, node: int, j: int, edges: str) -> int:
        """The plane ``node`` after 2**j generations; on a full table grow it (within the
        memory limit) or collect garbage and retry, and as a last resort take two jumps of
        half the length."""
        s = run.store
        collected = False
        while True:
            try:
                out = evolve.advance(frame(s, node, edges), j, run.params, s, run.packed,
                                     run.grids)
            except MemoryError:  # framing the plane found the table full
                out = -1
            if out >= 0:
                return out
            if s.grow_if_full():
                continue
            if collected:
                break
            collected = True
            try:
                (node,) = s.make_room([node])
            except MemoryError:
                if j == 0:
                    raise
                break
        if j == 0:
            raise MemoryError(f"one generation does not fit the HashLife memory limit "
                              f"({s.limit_bytes >> 20} MB)")
        return self._jump(run, self._jump(run, node, j - 1, edges), j - 1, edges)
