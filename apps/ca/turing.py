"""Generator of the three-tape prime-testing Turing machine of section 7.4.2 as CA rules.

The thesis describes the machine but does not print its rules, so this is a reconstruction
in the thesis's own rule language.  Layout (as in figure 7.9): the number N in binary on the
top row between two end markers, the trial divisor on the second row, the working remainder
on the third, and the read/write head three rows below the left end marker.

How it works as a cellular automaton (the thesis's footnote: the head does not move, it
passes a message to the adjacent cell): tape cells send "I am a 1" downwards with a
different bit for each distance, so the cell below the three tapes learns all three symbols;
the head sends write messages up to the second and third rows and sends its next state,
coded in bits 8 and up, to the cell beside it, which becomes the head life-form that
performs the action for (next state, symbols read).  Each head life-form *is* an action
(writes, move, next state), so the rule file needs one life-form per distinct action.

The algorithm: copy N to the third row; if N is even it is not prime unless it is 2 (its
digits are exactly "10"); write 3 on the second
row; then repeatedly subtract the divisor from the remainder, right to left with a borrow,
until the remainder is zero (N divisible: not prime; unless it was the very first subtraction,
which means divisor == N: prime) or negative (restore the remainder from the top row, add 2
to the divisor and start again).  This stops at divisor == N rather than at the thesis's
"more than half as many digits" bound, which taken literally calls
121 = 11 x 11 prime (and 25 too if checked before dividing).
Not prime: the head runs left into an invisible cross, which becomes visible (the thesis's
display); prime: the head stops and turns green.
"""

from __future__ import annotations

from dataclasses import dataclass

from apps.ca.patterns import Pattern

TAPE, MARKER = 1, 2
FIRST_HEAD = 3
M = "M"
# Message bits.
SURVIVE, READ3, READ2, READ1, READ_MARK, W1, W0, MARK_SURVIVE = (1 << i for i in range(8))
CODE_SHIFT = 8
VERDICTS = ("YES",)  # halting states; failure is shown by the cross (see below)
# The failure cross: invisible cells left of the machine that become visible, the thesis's
# demonstration of "not prime" (section 7.4.2).
CROSS_HIDDEN, CROSS_SPREAD, CROSS_SHOWN = 1 << 24, 1 << 25, 1 << 26


@dataclass(frozen=True)
class Action:
    w2: int | None  # write to the divisor row (None = leave)
    w3: int | None  # write to the remainder row
    move: int  # -1 left, +1 right, 0 stay (halted)
    next: str


def _states() -> list[str]:
    names = ["START", "COPY", "CHKEVEN", "CHK2A", "CHK2B", "W3", "TORIGHT0", "TORIGHT1",
             "RESTORE", "INCSKIP", "INC", "FAIL"]
    names += [f"SUB{b}{f}{z}" for b in (0, 1) for f in (0, 1) for z in (0, 1)]
    return names + list(VERDICTS)


def delta(q: str, t1: int | str, t2: int, t3: int) -> Action | None:
    """The transition function; None = cannot happen (the head would vanish)."""
    digit = t1 != M
    if q in VERDICTS:
        return Action(None, None, 0, q)
    if q == "FAIL":  # not prime: run left until the head hits the invisible cross
        return Action(None, None, -1, "FAIL")
    if q == "START":
        return Action(None, None, +1, "COPY") if not digit else None
    if q == "COPY":
        return Action(None, t1, +1, "COPY") if digit else Action(None, None, -1, "CHKEVEN")
    if q == "CHKEVEN":
        if not digit:
            return None
        return Action(None, None, -1, "CHK2A") if t1 == 0 else Action(1, None, -1, "W3")
    # Even: prime only if N is 2, binary "10" (a 1, then the left end marker).
    if q == "CHK2A":
        return Action(None, None, -1, "CHK2B") if t1 == 1 else Action(None, None, -1, "FAIL")
    if q == "CHK2B":
        return Action(None, None, 0, "YES") if not digit else Action(None, None, -1, "FAIL")
    if q == "W3":
        return Action(None, None, -1, "FAIL") if not digit else Action(1, None, +1, "TORIGHT1")
    if q.startswith("TORIGHT"):
        f = q[-1]
        return Action(None, None, +1, q) if digit else Action(None, None, -1, f"SUB0{f}0")
    if q.startswith("SUB"):
        b, f, z = (int(c) for c in q[3:])
        if digit:
            d = t3 - t2 - b
            bit = d & 1
            return Action(None, bit, -1, f"SUB{int(d < 0)}{f}{int(z or bit)}")
        if b:
            return Action(None, None, +1, "RESTORE")  # negative: D does not divide N
        if z:
            return Action(None, None, +1, "TORIGHT0")  # remainder still positive
        # zero: D == N (prime) or D divides N (not prime)
        return Action(None, None, 0, "YES") if f else Action(None, None, -1, "FAIL")
    if q == "RESTORE":
        return Action(None, t1, +1, "RESTORE") if digit else Action(None, None, -1, "INCSKIP")
    if q == "INCSKIP":
        return Action(None, None, -1, "INC")
    if q == "INC":
        if not digit:
            return None
        return Action(1, None, +1, "TORIGHT1") if t2 == 0 else Action(0, None, -1, "INC")
    raise ValueError(q)


READS = [(t1, t2, t3) for t1 in (0, 1, M) for t2 in (0, 1) for t3 in (0, 1)]


