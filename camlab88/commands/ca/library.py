"""``camlab88 ca library``: the shipped rule sets and patterns."""

from __future__ import annotations

import argparse


def add_parser(actions: argparse._SubParsersAction) -> argparse.ArgumentParser:
    p = actions.add_parser("library", help="list the shipped rule sets and patterns")
    p.set_defaults(handler=_library)
    return p


def _library(args: argparse.Namespace) -> int:
    from camlab88.apps.ca import library

    for kind, items in library.names().items():
        print(f"{kind}: {' '.join(items)}")
    return 0
