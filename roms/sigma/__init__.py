"""Sigma power-on data: the character generator and the default lookup tables."""

from roms.sigma.chargen import Font, load_font
from roms.sigma.lut import load_lut

__all__ = ["Font", "load_font", "load_lut"]
