"""Does the fidelity ledger's test bite?  For each row listed in the tables of
``mutation_tables/`` (beside this module; one table per ledger file: ``kas.toml`` for
docs/fidelity/kas.md, ``fidelity.toml`` for docs/fidelity.md), change the constant, table
entry or branch the row is about and run the row's tests: they must fail.  The report is
docs/fidelity/mutations.md, one section per ledger.

    python -m tests.support.mutations            # run every table, write the report
    python -m tests.support.mutations kas sigma  # run these tables, rewrite their sections
    python -m tests.support.mutations --check    # the tables only: rows, files and text exist

The mutations run in a scratch copy of the repository's tracked files (never in this
checkout, so tests running beside it are undisturbed): the copy's own ``camlab88`` is the
one imported (its folder is the working directory of each pytest run).  A mutation counts as
caught when its tests fail (pytest status 1); an error (collection, a crash, a time-out) is
reported as such, not as a catch.  Before any mutation the tests must pass unmutated.
Exit status: 0 every mutation caught, 1 one or more not, 2 a table is damaged.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import tempfile
import time
import tomllib
from dataclasses import dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
TABLES = Path(__file__).with_name("mutation_tables")
REPORT = ROOT / "docs" / "fidelity" / "mutations.md"
VERSION = 2
TIMEOUT = 900  # seconds for one pytest run
_FIELDS = ("row", "file", "find", "replace", "what", "tests")


class TableError(ValueError):
    """A mutation table is damaged: the message names the table and the entry."""


def ledger_of(stem: str) -> str:
    """The ledger file a table's stem names: ``fidelity`` is docs/fidelity.md."""
    return "docs/fidelity.md" if stem == "fidelity" else f"docs/fidelity/{stem}.md"


def stems() -> list[str]:
    return sorted(p.stem for p in TABLES.glob("*.toml"))


@dataclass(frozen=True)
class Mutation:
    ledger: str       # docs/fidelity/kas.md
    row: str          # text that occurs in exactly the row's line of the ledger
    file: str         # the implementing file, repository-relative
    find: str         # text occurring exactly once in it
    replace: str      # what it becomes
    what: str         # the mutation in words
    tests: tuple[str, ...]  # pytest node ids that must fail

    def label(self) -> str:
        row = self.row if len(self.row) <= 70 else self.row[:67] + "..."
        return f"`{Path(self.ledger).name}`: {row}"


def load(stem: str, text: str | None = None, root: Path = ROOT) -> list[Mutation]:
    """Table ``stem``, checked against ``root``: each row in its ledger (once), each
    ``find`` once in its file."""
    where = str(TABLES / f"{stem}.toml")
    ledger = ledger_of(stem)
    try:
        data = tomllib.loads((TABLES / f"{stem}.toml").read_text(encoding="utf-8")
                             if text is None else text)
    except tomllib.TOMLDecodeError as exc:
        raise TableError(f"{where}: {exc}") from None
    if data.get("version") != VERSION:
        raise TableError(f"{where}: version {data.get('version')!r}, expected {VERSION}")
    ledger_lines = [ln for ln in (root / ledger).read_text(encoding="utf-8").splitlines()
                    if ln.startswith("|")]
    out = []
    for i, e in enumerate(data.get("mutation", []), 1):
        bad = [f for f in _FIELDS if f not in e] + sorted(set(e) - set(_FIELDS))
        if bad:
            raise TableError(f"{where}: mutation {i}: missing or unknown fields {bad}")
        m = Mutation(ledger, *(e[f] for f in _FIELDS[:-1]), tuple(e["tests"]))
        found = sum(m.row in ln for ln in ledger_lines)
        if found != 1:
            raise TableError(f"{where}: mutation {i}: row text found in {found} rows of "
                             f"{ledger}: {m.row!r}")
        count = (root / m.file).read_text(encoding="utf-8").count(m.find)
        if count != 1 or m.find == m.replace:
            raise TableError(f"{where}: mutation {i}: {m.find!r} occurs {count} times in "
                             f"{m.file} (must be once, and differ from its replacement)")
        out.append(m)
    return out


def load_all(root: Path = ROOT) -> dict[str, list[Mutation]]:
    return {stem: load(stem, root=root) for stem in stems()}


def _copy_tracked(dest: Path) -> None:
    files = subprocess.run(["git", "ls-files", "-z"], cwd=ROOT, capture_output=True,
                           check=True).stdout.decode().split("\0")
    for name in filter(None, files):
        src, dst = ROOT / name, dest / name
        if not src.exists() and not src.is_symlink():
            continue  # deleted in the work tree, not yet committed
        dst.parent.mkdir(parents=True, exist_ok=True)
        if src.is_symlink():
            os.symlink(os.readlink(src), dst)
        else:
            shutil.copy2(src, dst)


