"""Edit mode (section 7.3.1): the right button edits the cell under the cursor in the
chosen method; held down while the mouse moves, it sets every cell passed over to the most
recently selected value (cells between two mouse reports are joined, so a quick drag leaves
no holes)."""

from __future__ import annotations

from camlab88.apps.ca.session import Session


def cells_between(a: tuple[int, int], b: tuple[int, int]) -> list[tuple[int, int]]:
    """Cells on the line from a (exclusive) to b (inclusive), Bresenham in cell space."""
    (x0, y0), (x1, y1) = a, b
    if max(abs(x1 - x0), abs(y1 - y0)) > 4096:  # across the plane's seam: no line
        return [b]
    dx, dy = abs(x1 - x0), -abs(y1 - y0)
    sx, sy = (1 if x1 > x0 else -1), (1 if y1 > y0 else -1)
    err, out = dx + dy, []
    while (x0, y0) != (x1, y1):
        e2 = 2 * err
        if e2 >= dy:
            err += dy
            x0 += sx
        if e2 <= dx:
            err += dx
            y0 += sy
        out.append((x0, y0))
    return out


class Editor:
    def __init__(self, session: Session) -> None:
        self.session = session
        self.value: int | None = None  # value being painted while the right button is held
        self.last: tuple[int, int] | None = None

    def press(self, cell: tuple[int, int]) -> list[tuple[int, int]]:
        """Right button pressed over ``cell``: returns the cells whose value changed."""
        before = self.session.engine.get(*cell)
        self.value = self.session.click(*cell)
        self.last = cell
        return [cell] if self.session.engine.get(*cell) != before else []

    def drag(self, cell: tuple[int, int]) -> list[tuple[int, int]]:
        if self.value is None or self.last is None or cell == self.last:
            return []
        changed = []
        for c in cells_between(self.last, cell):
            if self.session.engine.get(*c) != self.value:
                self.session.paint(c[0], c[1], self.value)
                changed.append(c)
        self.last = cell
        return changed

    def release(self) -> None:
        self.value = None
        self.last = None
