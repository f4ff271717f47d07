"""In-process rewind snapshots only (F4, a seek's jump) of a program that declares no state:
an object graph captured structurally and restored *in place* into the same running
program. A graph never leaves the process - it is never written to a file or read from one,
and nothing from outside ever reaches ``restore`` (emulator.harness.program_state.snapshot
and rewind are its only callers). Save state files and recordings hold a program's declared
state instead: plain values checked against the schema it declares (base.plainstate): a
graph from a file could name code, and did.

An object graph captured structurally and restored *in place* into a freshly built graph of
the same program. Not pickle: a graph names no code. Restoring never imports a module, never
calls a constructor or any callable the graph
names; it only creates instances (``object.__new__``) of classes of camlab88's own packages
that are already loaded, fills their attributes, and writes into the objects, arrays and
closures the fresh build made (so the references wiring them together - callbacks, views,
ports - stay the fresh build's).

A load is all or nothing: every write into an object that was there before it is noted
first, and if anything fails (the tree does not fit, a hook refuses) the notes are played
back, so a refused state leaves the program exactly as it was. Objects our modules hold at
module level (a menu's item list, a table: base.shared_objects) are shared by every program
in the process: a state is never written into them, the program gets its own copy instead.

What is saved: numbers, strings, bytes, Fractions, containers, numpy arrays and scalars,
random generators (Python's and numpy's), enums and instances of our own classes (their
``__dict__`` and slots), the objects behind bound methods, and our functions as *which* one
(module, qualified name, first line) with their cells: a closure the program made while it
ran (a callback waiting for an answer) is made again from its code, found in its module.
What is *kept from the fresh build*, never read from a file: other functions, classes,
modules, paths, parsed command lines, open files and sockets, locks, threads (configuration
and the outside world).
Anything else (e.g. a generator still running) cannot be saved: StateError names where it
is, so a program's state is never silently partial.

A tree is JSON: every non-scalar node is a one-key tagged mapping; bytes and arrays larger
than ``INLINE`` go to a list of binary blobs beside it.
"""

from __future__ import annotations

import argparse
import base64
import collections
import enum
import io
import math
import random
import socket
import sys
import threading
import types
from collections.abc import Callable
from contextvars import ContextVar
from fractions import Fraction
from pathlib import PurePath
from typing import Any

import numpy as np

from camlab88.base.shared_objects import OURS, shared

INLINE = 256  # bytes: smaller ones stay in the tree (base64)
_KEEP_TYPES: tuple[type, ...] = (
    types.FunctionType, types.BuiltinFunctionType, types.ModuleType, type, PurePath,
    io.IOBase, socket.socket, type(threading.Lock()), type(threading.RLock()),
    threading.Thread, threading.Event, types.MethodWrapperType, types.WrapperDescriptorType,
    types.MethodDescriptorType, np.ufunc, argparse.Namespace)
_DICTS = {collections.Counter: "counter", collections.OrderedDict: "ordered",
          collections.defaultdict: "default"}
_DICT_TYPES = {v: k for k, v in _DICTS.items()}
_BIT_GENERATORS = {c.__name__: c for c in (np.random.PCG64, np.random.PCG64DXSM,
                                           np.random.MT19937, np.random.Philox,
                                           np.random.SFC64)}


_OWN_STATE: set[type] = set()


def own_state(cls: type) -> type:
    """Mark one of our classes as saving itself: ``save_state() -> bytes`` and
    ``load_state(bytes)`` (in place, all or nothing: it checks everything before it writes)
    stand for its attributes in a captured graph."""
    _OWN_STATE.add(cls)
    return cls


class StateError(ValueError):
    """A graph that cannot be captured, or a tree that does not fit the fresh graph."""


def _ours(cls: type) -> bool:
    return cls.__module__.startswith(OURS)


def _qual(cls: type) -> str:
    return f"{cls.__module__}:{cls.__qualname__}"


