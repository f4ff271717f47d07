"""The command layer stays thin: no function in camlab88/ longer than about 40 lines, and
every area is a package whose actions are one module each (docs/harness.md)."""

from __future__ import annotations

import ast
import importlib
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2] / "camlab88"
LIMIT = 40


def test_no_function_in_camlab88_is_longer_than_40_lines() -> None:
    long = []
    for path in sorted(ROOT.rglob("*.py")):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef):
                n = node.end_lineno - node.lineno + 1
                if n > LIMIT:
                    long.append(f"{path.relative_to(ROOT.parent)}:{node.lineno} "
                                f"{node.name}: {n} lines")
    assert not long, "split these (a command only parses and wires):\n" + "\n".join(long)


def test_every_area_lists_its_actions_one_module_each() -> None:
    """Each action is a module declaring its parser (``add_parser``) beside the handler it
    runs; an area that is one command registers itself."""
    import argparse

    from camlab88.cli import COMMAND_MODULES

    for area in COMMAND_MODULES:
        pkg = importlib.import_module(f"camlab88.commands.{area}")
        assert Path(pkg.__file__).name == "__init__.py", area
        actions = getattr(pkg, "ACTIONS", ())
        if not actions:
            assert callable(pkg.register), area
        for action in actions:
            module = importlib.import_module(f"camlab88.commands.{area}.{action}")
            parser = module.add_parser(argparse.ArgumentParser().add_subparsers())
            handler = parser.get_default("handler")
            assert handler.__module__ == module.__name__, (area, action, handler)
