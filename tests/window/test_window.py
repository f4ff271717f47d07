"""The pygame window under SDL's dummy video driver (set in tests/conftest.py)."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from camlab88.emulator.host_input import KeyDown, KeyUp, PointerButton, PointerMove, Quit
from tests.support.processes import fresh_python


@pytest.fixture()
def window() -> Iterator[object]:
    from camlab88.emulator.window import Window

    w = Window("test", (16, 10), scale=3)
    yield w
    w.close()


def test_importing_the_emulator_does_not_import_pygame() -> None:
    code = (
        "import sys, camlab88.emulator.window, camlab88.emulator.host_input\n"
        "print('pygame' in sys.modules)"
    )
    assert fresh_python(code).strip() == "False"


def test_frame_is_shown_scaled_and_the_screenshot_matches(window, tmp_path: Path) -> None:
    rng = np.random.default_rng(7)
    frame = rng.integers(0, 256, size=(10, 16, 3), dtype=np.uint8)
    window.show(frame)
    want = np.repeat(np.repeat(frame, 3, axis=0), 3, axis=1)
    assert np.array_equal(window.pixels(), want)
    shot = window.screenshot(tmp_path / "shot.png")
    assert np.array_equal(np.asarray(Image.open(shot).convert("RGB")), want)
    assert [p.name for p in tmp_path.iterdir()] == ["shot.png"]  # no temp files left


def test_wrong_frame_shape_is_a_clear_error(window) -> None:
    with pytest.raises(ValueError, match="does not match"):
        window.show(np.zeros((16, 10, 3), np.uint8))


def test_pygame_events_become_host_input_in_device_pixels(window) -> None:
    import pygame

    pygame.event.clear()
    post = pygame.event.post
    post(pygame.event.Event(pygame.MOUSEMOTION, pos=(47, 29), rel=(1, 1), buttons=(1, 0, 1)))
    post(pygame.event.Event(pygame.MOUSEBUTTONDOWN, pos=(7, 8), button=1))
    post(pygame.event.Event(pygame.MOUSEBUTTONUP, pos=(300, -5), button=3))  # clipped
    post(pygame.event.Event(pygame.MOUSEBUTTONDOWN, pos=(7, 8), button=4))  # wheel: ignored
    post(pygame.event.Event(pygame.KEYDOWN, key=pygame.K_a, unicode="A", mod=pygame.KMOD_LSHIFT))
    post(pygame.event.Event(pygame.KEYDOWN, key=pygame.K_UP, unicode="", mod=0))
    post(pygame.event.Event(pygame.KEYDOWN, key=pygame.K_RETURN, unicode="\r", mod=0))
    post(pygame.event.Event(pygame.KEYUP, key=pygame.K_F1, mod=0))
    post(pygame.event.Event(pygame.QUIT))
    events = window.poll()
    assert events == [
        PointerMove(15, 9, frozenset({1, 3})),
        PointerButton(2, 2, 1, True),
        PointerButton(15, 0, 3, False),
        KeyDown("a", "A", frozenset({"shift"})),
        KeyDown("up", "", frozenset()),
        KeyDown("return", "\r", frozenset()),
        KeyUp("f1"),
        Quit(),
    ]
    assert window.poll() == []


def test_bad_scale_is_rejected() -> None:
    from camlab88.emulator.window import Window

    with pytest.raises(ValueError):
        Window("x", (4, 4), scale=0)


def test_wait_frame_rejects_nonsense(window) -> None:
    with pytest.raises(ValueError):
        window.wait_frame(0)
    window.wait_frame(1000)  # the first call only anchors
