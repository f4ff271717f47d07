"""The rule language: figures 7.6 and 7.8 as printed, the extensions, and every error path."""

from __future__ import annotations

from fractions import Fraction
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from camlab88.apps.ca.library import rules_path
from camlab88.apps.ca.rules import (
    MATCH_EXACT,
    MATCH_PATTERN,
    MATCH_RANGE,
    OP_ADD,
    OP_AND,
    OP_OR,
    OP_XOR,
    RuleError,
    load_rules,
    parse_rules,
)

DATA = Path(__file__).resolve().parents[1] / "data" / "ca"


def test_figure_7_6_life_as_printed() -> None:
    r = load_rules(str(DATA / "figure_7_6.rules"))
    f = r.forms[1]
    assert (f.top, f.left, f.rows, f.cols) == (-1, -1, 3, 3)
    assert f.colour == (0, 255, 0)
    centre = [m for m in f.messages if (m.dy, m.dx) == (0, 0)]
    assert centre[0].op == OP_OR and centre[0].value == 0x10
    assert sum(1 for m in f.messages if m.op == OP_ADD and m.value == 1) == 8
    first, second = r.interpretations
    assert (first.kind, first.a) == (MATCH_EXACT, 0x12)
    assert second.kind == MATCH_PATTERN
    # '#B?0011': 3 and 19 match; nothing with bits above the pattern does.
    assert [v for v in range(1 << 12) if second.matches(v)] == [3, 19]
    assert r.interpret(0x12).choices == ((Fraction(1), 1),)
    assert r.interpret(2) is None


def test_library_life_is_figure_7_6() -> None:
    assert load_rules(rules_path("life")).text == (DATA / "figure_7_6.rules").read_text()


def test_figure_7_8_maze_as_printed() -> None:
    r = load_rules(str(DATA / "figure_7_8.rules"))
    assert load_rules(rules_path("maze")).text == r.text
    walls, head, tail = r.forms[1], r.forms[2], r.forms[3]
    assert (walls.top, walls.left, walls.rows, walls.cols) == (-1, -1, 3, 3)
    assert (tail.top, tail.left, tail.rows, tail.cols) == (-2, -2, 5, 5)
    assert {(m.dy, m.dx) for m in head.messages} == {(-1, 0), (0, -1), (0, 0), (0, 1), (1, 0)}
    assert {(m.dy, m.dx): m.value for m in tail.messages}[(0, 0)] == 32
    assert len(tail.messages) == 9
    pat, seven, rng = r.interpretations
    assert [v for v in range(64) if pat.matches(v)] == list(range(8, 16))
    assert (seven.kind, seven.a) == (MATCH_EXACT, 7)
    assert (rng.kind, rng.a, rng.b) == (MATCH_RANGE, 16, 23)
    assert r.interpret(20).choices[0][1] == 3


def test_numbers_ops_and_first_match() -> None:
    r = parse_rules("""
        5 0 0 1 1   &#XFF  ^#B101  |7   // extents form, one row of three
        $
        #B11 2  3 9  R 0 10 4
    """)
    f = r.forms[5]
    assert [(m.dx, m.op, m.value) for m in f.messages] == [
        (-1, OP_AND, 255), (0, OP_XOR, 5), (1, OP_OR, 7)]
    assert r.interpret(3).choices[0][1] == 2  # '#B11' without ? is the number 3; first wins
    assert r.interpret(4).choices[0][1] == 4


def test_probabilistic_outcome_section_8_1() -> None:
    r = parse_rules("1 0 0 0 0 |1 $ 10001 50% 3 40% 6 10% 0  1 12.5% 1 87.5% 2")
    a, b = r.interpretations
    assert a.a == 10001
    assert a.outcome.choices == ((Fraction(1, 2), 3), (Fraction(2, 5), 6), (Fraction(1, 10), 0))
    assert b.outcome.choices[0][0] == Fraction(1, 8)


