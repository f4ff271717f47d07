"""What a session recording may make ``camlab88 replay`` run: a recording is data.

A recording names a command line, and recordings are shared, so the command line is checked
before anything runs: only the programs ``--record`` exists on, only the options each of them
declares with a replay class (exact spellings, no abbreviations), each value then checked by
the program's own argument parser. Each option's class is set where the option is declared,
beside its handler (``p.add_argument(...).replay = KEEP``; the shared run options in
camlab88.runopts, control_flags, stateopts ...). What each class means:

``KEEP``     replayed as recorded (numbers bounded: a recording cannot ask for a huge window)
``SCRATCH``  an output the recorded run wrote (--screenshot, --frames, --out, --save ...):
             redirected into the replay's scratch directory, which is deleted afterwards, so
             the program behaves as recorded but writes nothing of the user's
``DROP``     a recorder (--record, --record-line, --record-stream): the replay does not repeat
             it; a command whose ``--record`` is DROP is a program a replay runs
``OUTSIDE``  the line's outside end (sigma run --pty / --listen / --serial): never opened;
             the outside bytes stored in the recording (``+`` wire records) are fed instead
``KEEP`` also covers ``--load-state FILE``: the state a recorded run began from is an input
file, carried in the recording by content and loaded again from the replay's scratch copy
(a recording whose state file is not in it cannot be replayed: the file is missing).
``TAPE``     ``--tablet SOURCE``: kept so the program sets up the same decoder, but in a replay
             the device is never opened -- the tablet tape stored in the recording (``T`` wire
             records) is decoded instead (emulator/tablet_input/taped.py); the value is only parsed

Anything else is refused naming the option: listeners, ports, URLs, ``--dask``
(a replay renders in process), options of other programs, and programs without ``--record``.
"""

from __future__ import annotations

import argparse
import contextlib
import io
from pathlib import PurePosixPath

KEEP, SCRATCH, DROP, OUTSIDE, TAPE = "keep", "scratch", "drop", "outside", "tape"
MAX_NUMBER = 10**9  # any numeric value kept (ticks, seconds, baud, frames ...)
MAX_SCALE = 8       # --scale: a window 8 times 768x576 is already 85 MB of pixels
MAX_WORDS, MAX_WORD = 256, 4096

# why the options people are most likely to meet are refused (any other: "not replayed")
_WHY = {
    "--dask": "a replay renders in process, never on a Dask cluster",
    "--workers": "a replay renders in process",
    "--listen": "a replay opens no listener", "--port": "a replay opens no listener",
    "--pty": "a replay opens no pseudo-terminal", "--serial": "a replay opens no port",
    "--url": "a replay connects nowhere", "--tablet": "a replay reads no device",
}


class ReplayRefused(ValueError):
    """A recorded command line a replay will not run; the message names the reason."""


def checked_argv(argv: list[str]) -> list[str]:
    """The command line a replay runs for the recorded ``argv``: checked against the
    allowlist and the program's own parser, outputs moved into the scratch directory,
    recorders and outside ends dropped. Raises ReplayRefused."""
    from camlab88 import cli

    if len(argv) > MAX_WORDS or any(len(w) > MAX_WORD or "\0" in w for w in argv):
        raise ReplayRefused(f"the command line is longer than {MAX_WORDS} words of at most "
                            f"{MAX_WORD} characters")
    words = cli.normalise_argv(argv)
    key = _command_words(words[:2])  # an area that is one command (demo) is one word
    sub = cli.command_parser(cli.build_parser(words), key)
    table = None if sub is None else program_options(sub)
    if table is None:
        raise ReplayRefused(f"'{' '.join(words[:2])}' is not a program a replay runs "
                            f"(only: {', '.join(' '.join(k) for k in programs())})")
    out = list(key) + _options(words[len(key):], table, sub, " ".join(key))
    _parse(cli, out)
    return out


