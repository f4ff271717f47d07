"""The objects camlab88's modules hold at module level (menus' item lists, tables, functions):
shared by every program in the process, so a saved state must never be written into them.

``shared()`` is every mutable object (and function) reachable from the namespaces of our
loaded modules and their classes, through containers and our own instances. The walk costs
about as much as a whole state load, so it is kept and walked again only when the modules or
their namespaces change size (an import, a global added); the walk holds what it found, so
an id in it is never another object's.
"""

from __future__ import annotations

import collections
import sys
import types
from typing import Any

import numpy as np

OURS = ("apps.", "emulator.", "protocols.", "base.", "roms.", "camlab88.")
_MUTABLE = (list, dict, set, bytearray, collections.deque, np.ndarray, types.FunctionType)
_NOT_INSTANCES = (type, types.ModuleType, types.FunctionType, types.MethodType)

_cache: dict[str, Any] = {"key": None, "ids": frozenset(), "held": [], "n": -1, "mods": []}


def _ours(obj: Any) -> bool:
    return type(obj).__module__.startswith(OURS) and not isinstance(obj, _NOT_INSTANCES)


def _modules() -> list[types.ModuleType]:
    if len(sys.modules) != _cache["n"]:  # (modules are rarely removed, often added)
        _cache["n"] = len(sys.modules)
        _cache["mods"] = [m for name, m in list(sys.modules.items())
                          if name.startswith(OURS) and isinstance(m, types.ModuleType)]
    return _cache["mods"]


def shared() -> frozenset[int]:
    """Ids of the objects our modules hold (see the module's docstring)."""
    mods = _modules()
    key = (len(mods), sum(len(vars(m)) for m in mods))
    if key != _cache["key"]:
        held = _walk(mods)
        _cache.update(key=key, ids=frozenset(id(o) for o in held), held=held)
    return _cache["ids"]


def _walk(mods: list[types.ModuleType]) -> list[Any]:
    held: list[Any] = []
    seen: set[int] = set()
    todo: list[Any] = [vars(m) for m in mods]
    while todo:
        obj = todo.pop()
        if id(obj) in seen:
            continue
        seen.add(id(obj))
        if isinstance(obj, types.ModuleType | type(None) | bool | int | float | str | bytes):
            continue
        if isinstance(obj, _MUTABLE) or _ours(obj):
            held.append(obj)
        if isinstance(obj, dict):
            todo.extend(obj.values())
        elif isinstance(obj, list | tuple | set | frozenset | collections.deque):
            todo.extend(obj)
        elif isinstance(obj, type):
            if obj.__module__.startswith(OURS):
                todo.extend(vars(obj).values())
        elif isinstance(obj, staticmethod | classmethod):
            todo.append(obj.__func__)
        elif _ours(obj):
            todo.extend(getattr(obj, "__dict__", {}).values())
            for klass in type(obj).__mro__:
                for name in getattr(klass, "__slots__", ()):
                    if name not in ("__dict__", "__weakref__") and hasattr(obj, name):
                        todo.append(getattr(obj, name))
    return held
