"""How a command area registers its actions: one module per action, named in a tuple.

``camlab88/commands/<area>/__init__.py`` lists ``ACTIONS = ("play", "simulate", ...)``; each
``camlab88/commands/<area>/<action>.py`` defines ``register(actions)``, which adds its parser
to the area's subparsers and sets ``handler``.  Adding an action is one new module and one
name in the tuple; action modules never import each other (import-linter checks it).
"""

from __future__ import annotations

import argparse
import importlib
from collections.abc import Sequence


def register_area(subparsers: argparse._SubParsersAction, package: str, name: str,
                  help: str, actions: Sequence[str],
                  description: str | None = None) -> argparse.ArgumentParser:
    """Add area ``name`` with its ``actions`` (modules of ``package``) to ``subparsers``."""
    parser = subparsers.add_parser(name, help=help, description=description or help)
    sub = parser.add_subparsers(dest=f"{name}_action", metavar="ACTION")
    for action in actions:
        importlib.import_module(f"{package}.{action}").register(sub)
    parser.set_defaults(handler=lambda args: _no_action(parser))
    return parser


def _no_action(parser: argparse.ArgumentParser) -> int:
    """An area named without an action prints its help (exit 2: nothing was done)."""
    parser.print_help()
    return 2
