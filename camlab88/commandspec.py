"""Every command's parser built from data: what a user reads lives once, as prose.

Each area keeps ``camlab88/commands/<area>/commands.toml``: the area's own ``help`` and
``description`` (camlab88.areas), then a table per action module (an area that is one
command, ``demo``, ``replay`` ..., a table named after itself) with ``help``,
``description``, ``epilog``, ``keys`` (the window's key legend), ``name`` (when the command's
name is not the module's), ``defaults`` (more ``set_defaults``) and an ordered
``[[<action>.args]]`` list. An argument is ``name`` (a positional) or ``flags`` (``"--x"`` or
``["-x", "--x"]``) with argparse's own keywords: ``type`` names a function (the action
module's own, else one of ``TYPES``), a string ``choices`` names a sequence (the action
module's, or "module:NAME"); ``exclusive = "G"`` puts it in mutually exclusive group G. An
entry ``use = "<group>"`` adds a group of options: one the area's commands share, listed
once under ``[[shared.<group>]]`` in its file; one of every area's (``GROUPS``); or a
"module:function" helper, its other keys passed to the helper. ``{NAME}`` in prose is a
field of the entry (``{KEYS}``), one of the sentences several commands share
(``SNIPPETS``), or a constant of the action module (a sequence: joined with ", ").
docs/development.md shows an entry.
"""

from __future__ import annotations

import argparse
import importlib
import marshal
import re
import sys
from collections.abc import Callable
from functools import cache
from pathlib import Path
from typing import Any

COMMANDS = Path(__file__).resolve().parent / "commands"

# the shared option groups: name -> "module:function(parser, **keys)"
GROUPS = {
    "run": "camlab88.runopts:add_run_options",
    "events": "camlab88.scriptopts:add_events_option",
    "tablet": "camlab88.rainbow_tablet:add_tablet_option",
    "trace": "camlab88.traceopts:add_trace_options",
    "controls": "camlab88.control_flags:add_control_options",
    "states": "camlab88.stateopts:add_state_options",
}

# argparse types more than one command uses: name -> "module:function"
TYPES = {
    "int": "builtins:int",
    "float": "builtins:float",
    "path": "pathlib:Path",
    "positive": "camlab88.runopts:positive",
    "frames_dir": "camlab88.runopts:frames_dir",
    "seconds": "camlab88.stateopts:seconds",
    "frame_size": "camlab88.argtypes:frame_size",
    "film_path": "camlab88.argtypes:film_path",
    "mp4_file": "camlab88.argtypes:mp4_file",
    "gif_file": "camlab88.argtypes:gif_file",
    "dask_address": "camlab88.argtypes:dask_address",
}

# sentences several commands' prose shares: {NAME} -> "module:constant"
SNIPPETS = {
    "HEADLESS_NEEDS_EVENTS": "camlab88.scriptopts:HEADLESS_NEEDS_EVENTS",
    # the link tools' lines, shared with `python -m camlab88.protocols.link`
    "LINK_ECHO_HELP": "camlab88.protocols.link.cli_args:ECHO_HELP",
    "LINK_STREAM_HELP": "camlab88.protocols.link.cli_args:STREAM_HELP",
}

_PROSE = ("help", "description", "epilog")


@cache
def area_spec(area: str) -> dict[str, Any]:
    """The area's commands.toml (read once a process)."""
    return read_spec(COMMANDS / area / "commands.toml")


def read_spec(path: Path) -> dict[str, Any]:
    """A commands.toml, parsed; the parse is kept beside it (``__pycache__``, as marshal
    data holding the very bytes it was parsed from, so an edited file is parsed again and a
    damaged copy is ignored and rewritten). Importing tomllib and parsing the ca area's file
    cost ~12 ms of every ``ca run``; loading the copy ~0.1 ms."""
    source = path.read_bytes()
    copy = path.parent / "__pycache__" / f"{path.name}.{sys.implementation.cache_tag}.marshal"
    try:
        kept = marshal.loads(copy.read_bytes())
        if type(kept) is tuple and len(kept) == 2 and kept[0] == source:
            return kept[1]
    except (OSError, EOFError, ValueError, TypeError):  # none yet, or damaged: parse
        pass
    import tomllib

    spec = tomllib.loads(source.decode("utf-8"))
    if not sys.dont_write_bytecode:  # the user asked Python to write nothing beside its code
        _keep(copy, source, spec)
    return spec