def _attrs(obj: Any) -> dict[str, Any]:
    """An instance's own attributes: its ``__dict__`` and every slot that is set (less those
    its class names in ``_state_exclude``: rebuilt after a load, never saved)."""
    refusal = _own(obj, "_state_refusal", None)  # an object that knows it cannot be saved
    if refusal:
        raise StateError(refusal)
    out = dict(_instance_dict(obj) or {})
    for name in getattr(type(obj), "_state_exclude", ()):
        out.pop(name, None)
    if not _plain(type(obj)):
        for klass in type(obj).__mro__:
            for name in getattr(klass, "__slots__", ()):
                value = _own(obj, name) if name not in ("__dict__", "__weakref__") \
                    else _MISSING
                if value is not _MISSING:
                    out[name] = value
    return out


_MISSING = object()


def _own(obj: Any, name: str, missing: Any = _MISSING) -> Any:
    """The instance's own attribute ``name`` (its __dict__'s or a slot's, not its class's),
    or ``missing``. Never through the class's ``__getattr__``: a delegating wrapper made
    from a damaged state without its delegate would call itself for ever."""
    d = _instance_dict(obj)
    if d is not None and name in d:
        return d[name]
    if not _plain(type(obj)) and any(name in getattr(k, "__slots__", ())
                                     for k in type(obj).__mro__):
        try:
            return object.__getattribute__(obj, name)
        except AttributeError:
            return missing
    return missing


def _instance_dict(obj: Any) -> dict[str, Any] | None:
    try:
        d = object.__getattribute__(obj, "__dict__")
    except AttributeError:
        return None
    return d if isinstance(d, dict) else None


_PLAIN: dict[type, bool] = {}


def _plain(cls: type) -> bool:
    """Instances of ``cls`` keep every attribute in their ``__dict__`` (no slots)."""
    if cls not in _PLAIN:
        _PLAIN[cls] = all(set(getattr(k, "__slots__", ())) <= {"__dict__", "__weakref__"}
                          for k in cls.__mro__) and cls.__dictoffset__ != 0
    return _PLAIN[cls]


