"""``camlab88 ca library``: the shipped rule sets and patterns."""

from __future__ import annotations

import argparse

HELP = "list the shipped rule sets and patterns"



def run(args: argparse.Namespace) -> int:
    from camlab88.apps.ca import library

    for kind, items in library.names().items():
        print(f"{kind}: {' '.join(items)}")
    return 0
