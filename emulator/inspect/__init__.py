"""The device inspector: panels that show inside a device while it runs (Sigma: LUT,
planes, write mask, modes, cursor, last orders; Rainbow: pad graph, bands, video memory),
drawn with numpy and the ROM font.  ``panel_for(target)`` finds the device behind a harness
target and returns a function drawing its panel (None: nothing to inspect)."""

from camlab88.emulator.inspect.find import PANEL_WIDTH, panel_for

__all__ = ["PANEL_WIDTH", "panel_for"]