def test_broadcast_and_many_lifeforms() -> None:
    body = "".join(f"{n} 0 0 0 0 COLOUR 10 20 30 BROADCAST |#X100 |{n}\n" for n in range(1, 61))
    r = parse_rules(body + "$ 1 1")
    assert len(r.forms) == 60 and r.max_form == 60
    assert r.forms[60].broadcast == (OP_OR, 0x100)
    assert r.forms[60].colour == (0x10, 0x20, 0x30)


def test_extents_are_above_below_left_right_and_ranges_inclusive() -> None:
    # figure 7.6's comment: the extents are the rows above and below the sender, then the
    # columns to its left and right; here two rows above, none below, one column right
    f = parse_rules("1 2 0 0 1  +1 +2  +4 +8  +16 +32 $ 1 1").forms[1]
    assert (f.top, f.left, f.rows, f.cols) == (-2, 0, 3, 2)
    assert [(m.dy, m.dx, m.value) for m in f.messages] == [
        (-2, 0, 1), (-2, 1, 2), (-1, 0, 4), (-1, 1, 8), (0, 0, 16), (0, 1, 32)]
    r = parse_rules("1 0 0 0 0 |1 $ R 2 4 1")  # figure 7.8's 'R lo hi life-form'
    assert [v for v in range(7) if r.interpret(v) is not None] == [2, 3, 4]


def test_free_format_and_both_extent_forms_agree() -> None:
    a = parse_rules("1 1 1 1 1 +1 +1 +1 +1 |16 +1 +1 +1 +1 $ 3 1")
    b = parse_rules("1\n-1\n1\n-1 1\n+1 +1 +1\n+1 |16 +1\n+1 +1 +1\n$\n3\n1")
    assert a.forms == b.forms


ERRORS = [
    ("", 1, 1, "expected a life-form number or '$'"),
    ("// only a comment\n", 1, 18, "found end of file"),
    ("x", 1, 1, "expected a life-form number"),
    ("0 1 1 1 1", 1, 1, "life-form number must be 1..65535"),
    ("70000 1 1 1 1", 1, 1, "life-form number must be 1..65535"),
    ("1 1 1 1", 1, 8, "expected four message extents"),
    ("1 1 a 1 1", 1, 5, "expected four message extents"),
    ("1 2 1 -1 -2 +1", 1, 3, "expected extents"),
    ("1 40000 0 0 0 +1", 1, 3, "reach beyond"),
    ("1 0 0 0 0 $", 1, 11, "expected the message grid of life-form 1"),
    ("1 1 1 1 1\n+1 +1 $", 2, 1, "message grid has 2 entries but extents '1 1 1 1' need 3x3=9"),
    ("1 0 0 0 0 +", 1, 11, "expected a message grid entry"),
    ("1 0 0 0 0 +x", 1, 11, "expected a message value"),
    ("1 0 0 0 0 |#XZZ", 1, 11, "expected a message value"),
    ("1 0 0 0 0 |#B102", 1, 11, "expected a message value"),
    ("1 0 0 0 0 +4294967296", 1, 11, "does not fit the 32-bit message area"),
    ("1 0 0 0 0 COLOUR 00 GG 00 +1", 1, 21, "hexadecimal colour component"),
    ("1 0 0 0 0 COLOUR 00 FF", 1, 23, "colour components"),
    ("1 0 0 0 0 COLOUR 00 FF 00 COLOUR 00 FF 00 +1", 1, 27, "COLOUR given twice, or with"),
    ("1 0 0 0 0 COLOUR 00 FF 00 INVISIBLE +1", 1, 27, "INVISIBLE given twice, or with COLOUR"),
    ("1 0 0 0 0 INVISIBLE COLOUR 00 FF 00 +1", 1, 21, "COLOUR given twice, or with INVISIBLE"),
    ("1 0 0 0 0 BROADCAST 5 +1", 1, 21, "expected a broadcast message"),
    ("1 0 0 0 0 BROADCAST", 1, 20, "expected a broadcast message"),
    ("1 0 0 0 0 BROADCAST |1 BROADCAST |2 +1", 1, 24, "BROADCAST given twice"),
    ("1 0 0 0 0 +1\n1 0 0 0 0 +1 $", 2, 1, "life-form 1 is defined twice"),
    ("1 0 0 0 0 +1", 1, 13, "'$' ending the message rules"),
    ("1 1 1 1 1 +1 +1 +1 +1 |16 +1 +1 +1 +1\n3 1\n18 1", 2, 1,
     "expected '$' ending the message rules (after the grid of life-form 1)"),
    ("1 0 0 0 0 +1\n#X12 1", 2, 1, "expected '$' ending the message rules"),
    ("1 0 0 0 0 +1\n R 1 2 1", 2, 2, "expected '$' ending the message rules"),
    ("1 0 0 0 0 +1 $ foo 1", 1, 16, "expected an interpretation line"),
    ("1 0 0 0 0 +1 $ 3", 1, 17, "expected the life-form to become"),
    ("1 0 0 0 0 +1 $ 3 x", 1, 18, "expected the life-form to become"),
    ("1 0 0 0 0 +1 $ 3 70000", 1, 18, "life-form number must be 0..65535"),
    ("1 0 0 0 0 +1 $ R 5", 1, 19, "high bound"),
    ("1 0 0 0 0 +1 $ R x 5 1", 1, 18, "low bound"),
    ("1 0 0 0 0 +1 $ R 6 5 1", 1, 18, "range low bound 6 is above high bound 5"),
    ("1 0 0 0 0 +1 $ #B1?2 1", 1, 16, "expected a #B pattern"),
    ("1 0 0 0 0 +1 $ #B" + "?" * 33 + " 1", 1, 16, "longer than the 32-bit"),
    ("1 0 0 0 0 +1 $ #X1? 1", 1, 16, "'?' is only allowed in #B patterns"),
    ("1 0 0 0 0 +1 $ 99999999999 1", 1, 16, "does not fit"),
    ("1 0 0 0 0 +1 $ 5 50% 1 40% 2", 1, 16, "probabilities add up to 90%, expected 100%"),
    ("1 0 0 0 0 +1 $ 5 fifty% 1", 1, 18, "expected a percentage"),
    ("1 0 0 0 0 +1 $ 5 50%", 1, 21, "the life-form chosen with probability 50%"),
]