# ---------------------------------------------------------------------------- capture
class _Capture:
    def __init__(self) -> None:
        self.blobs: list[bytes] = []
        self.memo: dict[int, int] = {}
        self.keep_alive: list[Any] = []  # ids stay unique while the capture runs

    def bytes_node(self, tag: str, data: bytes) -> dict[str, Any]:
        if len(data) <= INLINE:
            return {tag: base64.b64encode(data).decode("ascii")}
        self.blobs.append(bytes(data))
        return {tag + "#": len(self.blobs) - 1}

    def node(self, obj: Any, where: str) -> Any:
        if obj is None or isinstance(obj, bool | str):
            return obj
        t = type(obj)
        if t is int:
            return obj
        if t is float:
            return obj if math.isfinite(obj) else {"F": repr(obj)}
        if t is bytes:
            return self.bytes_node("B", obj)
        if t is tuple:
            return {"T": [self.node(v, f"{where}[{i}]") for i, v in enumerate(obj)]}
        if t is frozenset:
            return {"FS": [self.node(v, f"{where}{{}}") for v in obj]}
        if t is Fraction:
            return {"Q": [obj.numerator, obj.denominator]}
        if t is complex:
            return {"C": [repr(obj.real), repr(obj.imag)]}
        if isinstance(obj, np.generic):
            return {"NS": obj.dtype.str, "v": base64.b64encode(obj.tobytes()).decode()}
        if isinstance(obj, enum.Enum):
            return self._enum(obj, where)
        if (isinstance(obj, _KEEP_TYPES) and not _our_function(obj)) or _compiled(obj):
            return {"K": 0}
        key = id(obj)
        if key in self.memo:
            return {"R": self.memo[key]}
        self.memo[key] = ref = len(self.memo)
        self.keep_alive.append(obj)
        body = self._mutable(obj, where)
        body["id"] = ref
        return body

    def _enum(self, obj: enum.Enum, where: str) -> dict[str, Any]:
        if not _ours(type(obj)):
            raise StateError(f"{where}: enum {_qual(type(obj))} is not camlab88's")
        return {"E": _qual(type(obj)), "n": obj.name}

    def _mutable(self, obj: Any, where: str) -> dict[str, Any]:
        t = type(obj)
        if t is list:
            return {"L": [self.node(v, f"{where}[{i}]") for i, v in enumerate(obj)]}
        if t is dict:
            return {"D": [[self.node(k, f"{where} key"), self.node(v, f"{where}[{k!r}]")]
                          for k, v in obj.items()]}
        if t is set:
            return {"S": [self.node(v, f"{where}{{}}") for v in obj]}
        if t in _DICTS:  # Counter, OrderedDict, defaultdict (its factory: the fresh one's)
            return {"DX": _DICTS[t], "D": [[self.node(k, f"{where} key"),
                                            self.node(v, f"{where}[{k!r}]")]
                                           for k, v in obj.items()]}
        if t is bytearray:
            return self.bytes_node("BA", bytes(obj))
        if t is collections.deque:
            return {"DQ": [self.node(v, f"{where}[]") for v in obj], "max": obj.maxlen}
        if isinstance(obj, np.ndarray):
            return self._array(obj, where)
        if t is random.Random:
            return {"PR": self.node(obj.getstate(), where)}
        if t is np.random.Generator:
            bits = obj.bit_generator
            return {"NR": type(bits).__name__, "s": self.node(bits.state, where)}
        if isinstance(obj, types.FunctionType):  # one of our functions: which, and its cells
            code = obj.__code__
            return {"Fn": [self.node(c.cell_contents, f"{where}.<cell {i}>")
                           for i, c in enumerate(obj.__closure__ or ())],
                    "code": [obj.__module__, code.co_qualname, code.co_firstlineno],
                    "defaults": self.node(obj.__defaults__, f"{where}.__defaults__")}
        if isinstance(obj, types.MethodType):
            return {"M": self.node(obj.__self__, f"{where}.__self__")}
        if t in _OWN_STATE:  # it saves itself (bytes), as a device model does
            node = self.bytes_node("SB", obj.save_state())
            node["OS"] = _qual(t)
            return node
        if _ours(t) and isinstance(obj, tuple):  # a NamedTuple of ours
            return {"NT": _qual(t), "v": [self.node(v, f"{where}[{i}]")
                                          for i, v in enumerate(obj)]}
        if _ours(t):
            # a list, not a mapping: restored in the order captured (references come after
            # their object), whatever order a JSON writer puts mapping keys in
            return {"O": _qual(t), "a": [[k, self.node(v, f"{where}.{k}")]
                                         for k, v in _attrs(obj).items()]}
        if isinstance(obj, types.GeneratorType) and obj.gi_frame is None:
            return {"K": 0}  # finished: nothing left in it
        what = "a running generator" if isinstance(obj, types.GeneratorType) else t.__name__
        raise StateError(f"{where}: cannot save {what}")

    def _array(self, a: np.ndarray, where: str) -> dict[str, Any]:
        if a.dtype.hasobject:
            return {"AO": [self.node(v, f"{where}[]") for v in a.ravel().tolist()],
                    "sh": list(a.shape)}
        node = self.bytes_node("A", np.ascontiguousarray(a).tobytes())
        node.update(dt=a.dtype.str, sh=list(a.shape))
        return node


def _compiled(obj: Any) -> bool:
    """A compiled kernel (numba's dispatcher): code, not state."""
    return type(obj).__module__.startswith("numba") and callable(obj)


def _our_function(obj: Any) -> bool:
    """One of our functions: saved as which one it is (and its cells, if a closure)."""
    return isinstance(obj, types.FunctionType) and (obj.__module__ or "").startswith(OURS)


def capture(root: Any) -> tuple[Any, list[bytes]]:
    """(tree, blobs) of everything reachable from ``root``; StateError names what cannot be
    saved, with its path from the root."""
    limit = sys.getrecursionlimit()
    sys.setrecursionlimit(max(limit, 20000))
    try:
        cap = _Capture()
        return cap.node(root, "state"), cap.blobs
    finally:
        sys.setrecursionlimit(limit)


# ---------------------------------------------------------------------------- restore
# what the restore running now has written (a hook's own restores add to its journal)
_JOURNAL: ContextVar[list[tuple[Callable[..., Any], tuple[Any, ...]]] | None] = ContextVar(
    "camlab88_objstate_journal", default=None)


def _put_attr(obj: Any, name: str, value: Any) -> None:
    if value is _MISSING:
        if _own(obj, name) is not _MISSING:
            object.__delattr__(obj, name)
    else:
        object.__setattr__(obj, name, value)


