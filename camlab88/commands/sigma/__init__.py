"""``camlab88 sigma render|run``: the Sigma T5684/T5688 terminals headless or in a window."""

from __future__ import annotations

ACTIONS = ("render", "run")
HELP = "the Sigma T5684/T5688 terminals"
DESCRIPTION = "Emulated Sigma T5684 / T5688 graphics terminals."
MODELS = ("t5684", "t5688")  # the --model choices of both actions


