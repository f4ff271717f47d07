"""The ledger of the thesis's claims (docs/fidelity.md), regenerated from the tests.

A test that reproduces a quantitative or checkable claim of the thesis is marked::

    @pytest.mark.claim("§3.1.4: text of the claim", measured="what camlab88 measures",
                       verdict="agrees")          # or "differs: why"

Claims shown by a benchmark, or whose program is not built yet, are listed in ``OTHERS``.
``python -m tests.support.claims`` collects the marked tests (``pytest --collect-only`` of
the test files that use the marker, with this module as a plugin), merges ``OTHERS`` and
rewrites the table between the ledger markers of docs/fidelity.md; ``--check`` only says
whether the table is up to date (exit 1 if not).
"""

from __future__ import annotations

import re
import sys
from dataclasses import dataclass
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
DOC = ROOT / "docs" / "fidelity.md"
BEGIN, END = "<!-- claims ledger: begin (python -m tests.support.claims) -->", \
    "<!-- claims ledger: end -->"


@dataclass(frozen=True)
class Claim:
    section: str
    text: str
    measured: str
    evidence: str
    verdict: str


def _split(label: str) -> tuple[str, str]:
    section, sep, text = label.partition(": ")
    if not sep or not section.strip():
        raise ValueError(f"claim label must be 'SECTION: text', not {label!r}")
    return section.strip(), text.strip()


def claim_of(item: pytest.Item) -> Claim | None:
    """The claim a collected test reproduces (None if it is not marked)."""
    mark = item.get_closest_marker("claim")
    if mark is None:
        return None
    if len(mark.args) != 1:
        raise ValueError(f"{item.nodeid}: claim takes one label, 'SECTION: text'")
    section, text = _split(mark.args[0])
    measured = mark.kwargs.get("measured", "")
    verdict = mark.kwargs.get("verdict", "agrees")
    node = item.nodeid.split("[")[0]
    return Claim(section, text, measured, f"`{node}`", verdict)


class _Collector:
    """pytest plugin: records the claims of the collected tests."""

    def __init__(self) -> None:
        self.claims: list[Claim] = []

    def pytest_collection_modifyitems(self, items: list[pytest.Item]) -> None:
        seen = set()
        for item in items:
            c = claim_of(item)
            if c is not None and c not in seen:  # parametrised tests count once
                seen.add(c)
                self.claims.append(c)


# Claims no pytest test reproduces: shown by a benchmark, or their program is not built yet.
OTHERS = [
    Claim("§3.1.4", "the real-time viewer cannot show a sequence of average complexity in "
          "real time over the 9600-baud line", "frames shown / dropped for the demo sequence "
          "at 9600, 19200 and 38400 baud", "`tests/kas_front/test_viewer.py::"
          "test_realtime_counts_equal_the_schedule`", "agrees (9600 baud drops frames; "
          "faster lines show more)"),
    Claim("§6.1", "the snooker display plays at 12 frames a second", "the playback rate "
          "of `snooker replay` (frame_rate of the session)", "`apps/snooker` session "
          "default frame rate (docs/fidelity/snooker.md)", "agrees (not yet marked in a test)"),
    Claim("§5", "the three-dimensional visualiser draws 12/3 frames a second",
          "—", "—", "not yet built (no visualiser)"),
    Claim("§5", "the anti-aliased renderer's output frames", "—", "—",
          "not yet built (no renderer)"),
    Claim("§4", "the painting program", "—", "—", "not yet built (no painting program)"),
]


def _section_key(c: Claim) -> tuple:
    nums = re.findall(r"\d+", c.section)
    appendix = c.section.lower().startswith("app")
    return (appendix, [int(n) for n in nums], c.text)


def table(claims: list[Claim]) -> str:
    rows = ["| § | claim | camlab88 measures | evidence | verdict |", "|---|---|---|---|---|"]
    for c in sorted(claims, key=_section_key):
        cells = [c.section, c.text, c.measured or "—", c.evidence, c.verdict]
        rows.append("| " + " | ".join(x.replace("|", "\\|") for x in cells) + " |")
    return "\n".join(rows) + "\n"


def marked_files() -> list[str]:
    """Test files that use the claim marker (collecting only these keeps it quick)."""
    return sorted(str(p.relative_to(ROOT)) for p in (ROOT / "tests").rglob("test_*.py")
                  if "mark.claim(" in p.read_text(encoding="utf-8"))


def collect() -> list[Claim]:
    plugin = _Collector()
    code = pytest.main(["--collect-only", "-q", "-p", "no:cacheprovider",
                        *marked_files()], plugins=[plugin])
    if code not in (0, 5):
        raise SystemExit(f"collecting the marked tests failed (pytest exit {code})")
    return plugin.claims + OTHERS


def updated(doc: str, body: str) -> str:
    if BEGIN not in doc or END not in doc:
        return doc.rstrip("\n") + f"\n\n{BEGIN}\n{body}{END}\n"
    head, rest = doc.split(BEGIN, 1)
    return f"{head}{BEGIN}\n{body}{END}{rest.split(END, 1)[1]}"


def main(argv: list[str] | None = None) -> int:
    from protocols.atomicfile import write_atomic

    argv = sys.argv[1:] if argv is None else argv
    doc = DOC.read_text(encoding="utf-8")
    claims = collect()
    new = updated(doc, table(claims))
    if "--check" in argv:
        print("ledger up to date" if new == doc else f"{DOC} ledger is out of date")
        return 0 if new == doc else 1
    if new != doc:
        write_atomic(DOC, new.encode("utf-8"))
    print(f"{DOC}: ledger of {len(claims)} claims written")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
