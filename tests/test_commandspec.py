"""The parsers built from the areas' commands.toml (camlab88/commandspec.py): typed defaults
written as text arrive typed, and --help loads neither the action's code (its handler is
imported when it runs) nor numpy."""

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
    assert handler.where == "camlab88.commands.ca.run:_run"  # the entry's handler = "_run"


def test_help_loads_neither_the_actions_code_nor_numpy() -> None:
    code = ("import sys\nfrom camlab88.cli import build_parser\n"
            "build_parser(['ca', 'run', '--help']).format_help()\n"
            "print(sorted({'camlab88.commands.ca.run', 'numpy'} & set(sys.modules)))")
    out = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True,
                         text=True, check=True).stdout
    assert out.strip() == "[]", out


def _spec_copy(toml: Path) -> Path:
    return toml.parent / "__pycache__" / f"{toml.name}.{sys.implementation.cache_tag}.marshal"


def test_the_parsed_spec_is_kept_and_a_damaged_or_stale_copy_is_parsed_again(
        tmp_path: Path, monkeypatch) -> None:
    from camlab88.commandspec import read_spec

    monkeypatch.setattr(sys, "dont_write_bytecode", False)
    toml = tmp_path / "commands.toml"
    toml.write_text('help = "first"\n[run]\nargs = [{flags = "--x", type = "int"}]\n')
    first = read_spec(toml)
    assert first == {"help": "first", "run": {"args": [{"flags": "--x", "type": "int"}]}}
    copy = _spec_copy(toml)
    assert copy.is_file()
    assert read_spec(toml) == first  # from the copy
    toml.write_text('help = "second"\n')  # edited: the copy no longer holds these bytes
    assert read_spec(toml) == {"help": "second"}
    copy.write_bytes(b"\x00damaged")
    assert read_spec(toml) == {"help": "second"}
    assert read_spec(toml) == {"help": "second"}  # rewritten, and read back


def test_a_copy_is_never_taken_for_other_bytes(tmp_path: Path, monkeypatch) -> None:
    # a copy written for one file's text, put beside another's, is not believed
    import marshal

    from camlab88.commandspec import read_spec

    monkeypatch.setattr(sys, "dont_write_bytecode", False)
    toml = tmp_path / "commands.toml"
    toml.write_text('help = "real"\n')
    _spec_copy(toml).parent.mkdir()
    _spec_copy(toml).write_bytes(marshal.dumps((b'help = "other"\n', {"help": "forged"})))
    assert read_spec(toml) == {"help": "real"}


def test_no_copy_is_written_when_python_is_told_to_write_nothing(tmp_path: Path,
                                                                 monkeypatch) -> None:
    from camlab88.commandspec import read_spec

    monkeypatch.setattr(sys, "dont_write_bytecode", True)
    toml = tmp_path / "commands.toml"
    toml.write_text('help = "x"\n')
    assert read_spec(toml) == {"help": "x"}
    assert not _spec_copy(toml).parent.exists()


def test_a_line_naming_an_action_builds_that_actions_parser_only() -> None:
    from camlab88.cli import build_parser

    def actions(words: list[str]) -> list[str]:
        area = build_parser(words)._subparsers._group_actions[0].choices["ca"]
        return list(area._subparsers._group_actions[0].choices)

    assert actions(["ca", "run", "--rules", "life"]) == ["run"]
    everything = actions(["ca", "rn"])  # a misspelt action: all, for "did you mean"
    assert "run" in everything and "convert" in everything
    assert actions(["ca", "--help"]) == everything
