"""HashLife as an engine strategy: advance an :class:`~apps.ca.engine.Engine` by any number
of generations in jumps, the engine's universe becoming one HashLife tree (tree.py).

The leaves are a strategy chosen per run: binary (bits/run.py: two-state rules on a plane
of 1s, 16 x 16-cell leaves of bits, jumps of any length) or generic (generic.py: leaves of
life-form values, any deterministic rules, jumps of powers of two).  A tree adopted by the
engine is kept between jumps, so a run of jumps converts cells to a tree once and back only
when cells are looked at.  The node table belongs to the rule set (results depend only on
the rules) and is shared by every engine running it; its garbage collection renumbers the
trees engines hold.
"""

from __future__ import annotations

from collections.abc import Callable

from camlab88.apps.ca.hashlife import tree as trees
from camlab88.apps.ca.hashlife.bits.run import BitRun
from camlab88.apps.ca.hashlife.generic import GenericRun
from camlab88.apps.ca.hashlife.leaf import deterministic_reason
from camlab88.apps.ca.rules import RuleSet

# Generations the direct engine takes at a time while order-dependent rules have live cells
# at the wrapping plane's seam (the generic strategy's next jump is 0 there).
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


class HashLife:
    """The strategy: deterministic rules, no advance area; both edge modes exactly."""

    name = "hashlife"

    def unsupported(self, engine) -> str | None:  # an Engine
        """Why this engine's state cannot be advanced by HashLife (None: it can)."""
        return reason_against(engine.rules, engine.advance_area)

    def advance(self, engine, generations: int, progress: Progress | None = None) -> None:
        reason = self.unsupported(engine)
        if reason is not None:
            raise ValueError(f"HashLife cannot step this plane: {reason}")
        run = self.binary(engine) or GenericRun.of(engine.rules, engine.hashlife_memory)
        done, total = 0, int(generations)
        while done < total:
            node = trees.plane(run, engine)
            n = run.next_jump(node, total - done, engine.edges)
            if n == 0:  # live cells at the seam, where the order of messages is absolute
                n = min(SEAM_DIRECT_BATCH, total - done)
                engine.step_direct(n)
            else:
                node = trees.jump(run, node, n, engine.edges)
                engine.generation += n
                engine.adopt(trees.adopt(run, node))
            done += n
            if progress is not None:
                progress(done, total)

    @staticmethod
    def binary(engine) -> BitRun | None:
        """The binary leaf strategy for this engine's rules and plane (None: generic)."""
        bits = BitRun.of(engine.rules, engine.hashlife_memory)
        tree = engine.tree
        if bits is None or (tree is not None and isinstance(tree.run, BitRun)):
            return bits
        if tree is not None:  # a generic tree: its census says which forms it holds
            return bits if set(engine.by_type()) <= {1} else None
        window = engine.dense_window
        ts = window[2] if window is not None else engine.ts
        return bits if ts.size == 0 or int(ts.max()) <= 1 else None
