"""Does the fidelity ledger's test bite?  For each row listed in ``mutations.toml`` (beside
this module), change the constant, table entry or branch the row is about and run the row's
tests: they must fail.  The report is docs/fidelity/mutations.md.

    python -m tests.support.mutations            # run every mutation, write the report
    python -m tests.support.mutations --check    # the table only: rows, files and text exist

The mutations run in a scratch copy of the repository's tracked files (never in this
checkout, so tests running beside it are undisturbed): the copy's own ``camlab88`` is the
one imported (its folder is the working directory of each pytest run).  A mutation counts as
caught when its tests fail (pytest status 1); an error (collection, a crash, a time-out) is
reported as such, not as a catch.  Before any mutation the tests must pass unmutated.
Exit status: 0 every mutation caught, 1 one or more not, 2 the table is damaged.
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
TABLE = Path(__file__).with_name("mutations.toml")
REPORT = ROOT / "docs" / "fidelity" / "mutations.md"
VERSION = 1
TIMEOUT = 900  # seconds for one pytest run
_FIELDS = ("ledger", "row", "file", "find", "replace", "what", "tests")


class TableError(ValueError):
    """mutations.toml is damaged: the message names the entry."""


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


def load(text: str | None = None, root: Path = ROOT) -> list[Mutation]:
    """The table, checked against ``root``: each row in its ledger (once), each ``find`` once
    in its file."""
    where = str(TABLE)
    try:
        data = tomllib.loads(TABLE.read_text(encoding="utf-8") if text is None else text)
    except tomllib.TOMLDecodeError as exc:
        raise TableError(f"{where}: {exc}") from None
    if data.get("version") != VERSION:
        raise TableError(f"{where}: version {data.get('version')!r}, expected {VERSION}")
    out = []
    for i, e in enumerate(data.get("mutation", []), 1):
        bad = [f for f in _FIELDS if f not in e] + sorted(set(e) - set(_FIELDS))
        if bad:
            raise TableError(f"{where}: mutation {i}: missing or unknown fields {bad}")
        m = Mutation(*(e[f] for f in _FIELDS[:-1]), tuple(e["tests"]))
        lines = [ln for ln in (root / m.ledger).read_text(encoding="utf-8").splitlines()
                 if m.row in ln and ln.startswith("|")]
        if len(lines) != 1:
            raise TableError(f"{where}: mutation {i}: row text found in {len(lines)} rows of "
                             f"{m.ledger}: {m.row!r}")
        count = (root / m.file).read_text(encoding="utf-8").count(m.find)
        if count != 1 or m.find == m.replace:
            raise TableError(f"{where}: mutation {i}: {m.find!r} occurs {count} times in "
                             f"{m.file} (must be once, and differ from its replacement)")
        out.append(m)
    return out


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


def report(results: list[tuple[Mutation, str, str]]) -> str:
    caught = sum(o == "caught" for _, o, _ in results)
    rows = ["# Does the ledger bite? Mutations of the rows' implementations", "",
            "Each row below is a row of the fidelity ledger (docs/fidelity.md, "
            "docs/fidelity/*.md) whose",
            "implementing constant, table entry or branch was changed as described; the "
            "row's tests were",
            "then run against the changed code and must fail. Made by `python -m "
            "tests.support.mutations`",
            "from `tests/support/mutations.toml` (`--check` checks the table's rows and text "
            "still exist).", "",
            f"Run {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}: {caught} of "
            f"{len(results)} mutations caught.", "",
            "| ledger row | file | mutation | outcome | the test that failed |",
            "|---|---|---|---|---|"]
    for m, outcome, detail in results:
        cell = detail.removeprefix("FAILED ").split(" - ")[0] if outcome == "caught" \
            else detail
        rows.append(f"| {m.label().replace('|', '/')} | `{m.file}` | {m.what} | {outcome} | "
                    f"{cell.replace('|', '/')} |")
    return "\n".join(rows) + "\n"


def main(argv: list[str] | None = None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    try:
        mutations = load()
    except (TableError, OSError) as exc:
        print(f"mutations: {exc}", file=sys.stderr)
        return 2
    if "--check" in argv:
        print(f"mutations: {len(mutations)} mutations, every row and text found")
        return 0
    results = run(mutations)
    from camlab88.base.atomicfile import write_atomic

    write_atomic(REPORT, report(results))
    missed = [m for m, o, _ in results if o != "caught"]
    print(f"{REPORT}: {len(results) - len(missed)} of {len(results)} caught")
    return 1 if missed else 0


if __name__ == "__main__":
    raise SystemExit(main())
