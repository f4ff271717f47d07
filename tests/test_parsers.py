"""The parsers each action module declares beside its handler: typed defaults arrive typed,
a command's --help loads no other action's code and no numpy, and a line naming an action
builds that action's parser only."""

from __future__ import annotations

import subprocess
import sys
from fractions import Fraction
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def _parse(words: list[str]):
    from camlab88.cli import build_parser

    return build_parser(words).parse_args(words)


def test_defaults_written_as_text_arrive_as_the_type_gives_them() -> None:
    # the handlers compare these values (snooker render refuses --size but for 768x512)
    assert _parse(["snooker", "render", "m.cp", "v.txt", "--frames", "d"]).size == (768, 512)
    assert _parse(["ca", "film", "life", "glider", "--generations", "2",
                   "--out", "f.mp4"]).size == (768, 512)
    run = _parse(["sigma", "run"])
    assert (run.order_timeout, run.idle_timeout) == (Fraction(10), Fraction(60))
    assert _parse(["demo"]).out == Path("camlab88-demo")


def test_an_actions_handler_is_its_modules_function() -> None:
    handler = _parse(["ca", "run", "--rules", "life", "--pattern", "glider",
                      "--generations", "1"]).handler
    from camlab88.commands.ca import run

    assert handler is run.run


def test_help_loads_no_other_actions_code_nor_numpy() -> None:
    code = ("import sys\nfrom camlab88.cli import build_parser\n"
            "build_parser(['ca', 'run', '--help']).format_help()\n"
            "print(sorted({'camlab88.commands.ca.convert', 'camlab88.commands.ca.film',\n"
            "              'camlab88.commands.kas', 'numpy'} & set(sys.modules)))")
    out = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True,
                         text=True, check=True).stdout
    assert out.strip() == "[]", out


def test_a_line_naming_an_action_builds_that_actions_parser_only() -> None:
    from camlab88.cli import build_parser

    def actions(words: list[str]) -> list[str]:
        area = build_parser(words)._subparsers._group_actions[0].choices["ca"]
        return list(area._subparsers._group_actions[0].choices)

    assert actions(["ca", "run", "--rules", "life"]) == ["run"]
    everything = actions(["ca", "rn"])  # a misspelt action: all, for "did you mean"
    assert "run" in everything and "convert" in everything
    assert actions(["ca", "--help"]) == everything
