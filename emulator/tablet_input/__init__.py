"""Tablet input on the host side, beside the emulated tablet device: the pointer a program
window reads (``pointer``), the emulated tablet driven from a window for the tablet tools
(``emulated_source``), a ``--tablet`` read onto or from a session's tablet tape (``taped``),
and the tablet tools themselves as programs on the harness (``program``: what they share;
``monitor``, ``calibrate``, ``emulate``).  These use the window's events and the harness, so
they live outside the device package ``camlab88.emulator.tablet``, which never imports either."""
