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
    """pytest plugin: records the claims of the collected tests, and every node id."""

    def __init__(self) -> None:
        self.claims: list[Claim] = []
        self.nodes: set[str] = set()

    def pytest_collection_modifyitems(self, items: list[pytest.Item]) -> None:
        seen = set()
        for item in items:
            self.nodes.add(item.nodeid.split("[")[0])
            c = claim_of(item)
            if c is not None and c not in seen:  # parametrised tests count once
                seen.add(c)
                self.claims.append(c)


# Claims reproduced by tests in other helpers' files (cited by node id; the script checks that
# each still exists), by a benchmark, or whose program is not built yet.
def _t(node: str) -> str:
    return f"`{node}`"


OTHERS = [
    Claim("§3.1.3", "superimposing a 50-frame bird that starts after 20 frames of a 40-frame "
          "flower gives 70 frames: bird still for 20, flower still for the last 30",
          "the composite's frames, part by part",
          _t("tests/kas/test_superimpose.py::test_bird_and_flower_example"), "agrees"),
    Claim("§3.1.4", "abbreviated graphics mode needs approximately half the characters of "
          "the standard mode", "vectors: 0.34-0.54 of the standard characters (0.45 for "
          "the KAS demo); whole streams with text and orders 0.56-0.94",
          "`benchmarks/bench_sigma.py`, `benchmarks/bench_kas_front.py` (docs/perf/sigma.md, "
          "docs/perf/kas_front.md); the demo's ratio: "
          + _t("tests/kas_front/test_abbreviated_saving.py::"
               "test_demo_vectors_take_about_half_the_characters_abbreviated"),
          "agrees for the vectors the mode abbreviates"),
    Claim("§3.1.4", "over the 9600-baud line a sequence of average complexity cannot be "
          "shown in real time", "frames shown and dropped for the demo sequence at 9600, "
          "19200 and 38400 baud: about 1 in 5 of its 28 frames at 9600, more on faster lines",
          _t("tests/kas_front/test_viewer.py::test_realtime_counts_equal_the_schedule"),
          "agrees"),
    Claim("§3.1.4", "frames double-buffered in two 2-bit buffers of the T5684's 4 planes, "
          "so only four colours, and no part-drawn frame is ever seen", "every 1/25 s "
          "period of line time mid-swap shows all of one frame",
          _t("tests/kas_front/test_viewer.py::"
             "test_double_buffer_never_shows_a_half_drawn_frame"), "agrees"),
    Claim("§6.2.2", "the checkpoint: 22 initial positions, then per frame the balls that "
          "moved with their deltas, a negative ball number ends it; 4096 units to the foot; "
          "positions packed 16 + 16 bits", "the thesis's example read; breaks round-trip "
          "exactly; every stored position in 0..65535 (potted balls parked in range)",
          _t("tests/snooker/test_checkpoint.py::test_thesis_example_reads") + ", "
          + _t("tests/snooker/test_checkpoint.py::test_simulated_break_round_trips_exactly"),
          "agrees (the example's elided lines 3-21 are filled in: docs/fidelity/snooker.md)"),
    Claim("§6.3.2", "the visualiser averaged 12 frames a second redrawing the balls, 3 when "
          "the table had to be redrawn too", "the visualiser on the emulated Rainbow, one "
          "scan-out a frame: static view 112 / 115 frames/s (min / median), moving view "
          "79 / 95, at load average 5 on 2 shared cores (docs/perf/camera.md)",
          "`benchmarks/bench_camera.py`", "differs: ten to thirty times faster, since the "
          "Rainbow's 1987 drawing speed is not emulated; as in the thesis the moving view, "
          "which redraws the table, is the slower"),
    Claim("§7.2", "figure 7.6, Life in the rule language, runs as printed",
          "the figure's text, comments and all, parses to the messages and interpretations "
          "the thesis explains; the library's life.rules is that text and runs Life",
          _t("tests/ca/test_ca_rules.py::test_figure_7_6_life_as_printed") + ", "
          + _t("tests/ca/test_ca_rules.py::test_library_life_is_figure_7_6"), "agrees"),
    Claim("§7.4.1", "figure 7.8, the maze runner's rules, run as printed",
          "the figure's text parses to the messages and interpretations the thesis "
          "explains and is the library's maze.rules, which solves mazes (next row)",
          _t("tests/ca/test_ca_rules.py::test_figure_7_8_maze_as_printed"), "agrees"),
    Claim("§7.4.1", "(the project's own, not the thesis's: 'shortest' does not occur in it) "
          "the maze runner reaches a maze's exit first by the shortest path",
          "the generation the runner reaches the exit = the shortest path's length (BFS)",
          _t("tests/ca/test_library.py::"
             "test_maze_runner_solves_the_demo_maze_by_the_shortest_path"),
          "ours: follows from the thesis's splitting runners (next row), measured on the "
          "demo maze"),
    Claim("§7.3.2", "zoom 16 shows 47 x 36 cells of the 752 x 576 area (16 pixels reserved "
          "for panning)", "the viewport's cells across at zoom 16",
          _t("tests/ca_program/test_view.py::test_start_view_and_cell_mapping"), "agrees"),
    Claim("§7.3.2", "at one pixel a cell only 0.04 % of the playing surface is visible; at "
          "1024 cells a pixel about 40 %", "752 x 576 / 65536² = 0.0101 % and 10.3 %",
          _t("tests/ca_program/test_view.py::test_subpixel_cells_per_pixel_is_a_square_area"),
          "differs: the thesis's figures are those of a 32768-cell-square surface (0.040 %, "
          "41.3 %), not of the 65536-cell one it describes (docs/fidelity/ca.md)"),
    Claim("App. I", "the red polygon anti-aliased in a 5-bit pad over 3-bit splodges, "
          "concatenated into a 256-entry table, moves in real time and stays correctly "
          "blended with no recomputation", "every pixel equal to the table's blend at five "
          "positions; pad memory unchanged; only moves sent",
          _t("tests/rainbow/test_appendix_i.py::"
             "test_polygon_blends_over_splodges_while_both_move"), "agrees"),
    Claim("§6.2.2", "the animator can replay all the frames produced, or a sub-range, in real "
          "time at 25 frames a second", "a replay of frames 0-19 reports 20 frames at 25 "
          "frames/s: 40 display frames of the 50 Hz Rainbow, 0.80 s",
          _t("tests/snooker_program/test_snooker_program_commands.py::test_replay_plays_a_checkpoint_at_25_fps"),
          "agrees"),
    Claim("§3.3", "a useful measure of automatic painting is the operator time per frame",
          "ten operations given on the middle frame paint all 100 frames of the walk (0.1 "
          "operations a frame); planning, Sigma orders, the 9600-baud line and the emulated "
          "T5688's fills: 2.07 s wall for the sequence at load average ~10 (docs/perf/paint.md)",
          "`benchmarks/bench_paint.py`", "not comparable: the thesis gives no operator time, and "
          "its own finding was less positive (automatic colouring used for only parts of the "
          "image, the rest finished by hand frame by frame, §3.3); our walk was drawn with "
          "whole-line-chain boundaries in mind, and following regions is ours"),
    Claim("§6.4.1", "the renderer's frames on the Sigma T5688 over the serial line",
          "175-306 s of line time a frame at 9600 baud (period 167-192 KB, software Bresenham "
          "258-293 KB); 20-33 leaking pixels a frame in period mode, 0 in the two cures",
          "`benchmarks/bench_render.py` (docs/perf/render.md); one frame's leaks: "
          + _t("tests/snooker_render/test_sigma.py::test_period_leaks_and_fixed_does_not"),
          "agrees"),
]