def _put_dict(d: dict[str, Any], old: dict[str, Any]) -> None:
    d.clear()
    d.update(old)


def _put_items(out: Any, items: list[Any]) -> None:
    out.clear()
    dict.update(out, items)


def _put_cell(cell: types.CellType, value: Any) -> None:
    if value is _MISSING:
        del cell.cell_contents
    else:
        cell.cell_contents = value


def _put_array(out: np.ndarray, old: np.ndarray) -> None:
    out[...] = old


def _put_slice(out: Any, old: Any) -> None:
    out[:] = old


def _put_set(out: set[Any], old: set[Any]) -> None:
    out.clear()
    out.update(old)


def _put_numpy_state(out: np.random.Generator, state: Any) -> None:
    out.bit_generator.state = state


class _Restore:
    def __init__(self, blobs: list[bytes], pinned: frozenset[str],
                 journal: list[tuple[Callable[..., Any], tuple[Any, ...]]]) -> None:
        self.blobs = blobs
        self.pinned = pinned
        self.memo: dict[int, Any] = {}
        self.restored: list[Any] = []  # objects told when the whole graph is in place
        self.counterpart: dict[int, Any] = {}  # tree id -> the fresh object in its place
        self.shared = shared()  # never written into, nor stood in for (their own copies)
        self.journal = journal  # (undo, its arguments): how to put back what was written
        self.own_loads: list[tuple[Any, bytes]] = []  # objects that load themselves, and what
        self.array_writes: list[tuple[np.ndarray, np.ndarray]] = []  # (fresh, its new values)

    def finish(self, last: bool) -> None:
        """Once the whole tree fits: the objects that load themselves, then the fresh
        arrays' new values. A load_state checks all before it writes, and an array write
        cannot fail, so only what something may still fail after is saved first to be put
        back (``last``: nothing runs after this restore - no hook, no outer restore)."""
        for i, (obj, data) in enumerate(self.own_loads):
            if not (last and i == len(self.own_loads) - 1):
                self.note(obj.load_state, obj.save_state())
            obj.load_state(data)
        for fresh, a in self.array_writes:
            if not last:
                self.note(_put_array, fresh, fresh.copy())
            fresh[...] = a  # in place: views of it the fresh build holds stay views

    def note(self, undo: Callable[..., Any], *args: Any) -> None:
        self.journal.append((undo, args))

    def own(self, fresh: Any) -> Any:
        """The fresh object, or None if it is one our modules share."""
        return None if id(fresh) in self.shared else fresh

    def data(self, node: dict[str, Any], tag: str) -> bytes:
        if tag in node:
            return base64.b64decode(node[tag], validate=True)
        index = node[tag + "#"]
        if type(index) is not int or not 0 <= index < len(self.blobs):
            raise StateError(f"blob {index!r} is missing")
        return self.blobs[index]

    def pair(self, node: Any, fresh: Any) -> None:
        """First pass: for every object of the tree, the fresh object that stands where it
        stands in *any* place the fresh graph has one (an array the tree meets first where
        the fresh build has nothing is still written into the fresh array a view holds)."""
        todo = [(node, fresh)]
        while todo:
            node, fresh = todo.pop()
            if not isinstance(node, dict) or fresh is None or id(fresh) in self.shared:
                continue
            ref = node.get("R", node.get("id"))
            if ref is not None:
                if ref in self.counterpart:
                    continue
                self.counterpart[ref] = fresh
            todo.extend(_children(node, fresh))

    def value(self, node: Any, fresh: Any, where: str) -> Any:
        if isinstance(fresh, str) and fresh in self.pinned:
            return fresh  # a word of the command line (a file name): never from a state
        if node is None or isinstance(node, bool | int | float | str):
            return node
        if isinstance(node, list) or not isinstance(node, dict) or not node:
            raise StateError(f"{where}: not a state node")
        if "R" in node:
            if node["R"] not in self.memo:
                raise StateError(f"{where}: reference {node['R']!r} before its object")
            return self.memo[node["R"]]
        if "id" in node:
            return self._mutable(node, self.own(self.counterpart.get(node["id"], fresh)), where)
        return self._immutable(node, fresh, where)

    def _immutable(self, node: dict[str, Any], fresh: Any, where: str) -> Any:
        if "K" in node:
            return fresh
        if "F" in node:
            return float(node["F"])
        if "B" in node or "B#" in node:
            return self.data(node, "B")
        if "T" in node:
            return tuple(self._items(node["T"], fresh if type(fresh) is tuple else (), where))
        if "FS" in node:
            return frozenset(self.value(v, None, where) for v in node["FS"])
        if "Q" in node:
            return Fraction(int(node["Q"][0]), int(node["Q"][1]))
        if "C" in node:
            return complex(float(node["C"][0]), float(node["C"][1]))
        if "NS" in node:
            return np.frombuffer(base64.b64decode(node["v"]), dtype=np.dtype(node["NS"]))[0]
        if "E" in node:
            return _class(node["E"], where)[node["n"]]
        raise StateError(f"{where}: unknown node {sorted(node)[:3]}")

    def _items(self, nodes: list[Any], fresh: Any, where: str) -> list[Any]:
        fresh = list(fresh) if isinstance(fresh, list | tuple) else []
        return [self.value(v, fresh[i] if i < len(fresh) else None, f"{where}[{i}]")
                for i, v in enumerate(nodes)]

    def _mutable(self, node: dict[str, Any], fresh: Any, where: str) -> Any:
        ref = node["id"]
        if "L" in node:
            out = fresh if type(fresh) is list else []
            self.memo[ref] = out
            items = self._items(node["L"], out, where)
            if out is fresh:
                self.note(_put_slice, out, out[:])
            out[:] = items
            return out
        if "D" in node:
            return self._dict(node, fresh, where)
        if "S" in node:
            out = fresh if type(fresh) is set else set()
            self.memo[ref] = out
            items = {self.value(v, None, where) for v in node["S"]}
            if out is fresh:
                self.note(_put_set, out, set(out))
            out.clear()
            out.update(items)
            return out
        if "BA" in node or "BA#" in node:
            out = fresh if type(fresh) is bytearray else bytearray()
            data = self.data(node, "BA")
            if out is fresh:
                self.note(_put_slice, out, bytes(out))
            out[:] = data
            self.memo[ref] = out
            return out
        if "DQ" in node:
            out = collections.deque(maxlen=node["max"])
            self.memo[ref] = out
            out.extend(self._items(node["DQ"], fresh, where))
            return out
        if "A" in node or "A#" in node or "AO" in node:
            self.memo[ref] = out = self._array(node, fresh, where)
            return out
        return self._special(node, fresh, where)

    def _dict(self, node: dict[str, Any], fresh: Any, where: str) -> dict[Any, Any]:
        kind = _DICT_TYPES.get(str(node.get("DX")), dict)
        if type(fresh) is kind:
            out = fresh
        elif kind is collections.defaultdict:
            raise StateError(f"{where}: a defaultdict the fresh program lacks")
        else:
            out = kind()
        self.memo[node["id"]] = out
        items = []
        for k, v in node["D"]:
            key = self.value(k, None, f"{where} key")
            items.append((key, self.value(v, out.get(key), f"{where}[{key!r}]")))
        if out is fresh:
            self.note(_put_items, out, list(out.items()))
        _put_items(out, items)  # (Counter.update would count the pairs)
        return out

    def _array(self, node: dict[str, Any], fresh: Any, where: str) -> np.ndarray:
        shape = tuple(int(n) for n in node["sh"])
        if "AO" in node:
            if len(node["AO"]) != math.prod(shape) or min(shape, default=0) < 0:
                raise StateError(f"{where}: {len(node['AO'])} objects for shape {shape}")
            a = np.empty(shape, dtype=object)
            a.ravel()[:] = [self.value(v, None, where) for v in node["AO"]] or a.ravel()
            return a
        try:
            dtype = np.dtype(node["dt"])
            if dtype.hasobject:
                raise TypeError("object dtype")
            a = np.frombuffer(self.data(node, "A"), dtype=dtype).reshape(shape)
        except (TypeError, ValueError) as exc:
            raise StateError(f"{where}: array does not fit: {exc}") from None
        if (isinstance(fresh, np.ndarray) and fresh.shape == shape and fresh.dtype == dtype
                and fresh.flags.writeable):
            self.array_writes.append((fresh, a))  # written once the whole tree fits
            return fresh
        return a.copy()

    def _special(self, node: dict[str, Any], fresh: Any, where: str) -> Any:
        ref = node["id"]
        if "PR" in node:
            out = fresh if type(fresh) is random.Random else random.Random()
            self.memo[ref] = out
            state = _tuples(self.value(node["PR"], None, where))
            if out is fresh:
                self.note(out.setstate, out.getstate())
            out.setstate(state)
            return out
        if "NR" in node:
            return self._numpy_random(node, fresh, where)
        if "Fn" in node:
            return self._function(node, fresh, where)
        if "M" in node:
            if not isinstance(fresh, types.MethodType):
                raise StateError(f"{where}: a bound method the fresh program lacks")
            self.memo[ref] = fresh
            owner = self.value(node["M"], fresh.__self__, f"{where}.__self__")
            if owner is not fresh.__self__:  # it stood in a shared object: bound to the copy
                self.memo[ref] = types.MethodType(fresh.__func__, owner)
            return self.memo[ref]
        if "OS" in node:
            cls = _class(node["OS"], where)
            if cls not in _OWN_STATE or type(fresh) is not cls:
                raise StateError(f"{where}: a {node['OS']} the fresh program lacks")
            self.memo[ref] = fresh
            self.own_loads.append((fresh, self.data(node, "SB")))  # once the tree fits
            return fresh
        if "NT" in node:
            cls = _class(node["NT"], where)
            out = tuple.__new__(cls, self._items(node["v"], fresh, where))
            self.memo[ref] = out
            return out
        if "O" in node:
            return self._object(node, fresh, where)
        raise StateError(f"{where}: unknown node {sorted(node)[:3]}")

    def _numpy_random(self, node: dict[str, Any], fresh: Any, where: str) -> Any:
        bits = _BIT_GENERATORS.get(node["NR"])
        if bits is None:
            raise StateError(f"{where}: unknown bit generator {node['NR']!r}")
        out = fresh if type(fresh) is np.random.Generator and \
            type(fresh.bit_generator) is bits else np.random.Generator(bits())
        self.memo[node["id"]] = out
        if out is fresh:
            self.note(_put_numpy_state, out, out.bit_generator.state)
        try:
            out.bit_generator.state = self.value(node["s"], None, where)
        except (TypeError, ValueError, KeyError) as exc:
            raise StateError(f"{where}: random generator state: {exc}") from None
        return out

    def _function(self, node: dict[str, Any], fresh: Any, where: str) -> Any:
        code = _code(node.get("code"), where)
        made = not (isinstance(fresh, types.FunctionType) and fresh.__code__ is code)
        if made:
            fresh = _function(code, node["code"][0], len(node["Fn"]), where)
        if id(fresh) in self.shared and fresh.__closure__:
            fresh, made = _copy_function(fresh), True  # never written: shared by all programs
        cells = fresh.__closure__ or ()
        if len(cells) != len(node["Fn"]):
            raise StateError(f"{where}: a closure the fresh program lacks")
        self.memo[node["id"]] = fresh
        defaults = self.value(node.get("defaults"), fresh.__defaults__, where)
        if defaults != fresh.__defaults__:
            if id(fresh) in self.shared:
                fresh, made = _copy_function(fresh), True
                self.memo[node["id"]] = fresh
            elif not made:
                self.note(setattr, fresh, "__defaults__", fresh.__defaults__)
            fresh.__defaults__ = defaults
        for i, (cell, sub) in enumerate(zip(cells, node["Fn"], strict=True)):
            value = self.value(sub, _contents(cell), f"{where}.<cell {i}>")
            if not made:
                self.note(_put_cell, cell, _contents(cell, _MISSING))
            cell.cell_contents = value
        return fresh

    def _object(self, node: dict[str, Any], fresh: Any, where: str) -> Any:
        cls = _class(node["O"], where)
        if type(fresh) is cls:
            out = fresh
        elif cls.__new__ is object.__new__:
            out = object.__new__(cls)
        else:
            raise StateError(f"{where}: {node['O']} is not built from a state")
        self.memo[node["id"]] = out
        if hasattr(type(out), "_state_restored"):
            self.restored.append(out)
        before = _attrs(out)
        attrs = node["a"]
        if not isinstance(attrs, list) or not all(
                isinstance(a, list) and len(a) == 2 and isinstance(a[0], str) for a in attrs):
            raise StateError(f"{where}: attributes are not a list of [name, value]")
        plain = out is fresh and _plain(type(out))
        if plain:  # its attributes are its __dict__: one copy puts them all back
            self.note(_put_dict, out.__dict__, dict(out.__dict__))
        for name, sub in attrs:
            value = self.value(sub, before.get(name), f"{where}.{name}")
            if out is fresh and not plain:
                self.note(_put_attr, out, name, _own(out, name))
            try:
                object.__setattr__(out, name, value)
            except (AttributeError, TypeError) as exc:
                raise StateError(f"{where}.{name}: {exc}") from None
        return out


