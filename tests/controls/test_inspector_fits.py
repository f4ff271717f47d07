"""The window with the inspector beside the screen fits the screen it opens on: at scale 1
768 + 384 pixels fit a 1280-wide screen as they are; on a narrower one (SDL's dummy
display is 1024 wide) or at --scale 2 the picture is scaled down to fit, and the pointer
still lands on the device pixel under it."""

from __future__ import annotations

import numpy as np
import pytest

from camlab88.emulator.window import Window, fit_zoom


@pytest.mark.parametrize("size, scale, screen, zoom", [
    ((1152, 576), 1, (1280, 1024), 1.0),         # the inspector on a 1280-wide screen
    ((1152, 576), 2, (1280, 1024), 1280 / 1152),  # --scale 2: as large as fits
    ((1152, 576), 1, (1024, 768), 1024 / 1152),
    ((768, 576), 1, None, 1.0),                   # screen size unknown: as asked
])
def test_the_zoom_fits_the_screen(size, scale, screen, zoom) -> None:
    assert fit_zoom(size, scale, screen) == pytest.approx(zoom)


def test_a_window_growing_an_inspector_stays_within_the_screen() -> None:
    import pygame

    w = Window("inspector", (768, 512))
    try:
        screen = pygame.display.get_desktop_sizes()[0]
        w.decorate = lambda f: np.concatenate([f, np.full((512, 384, 3), 200, np.uint8)], 1)
        w.show(np.zeros((512, 768, 3), np.uint8))
        width, height = w.surface.get_size()
        assert width <= screen[0] and height <= screen[1]
        assert width == round(1152 * w.zoom)
        x = int(700 * w.zoom) + 1  # a window pixel over device x = 700
        assert w._device_xy((x, 10))[0] == 700
    finally:
        w.close()


def test_a_window_too_large_for_the_screen_opens_fitted() -> None:
    """--scale 2 of a 768x512 screen (1536x1024) on SDL's 1024x768 dummy display: the window
    opens scaled down to fit, not at full size partly off the screen until the first frame."""
    import pygame

    w = Window("large", (768, 512), scale=2)
    try:
        screen = pygame.display.get_desktop_sizes()[0]
        width, height = w.surface.get_size()
        assert width <= screen[0] and height <= screen[1]
        assert w.zoom < 2 and (width, height) == (round(768 * w.zoom), round(512 * w.zoom))
        x = int(700 * w.zoom) + 1  # the pointer still lands on the device pixel under it
        assert w._device_xy((x, 10))[0] == 700
    finally:
        w.close()
