"""Sigma power-on data: the character generator and the default lookup tables."""

from camlab88.roms.sigma.chargen import Font, load_font
from camlab88.roms.sigma.lut import load_lut

__all__ = ["Font", "load_font", "load_lut"]