_CODES: dict[str, dict[tuple[str, int], types.CodeType]] = {}


def _contents(cell: types.CellType, empty: Any = None) -> Any:
    try:
        return cell.cell_contents
    except ValueError:  # an empty cell (a closure just made again)
        return empty


def _copy_function(fn: types.FunctionType) -> types.FunctionType:
    """A function of its own for one program, in place of one our modules share."""
    cells = tuple(types.CellType(c.cell_contents) if _contents(c, _MISSING) is not _MISSING
                  else types.CellType() for c in fn.__closure__ or ())
    out = types.FunctionType(fn.__code__, fn.__globals__, fn.__name__, fn.__defaults__,
                             cells or None)
    out.__kwdefaults__ = fn.__kwdefaults__
    out.__qualname__, out.__module__ = fn.__qualname__, fn.__module__
    return out


def _code(ref: Any, where: str) -> types.CodeType:
    """The code of one of our functions, found in its module (already loaded)."""
    if not (isinstance(ref, list) and len(ref) == 3 and isinstance(ref[0], str)):
        raise StateError(f"{where}: bad function reference {ref!r}")
    module, qual, line = ref
    mod = sys.modules.get(module)
    if mod is None or not module.startswith(OURS):
        raise StateError(f"{where}: function {module}:{qual} is not one of this program's")
    if module not in _CODES:
        _CODES[module] = _codes_of(mod)
    code = _CODES[module].get((qual, line))
    if code is None:
        raise StateError(f"{where}: function {module}:{qual} is not one of this program's")
    return code