def _pytest(copy: Path, tests: tuple[str, ...]) -> tuple[int, str]:
    env = {**os.environ, "PYTHONPATH": str(copy), "SDL_VIDEODRIVER": "dummy"}
    cmd = [sys.executable, "-m", "pytest", "-q", "-x", "-p", "no:cacheprovider", *tests]
    try:
        r = subprocess.run(cmd, cwd=copy, env=env, capture_output=True, text=True,
                           timeout=TIMEOUT)
    except subprocess.TimeoutExpired:
        return -1, "timed out"
    failed = [ln for ln in r.stdout.splitlines() if ln.startswith(("FAILED", "ERROR"))]
    last = r.stdout.strip().splitlines()[-1:] or [""]
    return r.returncode, (failed or last)[0]


def run(mutations: list[Mutation]) -> list[tuple[Mutation, str, str]]:
    """(mutation, outcome, detail) each: outcome 'caught', 'NOT CAUGHT' or 'error'."""
    results = []
    with tempfile.TemporaryDirectory(prefix="camlab88-mutations-") as tmp:
        copy = Path(tmp)
        _copy_tracked(copy)
        everything = tuple(dict.fromkeys(t for m in mutations for t in m.tests))
        code, detail = _pytest(copy, everything)
        if code != 0:
            raise SystemExit(f"mutations: the tests fail unmutated ({detail}); fix them first")
        for m in mutations:
            path = copy / m.file
            original = path.read_text(encoding="utf-8")
            path.write_text(original.replace(m.find, m.replace), encoding="utf-8")
            try:
                code, detail = _pytest(copy, m.tests)
            finally:
                path.write_text(original, encoding="utf-8")
            outcome = {0: "NOT CAUGHT", 1: "caught"}.get(code, "error")
            print(f"{outcome:>10}  {m.label()}  ({m.what})", flush=True)
            results.append((m, outcome, detail))
    return results


_INTRO = """# Does the ledger bite? Mutations of the rows' implementations

Each row below is a row of the fidelity ledger (docs/fidelity.md, docs/fidelity/*.md) whose
implementing constant, table entry or branch was changed as described; the row's tests were
then run against the changed code and must fail. Made by `python -m tests.support.mutations`
from `tests/support/mutation_tables/` (one table per ledger; `--check` checks the tables'
rows and text still exist). One section per ledger, each with the time of its own run.
"""


def section(stem: str, results: list[tuple[Mutation, str, str]]) -> str:
    caught = sum(o == "caught" for _, o, _ in results)
    rows = [f"## {ledger_of(stem)}", "",
            f"Run {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}: {caught} of "
            f"{len(results)} mutations caught.", ""]
    if results:
        rows += ["| ledger row | file | mutation | outcome | the test that failed |",
                 "|---|---|---|---|---|"]
    for m, outcome, detail in results:
        cell = detail.removeprefix("FAILED ").split(" - ")[0] if outcome == "caught" \
            else detail
        rows.append(f"| {m.label().replace('|', '/')} | `{m.file}` | {m.what} | {outcome} | "
                    f"{cell.replace('|', '/')} |")
    return "\n".join(rows) + "\n"


def sections_of(report_text: str) -> dict[str, str]:
    """The report's sections by ledger path (the text from one ``## `` heading to the next)."""
    out: dict[str, str] = {}
    for chunk in report_text.split("\n## ")[1:]:
        out[chunk.split("\n", 1)[0].strip()] = "## " + chunk.rstrip("\n") + "\n"
    return out


def report(fresh: dict[str, str], old_text: str = "") -> str:
    """The whole report: ``fresh`` sections (ledger path -> text) over the old report's."""
    kept = sections_of(old_text)
    kept.update(fresh)
    order = [ledger_of(s) for s in stems()]
    return _INTRO + "".join("\n" + kept[k] for k in order if k in kept)


def main(argv: list[str] | None = None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    try:
        tables = load_all()
    except (TableError, OSError) as exc:
        print(f"mutations: {exc}", file=sys.stderr)
        return 2
    if "--check" in argv:
        print(f"mutations: {sum(map(len, tables.values()))} mutations in {len(tables)} "
              "tables, every row and text found")
        return 0
    chosen = [a for a in argv if not a.startswith("-")] or list(tables)
    unknown = [c for c in chosen if c not in tables]
    if unknown:
        print(f"mutations: no table {unknown[0]!r} (tables: {', '.join(tables)})",
              file=sys.stderr)
        return 2
    results = run([m for c in chosen for m in tables[c]])
    fresh = {ledger_of(c): section(c, [r for r in results if r[0].ledger == ledger_of(c)])
             for c in chosen}
    from camlab88.base.atomicfile import write_atomic

    old = REPORT.read_text(encoding="utf-8") if REPORT.exists() else ""
    write_atomic(REPORT, report(fresh, old))
    missed = [m for m, o, _ in results if o != "caught"]
    print(f"{REPORT}: {len(results) - len(missed)} of {len(results)} caught")
    return 1 if missed else 0


if __name__ == "__main__":
    raise SystemExit(main())
