"""A real X server for a test (Xvfb on a display number it picks itself), and what the X
server says about its top-level windows (geometry, read with libX11 through ctypes:
the library SDL itself draws with there, so no other package is needed)."""

from __future__ import annotations

import contextlib
import ctypes
import ctypes.util
import os
import shutil
import subprocess
from collections.abc import Callable, Iterator
from dataclasses import dataclass

import pytest


@contextlib.contextmanager
def xvfb(width: int, height: int) -> Iterator[str]:
    """Xvfb with one screen of ``width`` x ``height``; yields its DISPLAY (":N"). Skips the
    test, saying why, where Xvfb is not installed."""
    if shutil.which("Xvfb") is None:
        pytest.skip("Xvfb is not installed (apt-get install xvfb; bash .ci/run does)")
    read, write = os.pipe()
    server = subprocess.Popen(["Xvfb", "-displayfd", str(write), "-nolisten", "tcp",
                               "-screen", "0", f"{width}x{height}x24"],
                              pass_fds=(write,), stdout=subprocess.DEVNULL,
                              stderr=subprocess.DEVNULL)
    os.close(write)
    try:
        with os.fdopen(read) as fd:
            number = fd.readline().strip()  # written once the server accepts clients
        if not number:
            pytest.fail("Xvfb started but named no display")
        yield f":{number}"
    finally:
        server.terminate()
        server.wait(timeout=30)


@dataclass(frozen=True)
class XWindow:
    x: int
    y: int
    width: int
    height: int
    mapped: bool


class _Attributes(ctypes.Structure):  # Xlib's XWindowAttributes
    _fields_ = [("x", ctypes.c_int), ("y", ctypes.c_int), ("width", ctypes.c_int),
                ("height", ctypes.c_int), ("border_width", ctypes.c_int),
                ("depth", ctypes.c_int), ("visual", ctypes.c_void_p),
                ("root", ctypes.c_ulong), ("c_class", ctypes.c_int),
                ("bit_gravity", ctypes.c_int), ("win_gravity", ctypes.c_int),
                ("backing_store", ctypes.c_int), ("backing_planes", ctypes.c_ulong),
                ("backing_pixel", ctypes.c_ulong), ("save_under", ctypes.c_int),
                ("colormap", ctypes.c_ulong), ("map_installed", ctypes.c_int),
                ("map_state", ctypes.c_int), ("all_event_masks", ctypes.c_long),
                ("your_event_mask", ctypes.c_long),
                ("do_not_propagate_mask", ctypes.c_long),
                ("override_redirect", ctypes.c_int), ("screen", ctypes.c_void_p)]


def _xlib() -> ctypes.CDLL:
    name = ctypes.util.find_library("X11") or "libX11.so.6"
    lib = ctypes.CDLL(name)
    lib.XOpenDisplay.restype = ctypes.c_void_p
    lib.XOpenDisplay.argtypes = [ctypes.c_char_p]
    lib.XDefaultRootWindow.restype = ctypes.c_ulong
    lib.XDefaultRootWindow.argtypes = [ctypes.c_void_p]
    lib.XQueryTree.argtypes = [ctypes.c_void_p, ctypes.c_ulong, ctypes.POINTER(ctypes.c_ulong),
                               ctypes.POINTER(ctypes.c_ulong),
                               ctypes.POINTER(ctypes.POINTER(ctypes.c_ulong)),
                               ctypes.POINTER(ctypes.c_uint)]
    lib.XGetWindowAttributes.argtypes = [ctypes.c_void_p, ctypes.c_ulong,
                                         ctypes.POINTER(_Attributes)]
    lib.XFree.argtypes = [ctypes.c_void_p]
    lib.XCloseDisplay.argtypes = [ctypes.c_void_p]
    return lib


@contextlib.contextmanager
def x_client(display: str) -> Iterator[Callable[[], list[XWindow]]]:
    """One connection to ``display`` for a whole watch (a connection a look, 5 a second, once
    left the child's window unseen); yields a function listing the root window's children
    as the X server places them. SDL names its windows in UTF-8, which XFetchName does not
    return, so no names: a test's own Xvfb has only its own windows."""
    lib = _xlib()
    dpy = lib.XOpenDisplay(display.encode())
    if not dpy:
        raise RuntimeError(f"cannot open X display {display}")

    def windows() -> list[XWindow]:
        root, parent = ctypes.c_ulong(), ctypes.c_ulong()
        children, count = ctypes.POINTER(ctypes.c_ulong)(), ctypes.c_uint()
        lib.XQueryTree(dpy, lib.XDefaultRootWindow(dpy), ctypes.byref(root),
                       ctypes.byref(parent), ctypes.byref(children), ctypes.byref(count))
        out = []
        for i in range(count.value):
            a = _Attributes()
            lib.XGetWindowAttributes(dpy, children[i], ctypes.byref(a))
            out.append(XWindow(a.x, a.y, a.width, a.height, a.map_state == 2))
        if children:
            lib.XFree(children)
        return out

    try:
        yield windows
    finally:
        lib.XCloseDisplay(dpy)