def _codes_of(mod: types.ModuleType) -> dict[tuple[str, int], types.CodeType]:
    """Every code object defined in a module: its functions, methods and what they nest."""
    out: dict[tuple[str, int], types.CodeType] = {}
    todo: list[Any] = list(vars(mod).values())
    seen: set[int] = set()
    while todo:
        obj = todo.pop()
        if id(obj) in seen:
            continue
        seen.add(id(obj))
        if isinstance(obj, type) and obj.__module__ == mod.__name__:
            todo.extend(vars(obj).values())
        elif isinstance(obj, staticmethod | classmethod | property):
            todo.extend(f for f in (getattr(obj, "__func__", None), getattr(obj, "fget", None),
                                    getattr(obj, "fset", None)) if f is not None)
        elif isinstance(obj, types.FunctionType) and obj.__module__ == mod.__name__:
            todo.append(obj.__code__)
        elif isinstance(obj, types.CodeType):
            out[(obj.co_qualname, obj.co_firstlineno)] = obj
            todo.extend(c for c in obj.co_consts if isinstance(c, types.CodeType))
    return out


def _function(code: types.CodeType, module: str, n_cells: int, where: str) -> Any:
    """The function a state names: a module-level one itself; a nested one (a closure the
    program made while it ran) made again from its code, with empty cells to fill."""
    mod = sys.modules[module]
    if "<locals>" not in code.co_qualname:
        obj: Any = mod
        for part in code.co_qualname.split("."):
            obj = getattr(obj, part, None)
        if isinstance(obj, types.FunctionType) and obj.__code__ is code:
            return obj
        raise StateError(f"{where}: function {module}:{code.co_qualname} is not found")
    if len(code.co_freevars) != n_cells:
        raise StateError(f"{where}: closure {code.co_qualname} has "
                         f"{len(code.co_freevars)} cells, the state {n_cells}")
    cells = tuple(types.CellType() for _ in range(n_cells))
    return types.FunctionType(code, mod.__dict__, code.co_name, None, cells)


