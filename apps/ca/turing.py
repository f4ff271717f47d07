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

The algorithm (§7.4.2): copy N to the third row; if N is even it is not prime unless it is 2
(its digits are exactly "10"); write 3 on the second row; then, for each trial divisor D:

* the bound check — D is declared prime-proof when it "contains more than half as many
  significant digits as the number on the top row" (rounded up: with k digits in N, a D of
  more than ceil(k/2) digits has D^2 >= 2^k > N).  With D right-aligned under N that is "D
  has a 1 in the leftmost floor(k/2) columns", which the head finds by pairing off the
  columns from both ends on the third row (cleared first; crossed = 1): a column from the
  right, then one from the left, ...; the left-hand crossings are exactly the leftmost
  floor(k/2) columns, and a 1 of D under one of them halts the machine: prime.  The third
  row is then restored from the top row.
* division by repeated subtraction of D from the remainder, right to left with a borrow,
  until the remainder is zero (D divides N: not prime) or negative (clear the third row,
  add 2 to D, and check again).

So the machine tries O(sqrt N) divisors, 3, 5, ... up to the first with more than ceil(k/2)
digits, never D = N (``trial_divisors`` counts them).  Not prime: the head runs left into an
invisible cross, which becomes visible (the thesis's display); prime: the head stops and
turns green.
"""

from __future__ import annotations

from dataclasses import dataclass

from camlab88.apps.ca.patterns import Pattern

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
    names = ["START", "COPY", "CHKEVEN", "CHK2A", "CHK2B", "W3", "TOLEFTC", "CLEARC",
             "CLEARI", "PRGO", "PRSEEK", "PLGO", "PLSEEK", "TOLEFTR", "RESTORE", "TORIGHT",
             "INCSKIP", "INC", "FAIL"]
    names += [f"SUB{b}{z}" for b in (0, 1) for z in (0, 1)]
    return names + list(VERDICTS)


def _moving(q: str, digit: bool, move: int, then: Action) -> Action:
    """Keep moving (state ``q``) over the digits; at an end marker do ``then``."""
    return Action(None, None, move, q) if digit else then


def _setup(q: str, t1: int | str, digit: bool) -> Action | None:
    """Copy N to the third row, reject even numbers (but 2), write 3 on the second row."""
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
    if q == "W3":  # N = 1 has no second digit: not prime
        return Action(1, None, -1, "TOLEFTC") if digit else Action(None, None, -1, "FAIL")
    return None


def _bound(q: str, digit: bool, t2: int, t3: int) -> Action | None:
    """The digit-count bound: clear row 3, pair columns off from both ends (module doc)."""
    if q in ("TOLEFTC", "TOLEFTR"):
        nxt = "CLEARC" if q == "TOLEFTC" else "RESTORE"
        return _moving(q, digit, -1, Action(None, None, +1, nxt))
    if q in ("CLEARC", "CLEARI"):
        nxt = "PRSEEK" if q == "CLEARC" else "INCSKIP"
        return Action(None, 0, +1, q) if digit else Action(None, None, -1, nxt)
    if q == "PRGO":
        return _moving(q, digit, +1, Action(None, None, -1, "PRSEEK"))
    if q == "PRSEEK":  # cross the rightmost free column; none left: not proven, go on
        if not digit:
            return Action(None, None, +1, "RESTORE")
        return Action(None, None, -1, q) if t3 else Action(None, 1, -1, "PLGO")
    if q == "PLGO":
        return _moving(q, digit, -1, Action(None, None, +1, "PLSEEK"))
    if q == "PLSEEK":  # the leftmost free column: a 1 of D there proves N prime
        if not digit:
            return Action(None, None, -1, "TOLEFTR")
        if t3:
            return Action(None, None, +1, q)
        return Action(None, None, 0, "YES") if t2 else Action(None, 1, +1, "PRGO")
    return None


def _divide(q: str, t1: int | str, digit: bool, t2: int, t3: int) -> Action | None:
    """Repeated subtraction of D from the remainder; the next odd D when it goes negative."""
    if q == "RESTORE":
        return Action(None, t1, +1, q) if digit else Action(None, None, -1, "SUB00")
    if q == "TORIGHT":
        return _moving(q, digit, +1, Action(None, None, -1, "SUB00"))
    if q.startswith("SUB"):
        b, z = int(q[3]), int(q[4])
        if digit:
            d = t3 - t2 - b
            bit = d & 1
            return Action(None, bit, -1, f"SUB{int(d < 0)}{int(z or bit)}")
        if b:
            return Action(None, None, +1, "CLEARI")  # negative: D does not divide N
        if z:
            return Action(None, None, +1, "TORIGHT")  # remainder still positive
        return Action(None, None, -1, "FAIL")  # zero: D (< N) divides N
    if q == "INCSKIP":
        return Action(None, None, -1, "INC")
    if q == "INC":
        if not digit:
            return None
        return Action(1, None, +1, "PRGO") if t2 == 0 else Action(0, None, -1, "INC")
    return None


def delta(q: str, t1: int | str, t2: int, t3: int) -> Action | None:
    """The transition function; None = cannot happen (the head would vanish)."""
    digit = t1 != M
    if q in VERDICTS:
        return Action(None, None, 0, q)
    if q == "FAIL":  # not prime: run left until the head hits the invisible cross
        return Action(None, None, -1, "FAIL")
    for part in (_setup(q, t1, digit), _bound(q, digit, t2, t3),
                 _divide(q, t1, digit, t2, t3)):
        if part is not None:
            return part
    if q not in _states():
        raise ValueError(q)
    return None


@dataclass
class Run:
    """A run of the machine on plain tapes: verdict, the trial divisors in order (each D
    the bound check looked at), and the number of head steps."""

    verdict: str
    divisors: list[int]
    steps: int


def simulate(n: int, limit: int = 10**7) -> Run:
    """Run ``delta`` on three Python tapes (the oracle the cellular automaton is tested
    against); the head starts under the left end marker."""
    bits = [int(b) for b in bin(n)[2:]]
    t1: list[int | str] = [M, *bits, M]
    t2, t3 = [0] * len(t1), [0] * len(t1)
    pos, q, divisors = 0, "START", []
    for steps in range(limit):
        a = delta(q, t1[pos], t2[pos], t3[pos])
        if a is None:
            raise RuntimeError(f"the head vanished in state {q} at column {pos}")
        if a.w2 is not None:
            t2[pos] = a.w2
        if a.w3 is not None:
            t3[pos] = a.w3
        if (q, a.next) in (("W3", "TOLEFTC"), ("INC", "PRGO")):
            divisors.append(int("".join(map(str, t2[1:-1])), 2))  # D complete: check it
        if a.next in VERDICTS or a.next == "FAIL":
            return Run("YES" if a.next in VERDICTS else "NO", divisors, steps + 1)
        pos, q = pos + a.move, a.next
    raise RuntimeError(f"no verdict for {n} in {limit} steps")


def trial_divisor_bound(n: int) -> int:
    """The last divisor tried for a prime ``n``: the first odd D with more than ceil(k/2)
    binary digits, k = N's digits (§7.4.2's "more than half as many")."""
    k = n.bit_length()
    return (1 << -(-k // 2)) + 1


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
    out += [f"{cross} 0 0 0 0 INVISIBLE  // the failure cross, hidden until 'not prime'",
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