def cited_nodes() -> list[str]:
    """The test node ids OTHERS cites."""
    return sorted({m for c in OTHERS for m in re.findall(r"`(tests/[^`]+::[^`]+)`",
                                                          c.evidence)})


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
    """The marked tests' claims plus OTHERS; fails if a cited test no longer exists."""
    plugin = _Collector()
    files = sorted(set(marked_files()) | {n.split("::")[0] for n in cited_nodes()})
    # camlab88 is imported already (this module uses it), so pytest cannot rewrite its plugin
    code = pytest.main(["--collect-only", "-q", "-p", "no:cacheprovider",
                        "-W", "ignore::pytest.PytestAssertRewriteWarning", *files],
                       plugins=[plugin])
    if code not in (0, 5):
        raise SystemExit(f"collecting the marked tests failed (pytest exit {code})")
    missing = [n for n in cited_nodes() if n not in plugin.nodes]
    if missing:
        raise SystemExit("the ledger cites tests that do not exist: " + ", ".join(missing))
    return plugin.claims + OTHERS


def updated(doc: str, body: str) -> str:
    if BEGIN not in doc or END not in doc:
        return doc.rstrip("\n") + f"\n\n{BEGIN}\n{body}{END}\n"
    head, rest = doc.split(BEGIN, 1)
    return f"{head}{BEGIN}\n{body}{END}{rest.split(END, 1)[1]}"


def main(argv: list[str] | None = None) -> int:
    from camlab88.base.atomicfile import write_atomic

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
