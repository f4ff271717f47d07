"""Tablet input on the host side, beside the emulated tablet device: the pointer a program
window reads (``pointer``), the emulated tablet driven from a window for the tablet tools
(``emulated_source``), and a ``--tablet`` read onto or from a session's tablet tape
(``taped``).  These use the window and the harness's replay, so they live outside the device
package ``emulator.tablet``, which never imports either."""
