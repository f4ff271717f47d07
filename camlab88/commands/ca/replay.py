"""``camlab88 ca replay``: a Log replayed as a Script up to a generation."""

from __future__ import annotations

import argparse
import sys

DESCRIPTION = """\
Start from the latest checkpoint (log name + generation) at or before GENERATION, apply the \
script's interventions and rules up to GENERATION, and print the statistics."""


HELP = "replay a Log as a Script up to a generation"


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("--script", required=True, help="log file written by a ca session")
    p.add_argument("--generation", type=int, required=True)
    p.add_argument("--edges", choices=["wrap", "bounded"],
                   help="only for logs that do not record their edges (default wrap)")
    p.add_argument("--seed", type=int,
                   help="only for logs that do not record their seed (default 0)")
    p.add_argument("--json", action="store_true")


def run(args: argparse.Namespace) -> int:
    from camlab88.apps.ca.engine import Engine
    from camlab88.apps.ca.log import (
        LogError,
        check_seed,
        read_log_settings,
        resolve_settings,
        start_from_script,
    )
    from camlab88.apps.ca.rules import RuleError

    try:
        edges, seed, warnings = resolve_settings(read_log_settings(args.script), args.edges,
                                                 args.seed)
        check_seed(seed)
        for w in warnings:
            print(f"camlab88 ca replay: warning: {w}", file=sys.stderr)
        engine = start_from_script(args.script, args.generation,
                                   lambda: Engine(edges=edges, seed=seed))
    except (OSError, LogError, RuleError, ValueError, RuntimeError) as exc:
        print(f"camlab88 ca replay: {exc}", file=sys.stderr)
        return 2
    _print_stats(engine.stats(), args.json)
    return 0


def _print_stats(stats: dict, as_json: bool) -> None:
    from camlab88.apps.ca.stats_text import stats_text

    print(stats_text(stats, as_json))
