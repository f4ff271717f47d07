"""The rule language of thesis figures 7.6 and 7.8, parsed into a :class:`RuleSet`.

A rule file has two parts separated by ``$``.  The message part gives, for each life-form,
its number, its message extents, an optional ``COLOUR rr gg bb`` or ``INVISIBLE`` (drawn as a
dead cell outside editing: section 7.4.2's "invisible cells", reconstructed), an optional
(reconstructed, section 8.1) ``BROADCAST op`` and the message grid; the interpretation part
maps the value in a cell's 32-bit message area to the life-form it holds next generation.
The format is free: tokens may be split over lines at will; ``//`` starts a comment. See
docs/ca.md.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from fractions import Fraction

from camlab88.base.textinput import InputError, quote, read_text, where

MAX_LIFEFORM = 65535  # cells hold a uint16-sized type; no small hard limit (thesis had 40)
MAX_REACH = 32767  # half the 65536-cell plane: any further and messages meet themselves
MASK32 = 0xFFFFFFFF

# Message operations, in the order their codes are used by the engine kernels.
OP_ADD, OP_OR, OP_AND, OP_XOR = 1, 2, 3, 4
OP_SYMBOLS = {"+": OP_ADD, "|": OP_OR, "&": OP_AND, "^": OP_XOR}
OP_NAMES = {OP_ADD: "+", OP_OR: "|", OP_AND: "&", OP_XOR: "^"}

# Interpretation kinds.
MATCH_EXACT, MATCH_PATTERN, MATCH_RANGE = 0, 1, 2


class RuleError(ValueError):
    """A rule file is malformed; the message names source, line, column and what was expected."""

    def __init__(self, source: str, line: int, column: int, message: str) -> None:
        super().__init__(f"{where(source, line or None, column or None)}: {message}")
        self.source = source
        self.line = line
        self.column = column
        self.detail = message


class Token:
    """A word of the rule text and where it starts (the parser's own: a plain class, since
    a rule table has thousands of them and a frozen dataclass's __init__ is slow)."""

    __slots__ = ("text", "line", "column")

    def __init__(self, text: str, line: int, column: int) -> None:
        self.text = text
        self.line = line
        self.column = column


@dataclass(frozen=True)
class Message:
    dy: int
    dx: int
    op: int
    value: int


@dataclass(frozen=True)
class LifeForm:
    number: int
    top: int  # offset of the first grid row (negative = above the sender)
    left: int  # offset of the first grid column (negative = left of the sender)
    rows: int
    cols: int
    messages: tuple[Message, ...]
    colour: tuple[int, int, int] | None = None
    broadcast: tuple[int, int] | None = None  # (op, value) sent to all receiving cells
    invisible: bool = False  # drawn as a dead cell (but in editing, where it must be seen)


@dataclass(frozen=True)
class Outcome:
    """Life-forms to choose between, with exact probabilities (one entry = deterministic)."""

    choices: tuple[tuple[Fraction, int], ...]


@dataclass(frozen=True)
class Interpretation:
    kind: int
    a: int  # exact: value; pattern: mask of bits that must match; range: low
    b: int  # exact: unused; pattern: required bits; range: high
    outcome: Outcome
    line: int

    def matches(self, value: int) -> bool:
        if self.kind == MATCH_EXACT:
            return value == self.a
        if self.kind == MATCH_PATTERN:
            return value & self.a == self.b
        return self.a <= value <= self.b


@dataclass(frozen=True)
class RuleSet:
    forms: dict[int, LifeForm]
    interpretations: tuple[Interpretation, ...]
    source: str = "<rules>"
    text: str = ""
    _tables: dict = field(default_factory=dict, compare=False, repr=False)

    @property
    def max_form(self) -> int:
        """Largest life-form number that has message rules or is produced by a rule."""
        produced = [lf for it in self.interpretations for _, lf in it.outcome.choices]
        return max([0, *self.forms, *produced])

    @property
    def reach(self) -> tuple[int, int]:
        """Furthest (rows, columns) any message travels from its sender."""
        ry = rx = 0
        for f in self.forms.values():
            for m in f.messages:
                ry, rx = max(ry, abs(m.dy)), max(rx, abs(m.dx))
        return ry, rx

    def interpret(self, value: int) -> Outcome | None:
        """The first interpretation line that matches ``value`` (None: the cell dies)."""
        for it in self.interpretations:
            if it.matches(value):
                return it.outcome
        return None


_COMMENT = re.compile(r"//[^\n]*")
_WORD = re.compile(r"\S+")
_DIGITS = re.compile(r"[0-9]+")
_SIGNED = re.compile(r"[+-]?[0-9]+")
# the outcome of most lines: one life-form, for certain (shared, as the lines are many)
_CERTAIN = Fraction(1)


def tokenize(text: str) -> list[Token]:
    tokens: list[Token] = []
    for lineno, raw in enumerate(text.splitlines(), start=1):
        line = _COMMENT.sub("", raw) if "//" in raw else raw
        for m in _WORD.finditer(line):
            tokens.append(Token(m.group(0), lineno, m.start() + 1))
    return tokens


def parse_number(tok: Token, text: str, source: str, what: str = "a number") -> int:
    """Decimal, ``#X`` hexadecimal or ``#B`` binary, as the figures write them."""
    t = text.upper()
    if len(t) > 40:  # 32 binary digits and the '#B'; longer is never a 32-bit number
        raise RuleError(source, tok.line, tok.column,
                        f"number {quote(tok.text, 24)} does not fit the 32-bit message area")
    try:
        if t.startswith("#X"):
            if not re.fullmatch(r"[0-9A-F]+", t[2:]):
                raise ValueError
            value = int(t[2:], 16)
        elif t.startswith("#B"):
            if not re.fullmatch(r"[01]+", t[2:]):
                raise ValueError
            value = int(t[2:], 2)
        else:
            if not _DIGITS.fullmatch(t):
                raise ValueError
            value = int(t, 10)
    except ValueError:
        raise RuleError(
            source, tok.line, tok.column,
            f"expected {what} (decimal, #X hex or #B binary), found '{tok.text}'",
        ) from None
    if value > MASK32:
        raise RuleError(source, tok.line, tok.column,
                        f"number '{tok.text}' does not fit the 32-bit message area")
    return value


class _Parser:
    def __init__(self, text: str, source: str) -> None:
        self.tokens = tokenize(text)
        self.pos = 0
        self.source = source
        lines = text.splitlines()
        self.eof_line = max(1, len(lines))
        self.eof_col = (len(lines[-1]) + 1) if lines else 1

    # -- token helpers --------------------------------------------------------
    def peek(self) -> Token | None:
        return self.tokens[self.pos] if self.pos < len(self.tokens) else None

    def error(self, tok: Token | None, message: str) -> RuleError:
        if tok is None:
            return RuleError(self.source, self.eof_line, self.eof_col,
                             message + ", found end of file")
        return RuleError(self.source, tok.line, tok.column, message)

    def take(self, expected: str) -> Token:
        tok = self.peek()
        if tok is None:
            raise self.error(None, f"expected {expected}")
        self.pos += 1
        return tok

    def integer(self, expected: str, signed: bool = False) -> int:
        tok = self.take(expected)
        if not (_SIGNED if signed else _DIGITS).fullmatch(tok.text):
            raise self.error(tok, f"expected {expected}, found '{tok.text}'")
        return int(tok.text)

    # -- message part ---------------------------------------------------------
    def parse(self) -> tuple[dict[int, LifeForm], tuple[Interpretation, ...]]:
        forms: dict[int, LifeForm] = {}
        while True:
            tok = self.peek()
            if tok is None:
                raise self.error(None, "expected a life-form number or '$' ending the message "
                                       "rules")
            if tok.text == "$":
                self.pos += 1
                break
            try:
                form = self.lifeform()
            except RuleError as exc:
                if not forms:
                    raise
                # After a complete grid, what does not parse as a life-form is most often
                # an interpretation line with the '$' before it forgotten: point there.
                raise self.error(tok, f"expected '$' ending the message rules (after the grid "
                                      f"of life-form {max(forms)}) or another life-form; "
                                      f"read as a life-form it fails at {exc.line}:"
                                      f"{exc.column}: {exc.detail}") from None
            if form.number in forms:
                raise self.error(tok, f"life-form {form.number} is defined twice "
                                      f"(first definition has its own grid)")
            forms[form.number] = form
        interps: list[Interpretation] = []
        while self.peek() is not None:
            interps.append(self.interpretation())
        return forms, tuple(interps)

    def lifeform_number(self, expected: str) -> tuple[Token, int]:
        tok = self.peek()
        value = self.integer(expected)
        assert tok is not None
        if not 1 <= value <= MAX_LIFEFORM:
            raise self.error(tok, f"life-form number must be 1..{MAX_LIFEFORM}, found {value}")
        return tok, value

    def lifeform(self) -> LifeForm:
        _, number = self.lifeform_number("a life-form number or '$' ending the message rules")
        head_tok = self.peek()
        nums = [self.integer("four message extents (e.g. '1 1 1 1' or '-1 1 -1 1')",
                             signed=True) for _ in range(4)]
        colour = None
        broadcast = None
        invisible = False
        while (tok := self.peek()) is not None and tok.text.upper() in ("COLOUR", "COLOR",
                                                                         "BROADCAST", "INVISIBLE"):
            self.pos += 1
            if tok.text.upper() == "INVISIBLE":
                if invisible or colour is not None:
                    raise self.error(tok, "INVISIBLE given twice, or with COLOUR, for one "
                                          "life-form")
                invisible = True
            elif tok.text.upper() == "BROADCAST":
                if broadcast is not None:
                    raise self.error(tok, "BROADCAST given twice for one life-form")
                op_tok = self.take("a broadcast message such as '|#X100'")
                if op_tok.text[:1] not in OP_SYMBOLS or len(op_tok.text) < 2:
                    raise self.error(op_tok, "expected a broadcast message '+n', '|n', '&n' or "
                                             f"'^n', found '{op_tok.text}'")
                broadcast = self.entry(op_tok)
            else:
                if colour is not None or invisible:
                    raise self.error(tok, "COLOUR given twice, or with INVISIBLE, for one "
                                          "life-form")
                colour = tuple(self.hex_byte() for _ in range(3))
        grid_start = self.peek()
        entries: list[tuple[int, int] | None] = []
        while (tok := self.peek()) is not None and tok.text[0] in ".+|&^":
            self.pos += 1
            entries.append(self.entry(tok))
        if not entries:
            raise self.error(grid_start, f"expected the message grid of life-form {number} "
                                         "('.', '+n', '|n', '&n' or '^n' entries)"
                             + (f", found '{grid_start.text}'" if grid_start else ""))
        assert head_tok is not None and grid_start is not None
        top, left, rows, cols = self.shape(nums, len(entries), head_tok, grid_start)
        messages = []
        for i, e in enumerate(entries):
            if e is not None:
                messages.append(Message(top + i // cols, left + i % cols, e[0], e[1]))
        return LifeForm(number, top, left, rows, cols, tuple(messages), colour, broadcast,
                        invisible)

    def hex_byte(self) -> int:
        tok = self.take("three two-digit hexadecimal colour components (e.g. 'COLOUR 00 FF 00')")
        text = tok.text.upper()
        if text.startswith("#X"):
            text = text[2:]
        if not re.fullmatch(r"[0-9A-F]{1,2}", text):
            raise self.error(tok, "expected a hexadecimal colour component 00..FF, "
                                  f"found '{tok.text}'")
        return int(text, 16)

    def entry(self, tok: Token) -> tuple[int, int] | None:
        if tok.text == ".":
            return None
        op = OP_SYMBOLS.get(tok.text[0])
        if op is None or len(tok.text) == 1:
            raise self.error(tok, "expected a message grid entry '.', '+n', '|n', '&n' or '^n', "
                                  f"found '{tok.text}'")
        value = parse_number(tok, tok.text[1:], self.source, "a message value")
        return op, value

    def shape(self, nums: list[int], count: int, head: Token,
              grid: Token) -> tuple[int, int, int, int]:
        """Resolve the two printed forms of the extents; the grid's size decides."""
        a, b, c, d = nums
        candidates: list[tuple[int, int, int, int]] = []
        if min(nums) >= 0:  # figure 7.6: above, below, left, right
            candidates.append((-a, -c, a + b + 1, c + d + 1))
        if a <= b and c <= d:  # figure 7.8: row range then column range
            candidates.append((a, c, b - a + 1, d - c + 1))
        if not candidates:
            raise self.error(head, f"expected extents 'above below left right' (all >= 0) or "
                                   f"ranges 'top bottom left right' (low <= high), found "
                                   f"'{a} {b} {c} {d}'")
        for top, left, rows, cols in candidates:
            if max(abs(top), abs(top + rows - 1), abs(left), abs(left + cols - 1)) > MAX_REACH:
                raise self.error(head, f"message extents reach beyond {MAX_REACH} cells")
        # Extents give a grid at least as large as ranges, equal only when both low numbers
        # are 0, where the two readings coincide: so at most one distinct reading fits.
        fits = [cand for cand in candidates if cand[2] * cand[3] == count]
        if not fits:
            sizes = " or ".join(f"{r}x{c}={r * c}" for _, _, r, c in candidates)
            raise self.error(grid, f"message grid has {count} entries but extents "
                                   f"'{a} {b} {c} {d}' need {sizes}")
        return fits[0]

    # -- interpretation part --------------------------------------------------
    def interpretation(self) -> Interpretation:
        tok = self.take("an interpretation line")
        text = tok.text.upper()
        if text == "R":
            lo_tok = self.peek()
            lo = self.value_token("the low bound of 'R lo hi life-form'")
            hi = self.value_token("the high bound of 'R lo hi life-form'")
            if lo > hi:
                raise self.error(lo_tok, f"range low bound {lo} is above high bound {hi}")
            kind, a, b = MATCH_RANGE, lo, hi
        elif text.startswith("#B") and "?" in text:
            bits = text[2:]
            if not re.fullmatch(r"[01?]+", bits):
                raise self.error(tok, f"expected a #B pattern of 0, 1 and ?, found '{tok.text}'")
            if len(bits) > 32:
                raise self.error(tok, f"pattern '{tok.text}' is longer than the 32-bit message "
                                      "area")
            mask = MASK32 & ~((1 << len(bits)) - 1)  # bits above the pattern must be zero
            want = 0
            for i, ch in enumerate(reversed(bits)):
                if ch != "?":
                    mask |= 1 << i
                    want |= int(ch) << i
            kind, a, b = MATCH_PATTERN, mask, want
        else:
            if "?" in text:
                raise self.error(tok, f"'?' is only allowed in #B patterns, found '{tok.text}'")
            if not ((text[:1].isascii() and text[:1].isdigit()) or text.startswith(("#X", "#B"))):
                raise self.error(tok, "expected an interpretation line: a value, a #B pattern "
                                      f"or 'R lo hi', found '{tok.text}'")
            kind, a, b = MATCH_EXACT, parse_number(tok, tok.text, self.source), 0
        return Interpretation(kind, a, b, self.outcome(tok), tok.line)

    def value_token(self, expected: str) -> int:
        tok = self.take(expected)
        return parse_number(tok, tok.text, self.source, expected)

    def outcome(self, start: Token) -> Outcome:
        tok = self.peek()
        if tok is not None and tok.text.endswith("%"):
            choices: list[tuple[Fraction, int]] = []
            total = Fraction(0)
            while (tok := self.peek()) is not None and tok.text.endswith("%"):
                self.pos += 1
                m = re.fullmatch(r"([0-9]+(?:\.[0-9]+)?)%", tok.text)
                if not m:
                    raise self.error(tok, f"expected a percentage such as '50%', found "
                                          f"'{tok.text}'")
                p = Fraction(m.group(1)) / 100
                _, form = self.lifeform_or_dead("the life-form chosen with probability "
                                                f"{tok.text}")
                choices.append((p, form))
                total += p
            if total != 1:
                raise self.error(start, f"probabilities add up to {float(total) * 100:g}%, "
                                        "expected 100%")
            return Outcome(tuple(choices))
        _, form = self.lifeform_or_dead("the life-form to become (or percentages such as "
                                        "'50% 3')")
        return Outcome(((_CERTAIN, form),))

    def lifeform_or_dead(self, expected: str) -> tuple[Token, int]:
        tok = self.peek()
        value = self.integer(expected)
        assert tok is not None
        if value > MAX_LIFEFORM:
            raise self.error(tok, f"life-form number must be 0..{MAX_LIFEFORM}, found {value}")
        return tok, value


def parse_rules(text: str, source: str = "<rules>") -> RuleSet:
    """Parse rule text; raises :class:`RuleError` naming line and column on any fault."""
    forms, interps = _Parser(text, source).parse()
    return RuleSet(forms=forms, interpretations=interps, source=source, text=text)


def load_rules(path: str) -> RuleSet:
    """A rule file; a directory, a bad byte or a bad rule raises RuleError naming where."""
    try:
        text = read_text(path)
    except InputError as exc:
        raise RuleError(str(path), exc.line, exc.column, exc.reason) from None
    return parse_rules(text, source=str(path))
