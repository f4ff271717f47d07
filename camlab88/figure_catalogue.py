"""The thesis's screen figures as data: number, section, caption, what our recording shows
and where it differs from the thesis, and why.

One place (``figure_catalogue.toml`` beside this module) read by ``camlab88 figures``, by the
web gallery and by ``examples/figures/make_figures.py --docs``, which writes docs/figures.md's
table from it (tests/test_figures.py checks the two agree).
"""

from __future__ import annotations

import tomllib
from dataclasses import dataclass
from functools import cache
from pathlib import Path

CATALOGUE = Path(__file__).with_name("figure_catalogue.toml")
VERSION = 1
VERDICTS = ("agrees", "differs", "cannot judge")
_FIELDS = ("number", "section", "caption", "short", "verdict", "shows", "differs")


class CatalogueError(ValueError):
    """The catalogue file is damaged: the message names the file and the entry."""


@dataclass(frozen=True)
class Figure:
    number: str    # "7.2"; Appendix I's figures are "I.1", "I.2"
    section: str   # where the thesis shows it: "7.2", "Appendix I"
    caption: str   # the thesis's caption, whole
    short: str     # the caption shortened for a one-line listing
    verdict: str   # one of VERDICTS
    shows: str     # what our recording shows
    differs: str   # where and why it differs from the thesis ("" when it agrees)

    @property
    def section_label(self) -> str:
        return self.section if self.section.startswith("Appendix") else f"§{self.section}"


def parse(text: str, where: str = str(CATALOGUE)) -> tuple[Figure, ...]:
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise CatalogueError(f"{where}: {exc}") from None
    if data.get("version") != VERSION:
        raise CatalogueError(f"{where}: version {data.get('version')!r}, expected {VERSION}")
    figures = []
    for i, entry in enumerate(data.get("figure", []), 1):
        missing = [f for f in _FIELDS if not isinstance(entry.get(f), str)]
        extra = sorted(set(entry) - set(_FIELDS))
        if missing or extra:
            raise CatalogueError(f"{where}: figure entry {i}: missing or not text: {missing}, "
                                 f"unknown: {extra}")
        fig = Figure(**{f: entry[f] for f in _FIELDS})
        if fig.verdict not in VERDICTS:
            raise CatalogueError(f"{where}: figure {fig.number}: verdict {fig.verdict!r} is not "
                                 f"one of {VERDICTS}")
        if (fig.verdict == "agrees") != (fig.differs == ""):
            raise CatalogueError(f"{where}: figure {fig.number}: say what differs exactly when "
                                 "the verdict is not 'agrees'")
        figures.append(fig)
    numbers = [f.number for f in figures]
    if len(set(numbers)) != len(numbers):
        raise CatalogueError(f"{where}: a figure number is listed twice")
    return tuple(figures)


@cache
def figures() -> tuple[Figure, ...]:
    """Every screen figure, in the thesis's order."""
    return parse(CATALOGUE.read_text(encoding="utf-8"))


def by_number() -> dict[str, Figure]:
    return {f.number: f for f in figures()}


def markdown_table() -> str:
    """docs/figures.md's table (make_figures.py --docs writes it there)."""
    rows = ["| fig. | § | the thesis's caption | ours | verdict: what differs, and why | "
            "what the recording shows | replay |",
            "|---|---|---|---|---|---|---|"]
    for f in figures():
        verdict = f.verdict if not f.differs else f"**{f.verdict}**: {f.differs}"
        rows.append(f"| {f.number} | {f.section_label} | {f.caption} | "
                    f"![](images/figures/fig-{f.number}.png) | {verdict} | {f.shows} | "
                    f"`camlab88 figures {f.number}` |")
    return "\n".join(rows) + "\n"
