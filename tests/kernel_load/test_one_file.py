"""numba's cache checks a cached kernel against its own source file only: a kernel that calls
a kernel, or reads a constant, of another of our modules would keep running the old code
after an edit there (a warm cache once ran an old HashLife recursion: a double free).  So
every function in a module that compiles kernels uses nothing of ours from another module:
kernels that call each other live in one file (docs/development.md, "Kernels")."""

from __future__ import annotations

import ast
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
PRODUCT = ("apps", "emulator", "protocols", "base", "roms")
ALLOWED = {"announce_compiles"}  # called from Python at import, not from a kernel


def _kernel_modules() -> list[Path]:
    return [p for top in PRODUCT for p in sorted((ROOT / top).rglob("*.py"))
            if "njit" in p.read_text()]


def _ours_imported(tree: ast.Module) -> set[str]:
    names = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom) and (node.module or "").startswith("camlab88"):
            names |= {a.asname or a.name for a in node.names}
        elif isinstance(node, ast.Import):
            names |= {(a.asname or a.name).split(".")[0] for a in node.names
                      if a.name.startswith("camlab88")}
    return names - ALLOWED


def _compiled(tree: ast.Module) -> list[ast.FunctionDef]:
    """The module's functions that numba compiles: decorated with njit, or handed to it."""
    handed = {n.args[0].id for n in ast.walk(tree) if isinstance(n, ast.Call)
              and isinstance(n.func, ast.Call) and "njit" in ast.unparse(n.func.func)
              and n.args and isinstance(n.args[0], ast.Name)}
    return [f for f in ast.walk(tree) if isinstance(f, ast.FunctionDef)
            and (f.name in handed or any("njit" in ast.unparse(d) for d in f.decorator_list))]


def test_kernels_use_nothing_of_ours_from_another_module() -> None:
    modules = _kernel_modules()
    assert len(modules) >= 10
    wrong = []
    for path in modules:
        tree = ast.parse(path.read_text())
        ours = _ours_imported(tree)
        for fn in _compiled(tree):
            used = {n.id for n in ast.walk(fn) if isinstance(n, ast.Name)} & ours
            if used:
                wrong.append(f"{path.relative_to(ROOT)}:{fn.lineno} {fn.name} uses {sorted(used)}")
    assert not wrong, "\n".join(wrong)


def test_hashlife_templates_are_in_the_kernels_file() -> None:
    """The recursion's template is compiled by ``_one_kind``, not by a decorator: it too
    uses only the file's own names (checked here, as the test above cannot see it)."""
    path = ROOT / "apps" / "ca" / "hashlife" / "kernels.py"
    tree = ast.parse(path.read_text())
    assert not _ours_imported(tree)
