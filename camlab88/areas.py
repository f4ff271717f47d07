"""How a command area registers its actions: one module per action, named in a tuple.

``camlab88/commands/<area>/__init__.py`` lists ``ACTIONS = ("play", "simulate", ...)`` and
holds the area's ``HELP`` and ``DESCRIPTION``; each action module
``camlab88/commands/<area>/<action>.py`` declares its parser (``add_parser``) beside its
handler. Adding an action is one new module and one name in the tuple; action modules never
import each other (import-linter checks it).
"""

from __future__ import annotations

import argparse
import importlib
import sys
from collections.abc import Callable, Sequence


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
        importlib.import_module(f"{package}.{action}").add_parser(sub)
    parser.set_defaults(handler=lambda args: _no_action(parser))
    return parser


def delegated_action(actions: argparse._SubParsersAction, name: str, help: str,
                     add_arguments: Callable[[argparse.ArgumentParser], None],
                     handler: Callable[[argparse.Namespace], int]) -> argparse.ArgumentParser:
    """The parser of an action whose options are declared beside the code that does its
    work (``link echo``, ``link stream``: protocols.link.cli_args): ``help``, the options
    ``add_arguments`` adds, and its ``handler``."""
    p = actions.add_parser(name, help=help)
    add_arguments(p)
    p.set_defaults(handler=handler)
    return p


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
