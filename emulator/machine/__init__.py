"""Machines: a device with everything around it (clock, line, host port), ticked, framed and
saved as one. Host programs talk to a machine's ``host`` port; the public API
(camlab88.Sigma, camlab88.Rainbow) stands on these. The errors a command catches from a
machine are offered here too (RainbowError: a call the device refused; SceneError: a scene
file that cannot be built), so commands never import a device's modules."""

from camlab88.emulator.machine.rainbow import RainbowMachine
from camlab88.emulator.machine.sigma import HostPort, SigmaMachine
from camlab88.emulator.machine.state_file import MachineStateError
from camlab88.emulator.rainbow.errors import RainbowError
from camlab88.emulator.rainbow.scene import SceneError

__all__ = ["HostPort", "MachineStateError", "RainbowError", "RainbowMachine", "SceneError",
           "SigmaMachine"]
