"""Imported first by a child process whose numba compiles a test counts: each compile prints
``compiled MODULE FUNCTION`` on standard output as it starts (a load from the cache prints
nothing)."""

from __future__ import annotations

from numba.core import event


class PrintCompiles(event.Listener):
    def on_start(self, ev: event.Event) -> None:
        function = ev.data["dispatcher"].py_func
        print("compiled", function.__module__, function.__name__, flush=True)

    def on_end(self, ev: event.Event) -> None:
        """Nothing more: the start says which kernel."""


event.register("numba:compile", PrintCompiles())
