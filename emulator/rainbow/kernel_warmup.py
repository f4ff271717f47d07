"""Every Rainbow kernel called once, with the argument types the device uses.

The completion of the "Rainbow" kernel group (base.kernel_notice): after the first cold
compile of any of them (the band compiler's, say, by a program that never shows a frame) the
rest compile too, under the same notice, so a later program loads them from the cache. One
frame of a real device rather than direct kernel calls, so the argument types are the ones
the device's own calls have.
"""

from __future__ import annotations

from camlab88.emulator.rainbow.device import Rainbow


def compile_kernels() -> None:
    r = Rainbow()
    pad = r.create_pad(8, 8, 1)
    r.map(r.screen, pad, 0, 0)
    r.frame()  # the band compiler (and its helpers), then the video processor's scan-out
