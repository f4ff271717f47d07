"""The render modes, the one list every command and the renderer take them from (thesis 6.4).

``period``, ``fixed`` and ``adapted`` draw on the Sigma T5688 over the serial line (see
sigma_host); ``truecolour`` renders 24-bit frames on the host."""

from __future__ import annotations

SIGMA_MODES = ("period", "fixed", "adapted")
MODES = (*SIGMA_MODES, "truecolour")
