"""How a command is declared and bound: one module per command, in one shape.

A command module (``camlab88/commands/<area>/<action>.py``, or a single command's package
``camlab88/commands/<name>/__init__.py``) holds its one-line ``HELP``, an optional
``DESCRIPTION`` and ``EPILOG``, ``add_arguments(p)`` declaring its options on an argparse
parser (absent when it takes none) and ``run(args) -> int``, its handler: the shape of
Django's management commands, so every command reads the same and is bound in one place
(``add_command``). An area (``camlab88/commands/<area>/__init__.py``) lists
``ACTIONS = ("play", "simulate", ...)`` with the area's ``HELP`` and ``DESCRIPTION``. Adding
an action is one new module and one name in the tuple; action modules never import each
other (import-linter checks it).
"""

from __future__ import annotations

import argparse
import importlib
import sys
from collections.abc import Sequence
from types import ModuleType


def add_command(subparsers: argparse._SubParsersAction, name: str,
                module: ModuleType) -> argparse.ArgumentParser:
    """The parser of the command `module` declares, named `name`, bound to its ``run``."""
    p = subparsers.add_parser(name, help=module.HELP,
                              description=getattr(module, "DESCRIPTION", None),
                              epilog=getattr(module, "EPILOG", None))
    add_arguments = getattr(module, "add_arguments", None)
    if add_arguments is not None:
        add_arguments(p)
    p.set_defaults(handler=module.run)
    return p


def register_command(subparsers: argparse._SubParsersAction, package: str,
                     name: str | None = None) -> argparse.ArgumentParser:
    """Add the single command `package` declares (``camlab88.commands.demo`` -> ``demo``;
    `name` where the command's name is not the package's)."""
    return add_command(subparsers, name or package.rsplit(".", 1)[1], sys.modules[package])


def register_area(subparsers: argparse._SubParsersAction, package: str,
                  actions: Sequence[str]) -> argparse.ArgumentParser:
    """Add the area of `package` (``camlab88.commands.ca`` -> ``ca``), its help and
    description, with its `actions`."""
    name = package.rsplit(".", 1)[1]
    area = sys.modules[package]
    parser = subparsers.add_parser(name, help=area.HELP,
                                   description=getattr(area, "DESCRIPTION", area.HELP))
    sub = parser.add_subparsers(dest=f"{name}_action", metavar="ACTION")
    for action in _needed(subparsers, name, actions):
        add_command(sub, action.replace("_", "-"),
                    importlib.import_module(f"{package}.{action}"))
    parser.set_defaults(handler=lambda args: _no_action(parser))
    return parser


def _needed(subparsers: argparse._SubParsersAction, name: str,
            actions: Sequence[str]) -> Sequence[str]:
    """The actions whose parsers a command line needs: only its own when it names one of
    the area's actions (``ca run`` imports no other action's module), else all (the area's
    help, a misspelt action's "did you mean"), and none when the line names no area (the
    top-level help reads the areas' own lines only). An action's command is its module's
    name with ``-`` for ``_`` (``edit_script`` is ``kas edit-script``). ``words``: the
    line, set by camlab88.cli; none: every parser (the replay allowlist's list)."""
    words = getattr(subparsers, "words", ())
    if words and words[0] != name:
        return ()
    if len(words) > 1:
        chosen = [a for a in actions if a.replace("_", "-") == words[1]]
        if chosen:
            return chosen
    return actions


def _no_action(parser: argparse.ArgumentParser) -> int:
    """An area named without an action prints its help (exit 2: nothing was done)."""
    parser.print_help()
    return 2
