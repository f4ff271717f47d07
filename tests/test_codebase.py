"""Checks on the code base itself: the architecture's seams, lint, and the CLI's help."""

from __future__ import annotations

import re
import shutil
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def _run(*cmd: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True, timeout=600)


def _tool(name: str) -> str:
    exe = Path(sys.executable).with_name(name)
    found = str(exe) if exe.exists() else shutil.which(name)
    assert found, f"{name} is not installed (pip install -e '.[test]')"
    return found


def test_import_contracts_hold() -> None:
    """apps/ never imports emulator/ or pygame; protocols/ imports nothing of ours; etc."""
    result = _run(_tool("lint-imports"), "--no-cache")
    assert result.returncode == 0, result.stdout + result.stderr


def test_ruff_clean() -> None:
    result = _run(_tool("ruff"), "check", ".")
    assert result.returncode == 0, result.stdout + result.stderr


def test_every_subcommand_has_help() -> None:
    from camlab88.cli import build_parser

    parser = build_parser()
    sub = next(a for a in parser._actions if a.dest == "command")
    assert "demo" in sub.choices
    for name, subparser in sub.choices.items():
        text = subparser.format_help()
        assert name in text and "usage" in text.lower()
    result = _run(sys.executable, "-m", "camlab88", "--help")
    assert result.returncode == 0 and "demo" in result.stdout


def _python_files() -> list[Path]:
    listed = _run("git", "ls-files", "*.py").stdout.split()
    return [ROOT / name for name in listed if (ROOT / name).exists()]


def test_no_type_ignore_comments_without_a_type_checker() -> None:
    """No type checker runs on this code (docs/development.md), so a ``type: ignore`` silences
    nothing and only tells the reader that something is wrong."""
    marker = "# type" + ": ignore"
    found = [f"{path.relative_to(ROOT)}:{n}" for path in _python_files()
             for n, line in enumerate(path.read_text().splitlines(), 1) if marker in line]
    assert not found, "type: ignore without a type checker:\n" + "\n".join(found)


def test_product_code_says_what_and_why_not_which_issue() -> None:
    """Comments and docstrings in the product describe the code, not the ticket it came from;
    the history is in git and docs/."""
    issue = re.compile(r"\bissue\s*#?\d", re.IGNORECASE)
    product = ("apps/", "base/", "camlab88/", "emulator/", "protocols/", "roms/")
    found = [f"{path.relative_to(ROOT)}:{n}" for path in _python_files()
             if path.relative_to(ROOT).as_posix().startswith(product)
             for n, line in enumerate(path.read_text().splitlines(), 1) if issue.search(line)]
    assert not found, "'issue N' in product code:\n" + "\n".join(found)


# Called by name from outside Python's view: dispatch tables built with getattr (the Rainbow
# executor's _op_<name>, the script's _<verb>, the session reader's _<kind>) and plugin hooks.
_CALLED_BY_NAME = re.compile(r"^(_op_\w+|pytest_\w+|dask_setup)$")
_BY_NAME_MODULES = {"protocols/rainbow/script.py", "protocols/session/parse.py"}
# In files other branches were rewriting during this clean-up; they go when those merge.
_DEAD_LEFT_FOR_LATER = {("apps/ca/engine.py", "from_corners"),
                        ("apps/ca/hashlife/kernels.py", "_sum3")}


def test_every_definition_in_the_product_is_used_somewhere() -> None:
    """A function, method or class whose name appears nowhere but in its own definition (not
    in the code, the tests, the benchmarks or the docs) is dead: delete it."""
    import ast
    from collections import Counter

    listed = _run("git", "ls-files").stdout.split()
    words: Counter[str] = Counter()
    for name in listed:
        path = ROOT / name
        if path.suffix in (".py", ".md", ".toml") and path.exists():
            words.update(re.findall(r"[A-Za-z_]\w*", path.read_text(errors="ignore")))
    product = ("apps/", "base/", "camlab88/", "emulator/", "protocols/", "roms/")
    dead = []
    for path in _python_files():
        rel = path.relative_to(ROOT).as_posix()
        if not rel.startswith(product):
            continue
        for node in ast.walk(ast.parse(path.read_text())):
            if not isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
                continue
            name = node.name
            if (words[name] > 1 or name.startswith("__") or _CALLED_BY_NAME.match(name)
                    or rel in _BY_NAME_MODULES or (rel, name) in _DEAD_LEFT_FOR_LATER):
                continue
            dead.append(f"{rel}:{node.lineno}: {name}")
    assert not dead, "defined and used nowhere:\n" + "\n".join(dead)


def test_no_two_test_modules_share_a_name() -> None:
    """A test module is found by its name: ``test_cli.py`` in five folders was five places
    to look (name them after their package: tests/kas/test_kas_cli.py)."""
    from collections import Counter

    names = Counter(p.name for p in (ROOT / "tests").rglob("test_*.py"))
    assert [n for n, k in names.items() if k > 1] == []


def test_the_index_of_tests_is_current() -> None:
    """tests/INDEX.md maps each module to its tests; regenerate it with
    ``python -m tests.support.index_of_tests --write``."""
    from tests.support.index_of_tests import INDEX, index

    assert INDEX.read_text(encoding="utf-8") == index(), (
        "tests/INDEX.md is stale: python -m tests.support.index_of_tests --write")