@pytest.mark.parametrize(("text", "line", "col", "words"), ERRORS)
def test_every_error_names_line_column_and_expectation(text: str, line: int, col: int,
                                                       words: str) -> None:
    with pytest.raises(RuleError) as info:
        parse_rules(text, source="bad.rules")
    err = info.value
    assert (err.line, err.column) == (line, col), str(err)
    assert words in str(err)
    assert str(err).startswith(f"bad.rules:{line}:{col}: ")


@settings(max_examples=150, deadline=None)
@given(st.text(alphabet="0123456789 $+|&^.#XBR?%-\n/abCOLUR", max_size=60))
def test_any_text_parses_or_raises_rule_error(text: str) -> None:
    try:
        parse_rules(text)
    except RuleError as err:
        assert err.line >= 1 and err.column >= 1


def test_invisible_lifeform_parses() -> None:
    rules = parse_rules("1 0 0 0 0 invisible |1\n2 0 0 0 0 |1\n$\n1 1\n")
    assert rules.forms[1].invisible and rules.forms[1].colour is None
    assert not rules.forms[2].invisible


def test_default_colours_are_green_red_blue_then_unique() -> None:
    # section 7.4.1: type 1 "green by default", type 2 "red", type 3 "blue"
    from camlab88.apps.ca.render import palette

    rules = parse_rules("1 0 0 0 0 |1  2 0 0 0 0 |1  3 0 0 0 0 |1 $ 1 1")
    pal = [tuple(int(v) for v in c) for c in palette(rules, 40)]
    assert pal[:4] == [(0, 0, 0), (0, 255, 0), (255, 0, 0), (0, 0, 255)]
    assert len(set(pal[1:])) == 40  # a unique colour per life-form