def _children(node: dict[str, Any], fresh: Any) -> list[tuple[Any, Any]]:
    """(child node, the fresh object in the same place) for a node and its fresh object."""
    def at(seq: Any, i: int) -> Any:
        return seq[i] if isinstance(seq, list | tuple) and i < len(seq) else None

    for tag in ("L", "T", "DQ", "NT"):
        if tag in node or (tag == "NT" and "v" in node):
            items = node.get(tag) if tag != "NT" else node.get("v")
            fresh_items = list(fresh) if isinstance(fresh, list | tuple) or \
                type(fresh) is collections.deque else []
            return [(sub, at(fresh_items, i)) for i, sub in enumerate(items or [])]
    if "D" in node and isinstance(fresh, dict):
        out = []
        for k, v in node["D"]:
            key = k if isinstance(k, str | int) else None
            out.append((v, fresh.get(key) if key is not None else None))
        return out
    if "O" in node and isinstance(node.get("a"), list):
        d = _instance_dict(fresh) if _plain(type(fresh)) else None
        return [(sub, d.get(name) if d is not None else _own(fresh, name, None))
                for name, sub in node["a"] if isinstance(name, str)]
    if "M" in node and isinstance(fresh, types.MethodType):
        return [(node["M"], fresh.__self__)]
    if "Fn" in node and isinstance(fresh, types.FunctionType) and fresh.__closure__:
        return [(sub, _contents(c)) for sub, c in zip(node["Fn"], fresh.__closure__,
                                                      strict=False)]
    return []


