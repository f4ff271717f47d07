"""The power-on ROM data: character generator and lookup tables, and their loaders' errors."""

from __future__ import annotations

from pathlib import Path

import pytest

from camlab88.roms.sigma import load_font, load_lut
from camlab88.roms.sigma.chargen import RomError, parse_font
from camlab88.roms.sigma.lut import parse_lut


def test_font_has_every_printable_ascii_glyph() -> None:
    f = load_font()
    assert (f.width, f.height, f.baseline) == (5, 9, 7)
    for code in range(0x21, 0x7F):
        assert f.glyph(code).any(), f"glyph {code:02X} is empty"
    assert not f.glyph(0x20).any()
    assert f.glyph(ord("g"))[7:].any() and not f.glyph(ord("a"))[7:].any()  # descenders


def test_luts_load_with_the_right_sizes() -> None:
    assert load_lut("t5684").shape == (16, 3)
    lut8 = load_lut("t5688")
    assert lut8.shape == (256, 3)
    assert (lut8[:16] == load_lut("t5684")).all()


def test_font_errors_name_file_and_line() -> None:
    p = Path("bad.txt")
    with pytest.raises(RomError, match=r"bad.txt:4: glyph rows use only"):
        parse_font("width 5\nheight 9\nchar 41 A\n#x...\n", p)
    with pytest.raises(RomError, match=r"bad.txt:2: glyph row before"):
        parse_font("width 5\n#....\n", p)
    with pytest.raises(RomError, match="missing 'baseline'"):
        parse_font("width 5\nheight 9\n", p)


def test_lut_errors_name_file_and_line() -> None:
    p = Path("bad.lut")
    with pytest.raises(RomError, match=r"bad.lut:2: entry out of range"):
        parse_lut("guns 4\n0 0 0 10\n", p, 16)
    with pytest.raises(RomError, match=r"bad.lut:1: entry before"):
        parse_lut("0 0 0 0\n", p, 16)
    with pytest.raises(RomError, match="1 entries, expected 16"):
        parse_lut("guns 4\n0 0 0 0\n", p, 16)
