"""How a command area registers its actions: one module per action, named in a tuple.

``camlab88/commands/<area>/__init__.py`` lists ``ACTIONS = ("play", "simulate", ...)``; each
action's parser is its entry in ``camlab88/commands/<area>/commands.toml`` (built by
camlab88.commandspec), and ``camlab88/commands/<area>/<action>.py`` holds its handler.  Adding
an action is one new module, one entry and one name in the tuple; action modules never import
each other (import-linter checks it).
"""

from __future__ import annotations

import argparse
from collections.abc import Sequence

from camlab88.commandspec import add_command, area_spec


def register_area(subparsers: argparse._SubParsersAction, package: str,
                  actions: Sequence[str]) -> argparse.ArgumentParser:
    """Add the area of `package` (``camlab88.commands.ca`` -> ``ca``), its help and
    description from the top of its commands.toml, with its `actions`."""
    name = package.rsplit(".", 1)[1]
    spec = area_spec(name)
    parser = subparsers.add_parser(name, help=spec["help"],
                                   description=spec.get("description", spec["help"]))
    sub = parser.add_subparsers(dest=f"{name}_action", metavar="ACTION")
    for action in _needed(subparsers, name, actions):
        add_command(sub, f"{package}.{action}")
    parser.set_defaults(handler=lambda args: _no_action(parser))
    return parser


def _needed(subparsers: argparse._SubParsersAction, name: str,
            actions: Sequence[str]) -> Sequence[str]:
    """The actions whose parsers a command line needs: only its own when it names one of
    the area's actions (``ca run`` builds no parser for ``ca convert``, whose options
    import modules of their own: ~10 ms of every short run), else all (the area's help, a
    misspelt action's "did you mean"). ``words``: the line, set by camlab88.cli."""
    words = getattr(subparsers, "words", ())
    if len(words) > 1 and words[0] == name:
        spec = area_spec(name)
        chosen = [a for a in actions if spec[a].get("name", a) == words[1]]
        if chosen:
            return chosen
    return actions


def _no_action(parser: argparse.ArgumentParser) -> int:
    """An area named without an action prints its help (exit 2: nothing was done)."""
    parser.print_help()
    return 2