def _tuples(value: Any) -> Any:
    return tuple(_tuples(v) for v in value) if isinstance(value, list | tuple) else value


def _class(name: Any, where: str) -> Any:
    """One of our classes, already loaded; a state never imports anything."""
    if not isinstance(name, str) or ":" not in name:
        raise StateError(f"{where}: bad class name {name!r}")
    module, qual = name.split(":", 1)
    mod = sys.modules.get(module)
    if not module.startswith(OURS) or mod is None:
        raise StateError(f"{where}: class {name} is not one of this program's")
    obj: Any = mod
    for part in qual.split("."):
        obj = getattr(obj, part, None)
    if not isinstance(obj, type) or obj.__module__ != module:
        raise StateError(f"{where}: class {name} is not one of this program's")
    return obj


def restore(root: Any, tree: Any, blobs: list[bytes], _hooks: bool = True,
            pinned: frozenset[str] = frozenset()) -> Any:
    """Write ``tree`` into the fresh graph at ``root`` (in place where it fits); returns the
    restored root (``root`` itself when it is one of our objects). A string of the fresh
    graph that is in ``pinned`` (the command line's words: file names the program was given)
    stays as it is, whatever the state says, so a state never chooses where a program reads
    or writes. StateError when the tree does not fit, and then nothing has changed: every
    object written into has been put back as it was."""
    outer = _JOURNAL.get()
    journal = outer if outer is not None else []  # a hook's restore: the outer one undoes
    token = _JOURNAL.set(journal)
    limit = sys.getrecursionlimit()
    sys.setrecursionlimit(max(limit, 20000))
    try:
        done = _Restore(blobs, pinned, journal)
        done.pair(tree, root)
        out = done.value(tree, root, "state")
        done.finish(last=outer is None and not (_hooks and done.restored))
        for obj in done.restored if _hooks else ():  # (a hook's own restores run none)
            obj._state_restored()
        return out
    except BaseException as exc:
        if outer is None:
            for undo, args in reversed(journal):
                undo(*args)
        if isinstance(exc, StateError) or not isinstance(
                exc, KeyError | IndexError | TypeError | ValueError):
            raise
        raise StateError(f"state does not fit this program: {exc!r}") from None
    finally:
        sys.setrecursionlimit(limit)
        _JOURNAL.reset(token)
