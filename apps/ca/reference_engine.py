"""The thesis's own engine (§7.5, figures 7.10-7.12): the oracle the fast engine must match.

Written as the thesis describes it, for clarity rather than speed:

* a generation (figure 7.10) is a linked list of the rows that hold living cells, each row
  record pointing to a vector of (x, life-form) entries in x order;
* the next generation is built in a second such structure; when it is complete the
  *current* and *next* pointers are swapped and the old structure's row records are re-used
  (kept on a free list) for the one after;
* messages go into lines of workspace (figure 7.11), each a doubly linked list of entries
  (previous, x, message area, next), one line per row from ``reach_up`` rows above the row
  being processed to ``reach_down`` rows below it — for Life exactly *Above*, *Current* and
  *Below*.  Processing a row sends every living cell's messages into those lines (a cursor
  walks each list left to right, stepping back over the few entries a sender's grid reaches
  behind it); then the topmost line can receive nothing more, so its entries are
  interpreted into the next generation's row, and the lines cycle: the old topmost becomes
  the (empty) bottom line (figure 7.12).

The message areas, their combination in sender order and the interpretation are those of
``camlab88.apps.ca.rules``; broadcasts (§8.1) are applied to every cell that received a local
message, in sender order.  Not modelled (the fast engine has them): random outcomes, the
advance area, and rows wrapping round the plane (columns wrap; live cells must stay
``reach`` rows from the top and bottom edges of a wrapping plane).
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator

from camlab88.apps.ca.rules import OP_ADD, OP_AND, OP_OR, RuleSet

SIDE = 65536
MASK32 = 0xFFFFFFFF
PREV, X, MSG, NEXT = range(4)  # the fields of a workspace entry (figure 7.11)


def apply(cur: int, op: int, value: int) -> int:
    """One message combined into a message area (32 bits)."""
    if op == OP_ADD:
        return (cur + value) & MASK32
    if op == OP_OR:
        return cur | value
    if op == OP_AND:
        return cur & value
    return cur ^ value


class Row:
    """A row record of figure 7.10: its y, the vector of (x, life-form), the next row."""

    __slots__ = ("y", "cells", "next")

    def __init__(self) -> None:
        self.y = 0
        self.cells: list[tuple[int, int]] = []
        self.next: Row | None = None


class Generation:
    """The linked list of rows holding living cells (figure 7.10)."""

    def __init__(self, pool: list[Row]) -> None:
        self.head: Row | None = None
        self.tail: Row | None = None
        self._pool = pool

    def append(self, y: int, cells: list[tuple[int, int]]) -> None:
        row = self._pool.pop() if self._pool else Row()
        row.y, row.cells, row.next = y, cells, None
        if self.tail is None:
            self.head = row
        else:
            self.tail.next = row
        self.tail = row

    def rows(self) -> Iterator[Row]:
        row = self.head
        while row is not None:
            yield row
            row = row.next

    def clear(self) -> None:
        """Give the row records back for re-use (the thesis's own storage management)."""
        self._pool.extend(self.rows())
        self.head = self.tail = None


class Line:
    """A line of workspace: a doubly linked list of [prev, x, message, next] entries."""

    __slots__ = ("head", "cursor")

    def __init__(self) -> None:
        self.head: list | None = None
        self.cursor: list | None = None

    def send(self, x: int, op: int, value: int) -> None:
        node = self.cursor or self.head
        if node is None:
            self.head = self.cursor = [None, x, apply(0, op, value), None]
            return
        while node[X] > x and node[PREV] is not None:
            node = node[PREV]
        while node[NEXT] is not None and node[NEXT][X] <= x:
            node = node[NEXT]
        if node[X] == x:
            node[MSG] = apply(node[MSG], op, value)
        elif node[X] < x:  # a new entry after this one
            new = [node, x, apply(0, op, value), node[NEXT]]
            if node[NEXT] is not None:
                node[NEXT][PREV] = new
            node[NEXT] = node = new
        else:  # before the head
            node = [None, x, apply(0, op, value), node]
            node[NEXT][PREV] = node
            self.head = node
        self.cursor = node

    def entries(self) -> Iterator[tuple[int, int]]:
        node = self.head
        while node is not None:
            yield node[X], node[MSG]
            node = node[NEXT]


class ReferenceEngine:
    """Plane of 65536 x 65536 cells stepped by the algorithm of §7.5."""

    def __init__(self, rules: RuleSet, edges: str = "wrap") -> None:
        if edges not in ("wrap", "bounded"):
            raise ValueError(f"edges must be wrap or bounded, not {edges!r}")
        self.rules = rules
        self.edges = edges
        self.generation = 0
        self._pool: list[Row] = []
        self.current = Generation(self._pool)
        self.next = Generation(self._pool)
        self._sends = {n: [(m.dy, m.dx, m.op, m.value) for m in f.messages]
                       for n, f in rules.forms.items()}
        self._bcast = {n: f.broadcast for n, f in rules.forms.items() if f.broadcast}
        ups = [-m.dy for f in rules.forms.values() for m in f.messages if m.dy < 0]
        downs = [m.dy for f in rules.forms.values() for m in f.messages if m.dy > 0]
        self.reach_up, self.reach_down = max(ups, default=0), max(downs, default=0)
        self._meaning: dict[int, int] = {}

    # -- cells in and out ---------------------------------------------------------------
    def set_cells(self, xs: Iterable[int], ys: Iterable[int], ts: Iterable[int]) -> None:
        """Replace the plane's contents with these cells (life-form 0 = none)."""
        by_row: dict[int, dict[int, int]] = {}
        for x, y, t in zip(xs, ys, ts, strict=True):
            if int(t):
                by_row.setdefault(int(y), {})[int(x)] = int(t)
        self.current.clear()
        for y in sorted(by_row):
            self.current.append(y, sorted(by_row[y].items()))

    def cells(self) -> list[tuple[int, int, int]]:
        """(y, x, life-form) of every living cell, row by row, left to right."""
        return [(row.y, x, t) for row in self.current.rows() for x, t in row.cells]

    # -- one generation -----------------------------------------------------------------
    def step(self, generations: int = 1) -> None:
        for _ in range(int(generations)):
            self._step_once()

    def _step_once(self) -> None:
        self._check_rows()
        bcast = [self._bcast[t] for row in self.current.rows() for _, t in row.cells
                 if t in self._bcast]
        depth = self.reach_up + 1 + self.reach_down
        lines = [Line() for _ in range(depth)]   # lines[i] is row (n - reach_up + i)
        top = None                               # the row lines[0] stands for
        for row in self.current.rows():
            if top is None:
                top = row.y - self.reach_up
            while top < row.y - self.reach_up:   # rows above can receive nothing more
                top = self._retire(lines, top, bcast)
                if all(line.head is None for line in lines):
                    top = row.y - self.reach_up  # nothing pending: jump to this row
            self._send_row(row, lines)
        while top is not None and any(line.head is not None for line in lines):
            top = self._retire(lines, top, bcast)
        self.current.clear()
        self.current, self.next = self.next, self.current  # the pointer swap of §7.5
        self.generation += 1

    def _send_row(self, row: Row, lines: list[Line]) -> None:
        """Every living cell of the row sends its messages into the workspace lines."""
        for line in lines:
            line.cursor = line.head
        base = self.reach_up
        wrap = self.edges == "wrap"
        for x, t in row.cells:
            for dy, dx, op, value in self._sends.get(t, ()):
                tx = x + dx
                if wrap:
                    tx %= SIDE
                elif not 0 <= tx < SIDE or not 0 <= row.y + dy < SIDE:
                    continue
                lines[base + dy].send(tx, op, value)

    def _retire(self, lines: list[Line], top: int, bcast: list[tuple[int, int]]) -> int:
        """Interpret the topmost line into the next generation; cycle the lines."""
        line = lines.pop(0)
        born = []
        for x, msg in line.entries():
            for op, value in bcast:
                msg = apply(msg, op, value)
            t = self._interpret(msg)
            if t:
                born.append((x, t))
        if born:
            self.next.append(top, born)
        lines.append(Line())
        return top + 1

    def _interpret(self, msg: int) -> int:
        t = self._meaning.get(msg)
        if t is None:
            outcome = self.rules.interpret(msg)
            if outcome is None:
                t = 0
            elif len(outcome.choices) == 1:
                t = outcome.choices[0][1]
            else:
                raise NotImplementedError("the reference engine has no random outcomes")
            self._meaning[msg] = t
        return t

    def _check_rows(self) -> None:
        if self.edges != "wrap" or self.current.head is None:
            return
        first, last = self.current.head.y, self.current.tail.y
        if first < self.reach_up or last >= SIDE - self.reach_down:
            raise ValueError("the reference engine does not wrap rows: keep living cells "
                             f"{self.reach_up} row(s) from the top and {self.reach_down} "
                             "from the bottom of the plane")
