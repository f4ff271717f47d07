"""The host test bench: the public API (camlab88.Sigma, camlab88.Rainbow) and its pytest
plugin, for people testing their own host software against the emulated devices."""