def _keep(copy: Path, source: bytes, spec: dict[str, Any]) -> None:
    """Write the parse's copy atomically (the .pyc files' trust: marshal data beside the
    code); a read-only install, or a value marshal cannot hold, keeps none."""
    from camlab88.base.atomicfile import write_atomic

    try:
        data = marshal.dumps((source, spec))
        copy.parent.mkdir(exist_ok=True)
        write_atomic(copy, data)
    except (OSError, ValueError):
        pass


def _where(module: str) -> tuple[str, str]:
    """(area, action) of a command module: ``camlab88.commands.ca.run`` -> ("ca", "run");
    an area that is one command (``camlab88.commands.demo``) -> ("demo", "demo")."""
    parts = module.split(".")[2:]
    return parts[0], parts[-1]


def keys_of(module: str) -> str:
    """The window's key legend of a command module (its ``keys``)."""
    area, action = _where(module)
    return area_spec(area)[action]["keys"]


def add_command(actions: argparse._SubParsersAction, module: str,
                handler: Callable[[argparse.Namespace], int] | None = None,
                ) -> argparse.ArgumentParser:
    """The parser of command `module` from its entry, added to `actions`; it runs `handler`,
    by default the entry's ``handler``, a function of `module` imported only when the command
    runs (``ca run --help`` reads no other action's code)."""
    area, action = _where(module)
    spec = area_spec(area)[action]
    texts = {k: _fill(spec[k], module, spec) for k in _PROSE if k in spec}
    p = actions.add_parser(spec.get("name", action), **texts)
    exclusive: dict[str, Any] = {}
    shared = area_spec(area).get("shared", {})
    for arg in spec.get("args", ()):
        _add(p, dict(arg), module, exclusive, shared)
    p.set_defaults(**spec.get("defaults", {}),
                   handler=handler or Handler(f"{module}:{spec['handler']}"))
    return p


class Handler:
    """A command's handler named "module:function", imported when the command runs."""

    def __init__(self, where: str) -> None:
        self.where = where

    def __call__(self, args: argparse.Namespace) -> int:
        return _resolve(self.where)(args)


def _add(p: argparse.ArgumentParser, arg: dict[str, Any], module: str,
         exclusive: dict[str, Any], shared: dict[str, list[dict[str, Any]]]) -> None:
    if "use" in arg:
        use = arg.pop("use")
        if use in shared:  # the area's own group, written once in its [shared] table
            for each in shared[use]:
                _add(p, dict(each), module, exclusive, shared)
        else:
            _resolve(GROUPS.get(use, use))(p, **arg)
        return
    group, required = arg.pop("exclusive", None), arg.pop("exclusive_required", False)
    target = p
    if group is not None:
        if group not in exclusive:  # made where its first member stands, as argparse lists it
            exclusive[group] = p.add_mutually_exclusive_group(required=required)
        target = exclusive[group]
    flags = arg.pop("flags", None) or arg.pop("name")
    names = [flags] if isinstance(flags, str) else flags
    if "type" in arg:
        arg["type"] = _resolve(TYPES.get(arg["type"]) or f"{module}:{arg['type']}")
    if isinstance(arg.get("choices"), str):
        name = arg["choices"]
        arg["choices"] = _resolve(name if ":" in name else f"{module}:{name}")
    if isinstance(arg.get("metavar"), list):  # one name per value of an nargs=N option
        arg["metavar"] = tuple(arg["metavar"])
    if "help" in arg:
        arg["help"] = _fill(arg["help"], module)
    target.add_argument(*names, **arg)


def _resolve(where: str) -> Any:
    module, name = where.split(":")
    return getattr(importlib.import_module(module), name)


def _fill(text: str, module: str, spec: dict[str, Any] | None = None) -> str:
    """{NAME}: the entry's own field (``{KEYS}``: its ``keys``), a shared sentence, else a
    constant of the action module."""
    if "{" not in text:
        return text
    return re.sub(r"\{([A-Z_]+)\}", lambda m: _constant(m[1], module, spec or {}), text)


def _constant(name: str, module: str, spec: dict[str, Any]) -> str:
    own = spec.get(name.lower())
    value = own if isinstance(own, str) else _resolve(SNIPPETS.get(name) or f"{module}:{name}")
    return value if isinstance(value, str) else ", ".join(map(str, value))