def _read_bits(t1: int | str, t2: int, t3: int) -> int:
    return ((READ1 if t1 == 1 else 0) | (READ_MARK if t1 == M else 0)
            | (READ2 if t2 else 0) | (READ3 if t3 else 0))


def _machine() -> tuple[dict[str, int], dict[Action, int], dict[tuple[str, tuple], int]]:
    codes = {q: i + 1 for i, q in enumerate(_states())}
    actions: dict[Action, int] = {}
    table: dict[tuple[str, tuple], int] = {}
    for q in _states():
        for r in READS:
            a = delta(q, *r)
            if a is None:
                continue
            if a not in actions:
                actions[a] = FIRST_HEAD + len(actions)
            table[(q, r)] = actions[a]
    return codes, actions, table


def rules_text() -> str:
    codes, actions, table = _machine()
    out = ["// Three-tape Turing machine recognising primes (thesis section 7.4.2).",
           "// RECONSTRUCTED: generated by apps/ca/turing.py; see docs/ca.md.",
           "// 1 = a binary 1 on any tape, 2 = end marker, 3.. = the head, one life-form",
           "// per action (writes, move, next state).", "",
           "1 0 3 0 0 COLOUR FF FF FF  // tape 1: survive, tell the rows below what it is",
           f"|{SURVIVE}", f"|{READ3}", f"|{READ2}", f"|{READ1}", "",
           "2 0 3 0 0 COLOUR 40 80 FF  // end marker (top row only)",
           f"|#X{MARK_SURVIVE:X}", ".", ".", f"|{READ_MARK}", ""]
    cross = FIRST_HEAD + len(actions)
    out += [f"{cross} 0 0 0 0 COLOUR 00 00 00  // the failure cross, invisible",
            f"|#X{CROSS_HIDDEN:X}", "",
            f"{cross + 1} 1 1 1 1 COLOUR FF 00 00  // the failure cross, shown",
            f". |#X{CROSS_SPREAD:X} .",
            f"|#X{CROSS_SPREAD:X} |#X{CROSS_SHOWN:X} |#X{CROSS_SPREAD:X}",
            f". |#X{CROSS_SPREAD:X} .", ""]
    for a, t in actions.items():
        if a.next in VERDICTS:
            colour = "00 FF 00"
        elif a.next == "FAIL":
            colour = "FF 60 60"
        else:
            colour = "FF FF 00"
        w = {None: ".", 1: f"|{W1}", 0: f"|{W0}"}
        step = f"|#X{codes[a.next] << CODE_SHIFT:X}"
        row = [step if dx == a.move else "." for dx in (-1, 0, 1)]
        out += [f"{t} -2 0 -1 1 COLOUR {colour}  // head: {a}",
                f". {w[a.w2]} .", f". {w[a.w3]} .", " ".join(row), ""]
    out += ["$", "",
            "#B1??????? 2   // marker stays",
            "#B01????? 1    // written 1",
            "#B????1 1      // a 1 with no write stays (a write-0 message kills it)",
            f"#B1{'?' * 26} {cross + 1}   // the cross, once shown, stays shown",
            f"#B11{'?' * 24} {cross + 1}  // a hidden cross cell next to a shown one shows",
            f"R #X{CROSS_HIDDEN | 1 << CODE_SHIFT:X} #X{CROSS_HIDDEN | (CROSS_HIDDEN - 1):X} "
            f"{cross + 1}  // ... and so does one the failing head runs into",
            f"#X{CROSS_HIDDEN:X} {cross}  // otherwise it stays hidden",
            "// the head: (next state << 8) | symbols read -> the action's life-form"]
    for (q, r), t in table.items():
        out.append(f"#X{(codes[q] << CODE_SHIFT) | _read_bits(*r):X} {t}  // {q} {r}")
    return "\n".join(out) + "\n"


def verdict_forms() -> dict[str, int]:
    """The life-forms that show the verdict: the halted head (YES) and the shown cross
    (NO)."""
    _, actions, _ = _machine()
    forms = {a.next: t for a, t in actions.items() if a.next in VERDICTS}
    forms["NO"] = FIRST_HEAD + len(actions) + 1
    return forms


def cross_forms() -> tuple[int, int]:
    """(hidden, shown) life-forms of the failure cross."""
    _, actions, _ = _machine()
    return FIRST_HEAD + len(actions), FIRST_HEAD + len(actions) + 1


def pattern(n: int) -> Pattern:
    """N in binary between markers on the top row, the head three rows below the left end."""
    if n < 1:
        raise ValueError("the machine tests numbers >= 1")
    bits = bin(n)[2:]
    cells = [(0, 0, MARKER), (len(bits) + 1, 0, MARKER)]
    cells += [(i + 1, 0, TAPE) for i, b in enumerate(bits) if b == "1"]
    _, _, table = _machine()
    cells.append((0, 3, table[("START", (M, 0, 0))]))
    hidden, _ = cross_forms()
    cx, cy = -6, 3  # the cross, left of the machine on the head's row
    cells += [(cx + d, cy, hidden) for d in range(-2, 3)]
    cells += [(cx, cy + d, hidden) for d in (-2, -1, 1, 2)]
    return Pattern.from_cells(cells, ref=(0, 0), name=f"prime test of {n}",
                              rule="turing_primes")
