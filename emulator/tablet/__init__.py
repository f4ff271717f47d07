"""The emulated tablet: a mouse-driven tablet that speaks a real serial protocol on a pty."""

from __future__ import annotations

from camlab88.emulator.tablet.device import EmulatedTablet
from camlab88.emulator.tablet.drive import demo_path, pointer_to_tablet
from camlab88.emulator.tablet.view import TabletView

__all__ = ["EmulatedTablet", "TabletView", "demo_path", "pointer_to_tablet"]
