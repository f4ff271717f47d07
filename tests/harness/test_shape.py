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


def test_every_command_module_has_the_one_shape() -> None:
    """Every command module, an area's action or a single command, has the shape
    camlab88.areas describes: its one-line ``HELP``, its options beside its handler, and
    ``run``, which the one binding (areas.add_command) makes the parser's handler."""
    import argparse

    from camlab88.areas import add_command
    from camlab88.cli import COMMAND_MODULES

    for area in COMMAND_MODULES:
        pkg = importlib.import_module(f"camlab88.commands.{area}")
        assert Path(pkg.__file__).name == "__init__.py", area
        actions = getattr(pkg, "ACTIONS", ())
        modules = [importlib.import_module(f"camlab88.commands.{area}.{a}") for a in actions]
        for module in modules or [pkg]:
            assert not hasattr(module, "add_parser"), module.__name__
            assert isinstance(module.HELP, str) and "\n" not in module.HELP, module.__name__
            parser = add_command(argparse.ArgumentParser().add_subparsers(), "x", module)
            assert parser.get_default("handler") is module.run, module.__name__
