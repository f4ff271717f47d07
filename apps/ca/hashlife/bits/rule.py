"""Whether a rule set can take the binary path, and its transition table — found by running
the rules themselves (the generic leaf kernel) on every 3 x 3 neighbourhood of 0s and 1s,
never by recognising a rule by name.

The binary path needs: deterministic rules (no section 8.1 outcomes, no broadcast), an
order of messages that cannot matter, a message reach of at most 1, and values 0 and 1
mapped to 0 and 1 (other life-forms may exist in the rules; the plane must hold only 1s).
The 512 outcomes (index bit 3*(dy+1) + (dx+1) = the cell at dy, dx; the centre is bit 4)
become either birth and survival counts (outer-totalistic rules, for the bit-sliced adder)
or a 4 x 4 -> 2 x 2 lookup of 65536 entries.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from camlab88.apps.ca.hashlife.kernels import (
    KIND_LOOKUP,
    KIND_TOTALISTIC,
    LUT,
    TERM,
    TERM_ANY,
    TERM_BIRTH,
    TERM_SURVIVAL,
    generation,
)
from camlab88.apps.ca.hashlife.leaf import deterministic_reason, order_matters, pack
from camlab88.apps.ca.rules import RuleSet

CENTRE = 4


@dataclass(frozen=True)
class BinaryRule:
    """A rule set's two-state transition: the 512 table and the packed kernel table."""

    table: np.ndarray  # uint8[512]
    totalistic: bool
    packed: np.ndarray  # uint64: header (LUT entries) and, for lookup rules, 65536 more


def derive_table(rules: RuleSet) -> np.ndarray:
    """The next value of the centre of each 3 x 3 neighbourhood of 0s and 1s, by running
    one generation of the rules (leaf.generation) on it; values may be other than 0, 1."""
    packed = pack(rules)
    grid = np.zeros((4 * 5, 5), np.int64)  # four 5 x 5 planes, one above the other
    out = np.zeros(512, np.int64)
    for index in range(512):
        grid[1:4, 1:4] = (index >> np.arange(9).reshape(3, 3)) & 1
        generation(grid, 0, 1, 2, 3, packed)
        out[index] = grid[5 + 2, 2]
    return out


def reason_against(rules: RuleSet) -> str | None:
    """Why ``rules`` cannot take the binary path (None: they can)."""
    reason = deterministic_reason(rules)
    if reason is not None:
        return reason
    if order_matters(rules):
        return "the order of messages can matter"
    if max(rules.reach) > 1:
        return f"the message reach is {max(rules.reach)}, not 1"
    return None


def binary_rule(rules: RuleSet) -> BinaryRule | str:
    """The rules' binary transition, or why they have none (cached on the rule set)."""
    key = "hashlife_binary_rule"
    if key not in rules._tables:
        rules._tables[key] = _derive(rules)
    return rules._tables[key]


def _derive(rules: RuleSet) -> BinaryRule | str:
    reason = reason_against(rules)
    if reason is not None:
        return reason
    table = derive_table(rules)
    if table.max() > 1:
        return "life-forms 0 and 1 can become another life-form"
    table = table.astype(np.uint8)
    terms = totalistic_terms(table)
    if terms is not None:
        packed = np.zeros(LUT, np.uint64)
        packed[0], packed[1] = KIND_TOTALISTIC, len(terms)
        for i, (kind, total) in enumerate(terms):
            at = 2 + TERM * i
            packed[at] = kind
            packed[at + 1:at + TERM] = [0xFFFFFFFFFFFFFFFF if (total >> b) & 1 else 0
                                        for b in range(4)]
        return BinaryRule(table, True, packed)
    packed = np.zeros(LUT + 65536, np.uint64)
    packed[0] = KIND_LOOKUP
    packed[LUT:] = lookup_4x4(table)
    return BinaryRule(table, False, packed)


def totalistic_terms(table: np.ndarray) -> list[tuple[int, int]] | None:
    """The (kind, block sum) terms of an outer-totalistic table, None if the table depends
    on more than the centre and its neighbour count.  The block sum counts the 3 x 3 block,
    centre included (n neighbours: n if the centre is dead, n + 1 if live); a sum that
    gives life whatever the centre is one TERM_ANY, else TERM_BIRTH (dead centres only) or
    TERM_SURVIVAL (live ones only)."""
    index = np.arange(512)
    centre = (index >> CENTRE) & 1
    count = np.array([bin(i & ~(1 << CENTRE)).count("1") for i in index])
    outcome = np.zeros((2, 9), np.int64) - 1
    for c, n, v in zip(centre, count, table):
        if outcome[c, n] not in (-1, v):
            return None
        outcome[c, n] = v
    terms = []
    for total in range(10):
        born = total < 9 and outcome[0, total] == 1
        lives = total > 0 and outcome[1, total - 1] == 1
        if born and lives:
            terms.append((TERM_ANY, total))
        elif born or lives:
            terms.append((TERM_BIRTH if born else TERM_SURVIVAL, total))
    return terms


def lookup_4x4(table: np.ndarray) -> np.ndarray:
    """For each 4 x 4 block (bit 4*y + x), its centre 2 x 2 one generation on
    (bit 2*y + x of the entry, for the cell at 1 + y, 1 + x)."""
    block = np.arange(65536)
    out = np.zeros(65536, np.uint16)
    for oy in range(2):
        for ox in range(2):
            index = np.zeros(65536, np.int64)
            for dy in range(3):
                for dx in range(3):
                    bit = (block >> (4 * (oy + dy) + ox + dx)) & 1
                    index |= bit << (3 * dy + dx)
            out |= (table[index].astype(np.uint16) << (2 * oy + ox))
    return out
