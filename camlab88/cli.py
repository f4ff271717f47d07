"""The one console script: ``camlab88 <subcommand> ...``.

Each area registers its own subcommands from ``camlab88.commands.<area>`` so that the
areas stay independent; a module here only parses arguments and wires a program to a
device, and imports heavy packages inside its handlers so ``--help`` stays fast.
"""

from __future__ import annotations

import argparse
import importlib
import sys
from collections.abc import Sequence

from camlab88 import __version__

# Order is the order shown in --help.
COMMAND_MODULES: tuple[str, ...] = (
    "demo",
    "sigma",
    "rainbow",
    "tablet",
    "link",
    "kas",
    "snooker",
    "ca",
)


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="camlab88",
        description="Working models of the Sigma T5684/T5688 terminals and the Cambridge "
        "Rainbow workstation, and the 1987 animation programs that ran on them.",
    )
    parser.add_argument("--version", action="version", version=f"camlab88 {__version__}")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")
    sub.required = True
    for module in _command_modules():
        module.register(sub)
    return parser


def _command_modules() -> list:
    return [importlib.import_module(f"camlab88.commands.{name}") for name in COMMAND_MODULES]


def normalise_argv(argv: Sequence[str]) -> list[str]:
    """Let an area rewrite its own command line first (e.g. ``camlab88 snooker SESSION``
    means ``camlab88 snooker play SESSION``)."""
    out = list(argv)
    for module in _command_modules():
        hook = getattr(module, "normalise_argv", None)
        if hook is not None:
            out = hook(out)
    return out


def main(argv: Sequence[str] | None = None) -> int:
    parser = build_parser()
    args = parser.parse_args(normalise_argv(sys.argv[1:] if argv is None else argv))
    try:
        result = args.handler(args)
    except KeyboardInterrupt:
        return 130
    except BrokenPipeError:
        return 0
    return int(result or 0)


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
