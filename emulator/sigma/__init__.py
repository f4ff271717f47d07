"""The Sigma T5684 / T5688 terminals (docs/interfaces.md: emulator.sigma)."""

from emulator.sigma.models import MODELS, Model
from emulator.sigma.terminal import Registers, Terminal

__all__ = ["MODELS", "Model", "Registers", "Terminal"]
