"""Machines: a device with everything around it (clock, line, host port), ticked, framed and
saved as one. Host programs talk to a machine's ``host`` port; the public API
(camlab88.Sigma, camlab88.Rainbow) stands on these."""

from camlab88.emulator.machine.rainbow import RainbowMachine
from camlab88.emulator.machine.sigma import HostPort, SigmaMachine
from camlab88.emulator.machine.state_file import MachineStateError

__all__ = ["HostPort", "MachineStateError", "RainbowMachine", "SigmaMachine"]
