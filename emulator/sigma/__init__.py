"""The Sigma T5684 / T5688 terminals (docs/interfaces.md: emulator.sigma)."""

from camlab88.emulator.sigma.models import MODELS, Model
from camlab88.emulator.sigma.terminal import Registers, Terminal

__all__ = ["MODELS", "Model", "Registers", "Terminal"]