def program_options(sub: argparse.ArgumentParser) -> dict[str, str] | None:
    """What a replay does with each option of the command ``sub`` parses (its declared
    classes), or None when the command is not a program a replay runs (no session
    ``--record``)."""
    record = sub._option_string_actions.get("--record")
    if getattr(record, "replay", None) != DROP:
        return None
    return {flag: action.replay for action in sub._actions if hasattr(action, "replay")
            for flag in action.option_strings}


def programs() -> dict[tuple[str, ...], dict[str, str]]:
    """Every program a replay runs, with program_options (builds every parser)."""
    from camlab88 import cli

    out: dict[tuple[str, ...], dict[str, str]] = {}
    for area, area_parser in _choices(cli.build_parser()).items():
        actions = _choices(area_parser) or {"": area_parser}  # demo: the area is the command
        for action, sub in actions.items():
            table = program_options(sub)
            if table is not None:
                out[(area, action) if action else (area,)] = table
    return out


def _command_words(words: list[str]) -> tuple[str, ...]:
    """The words of ``words`` that name the command: an area and its action, or an area
    that is one command (``demo``) alone."""
    from camlab88 import cli

    area = cli.command_parser(cli.build_parser(words), words[:1])
    return tuple(words[:2]) if _choices(area) else tuple(words[:1])


def _choices(parser: argparse.ArgumentParser) -> dict[str, argparse.ArgumentParser]:
    return next((a.choices for a in parser._actions
                 if isinstance(a, argparse._SubParsersAction)), {})


def _options(words: list[str], table: dict[str, str], sub: argparse.ArgumentParser,
             program: str) -> list[str]:
    out: list[str] = []
    i = 0
    while i < len(words):
        word = words[i]
        i += 1
        if not word.startswith("-") or word == "-":
            out.append(word)  # a positional: the program's parser checks it
            continue
        name, eq, value = word.partition("=")
        kind = table.get(name)
        action = sub._option_string_actions.get(name)
        if kind is None or action is None:
            why = _WHY.get(name, f"not an option a replay of '{program}' accepts")
            raise ReplayRefused(f"option {name}: {why}")
        if action.nargs != 0 and not eq:
            if i >= len(words):
                raise ReplayRefused(f"option {name}: its value is missing")
            value, i = words[i], i + 1
        elif action.nargs == 0 and eq:
            raise ReplayRefused(f"option {name}: takes no value")
        out += _apply(kind, name, value if action.nargs != 0 else None, len(out))
    return out


def _apply(kind: str, name: str, value: str | None, n: int) -> list[str]:
    if kind in (DROP, OUTSIDE):
        return []
    if kind == TAPE:  # never opened in a replay: the recorded tape is decoded instead
        return [name, str(value)]
    if kind == SCRATCH:  # keep only the file's own name, under a directory of its own
        leaf = PurePosixPath(str(value).replace("\\", "/")).name
        return [name, f"_out/{n}/{leaf if leaf not in ('', '.', '..') else 'out'}"]
    if value is None:
        return [name]
    _bounded(name, value)
    return [name, value]


def _bounded(name: str, value: str) -> None:
    try:
        number = float(value)
    except ValueError:
        return
    limit = MAX_SCALE if name == "--scale" else MAX_NUMBER
    if not abs(number) <= limit:  # also NaN
        raise ReplayRefused(f"option {name} {value}: outside -{limit}..{limit}")


def _parse(cli, argv: list[str]) -> argparse.Namespace:
    """The program's own parser on the command line the replay will run."""
    said = io.StringIO()
    try:
        with contextlib.redirect_stderr(said), contextlib.redirect_stdout(said):
            args = cli.build_parser(argv).parse_args(argv)
    except SystemExit:
        last = (said.getvalue().strip().splitlines() or ["does not parse"])[-1]
        raise ReplayRefused(f"the program's parser refuses it: {last}") from None
    return args
