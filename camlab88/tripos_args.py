"""Tripos-style arguments (ReadArgs templates), as the thesis's programs took them.

Section 7.3.1 gives the CA program's template: ``Log/k, RecordPansAndZooms/s, Checkpoint,
Script/k, ReplayPansAndZooms/s`` — ``/k``: the keyword must be quoted before its value,
``/s``: a switch (TRUE when given), no qualifier: the value may be given with its keyword or
by position.  As Tripos's ReadArgs did (reconstructed: the thesis gives only the template),
keywords are matched without regard to case, ``KEY=value`` is accepted beside ``KEY value``,
and a word that is not a keyword fills the first unfilled positional item.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass


class TriposArgsError(ValueError):
    """A bad Tripos argument list; the message names the argument and its position."""


@dataclass(frozen=True)
class Item:
    """One template item: its keyword and qualifier ('' / 'k' / 's')."""

    keyword: str
    qualifier: str = ""


def parse_template(template: str) -> list[Item]:
    """``"Log/k,RecordPansAndZooms/s,Checkpoint"`` -> items."""
    items = []
    for part in template.split(","):
        name, _, qual = part.strip().partition("/")
        if qual.lower() not in ("", "k", "s"):
            raise ValueError(f"template item {part!r}: qualifier /{qual} not supported")
        items.append(Item(name, qual.lower()))
    return items


def read_args(words: Sequence[str], template: str) -> dict[str, str | bool]:
    """The values ``words`` give to ``template``'s items, keyed by keyword as the template
    spells it: a switch maps to True, any other item to its text; items not given are left
    out."""
    items = parse_template(template)
    by_key = {it.keyword.lower(): it for it in items}
    got: dict[str, str | bool] = {}
    i = 0
    while i < len(words):
        word, pos = words[i], i + 1
        key, eq, value = word.partition("=")
        item = by_key.get(key.lower())
        if item is None:
            _positional(items, got, word, pos)
        elif item.keyword in got:
            raise TriposArgsError(f"argument {pos} ({word!r}): {item.keyword} given twice")
        elif item.qualifier == "s":
            if eq:
                raise TriposArgsError(f"argument {pos} ({word!r}): {item.keyword} is a "
                                      "switch and takes no value")
            got[item.keyword] = True
        elif eq:
            got[item.keyword] = _value(item, value, pos)
        else:
            i += 1
            if i == len(words):
                raise TriposArgsError(f"argument {pos} ({word!r}): {item.keyword} needs a value")
            got[item.keyword] = _value(item, words[i], pos)
        i += 1
    return got


def _value(item: Item, value: str, pos: int) -> str:
    if value == "":
        raise TriposArgsError(f"argument {pos}: {item.keyword} needs a value")
    return value


def _positional(items: list[Item], got: dict[str, str | bool], word: str, pos: int) -> None:
    """A word that is no keyword fills the first unfilled item without /k or /s."""
    for item in items:
        if item.qualifier == "" and item.keyword not in got:
            got[item.keyword] = word
            return
    keyed = ", ".join(f"{it.keyword}/{it.qualifier}" if it.qualifier else it.keyword
                      for it in items)
    raise TriposArgsError(f"argument {pos} ({word!r}): not a keyword of {keyed}, and no "
                          "positional item is left for it")
