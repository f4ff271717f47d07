"""§6.4 asks for gamma correction: linear light is encoded to drive levels with gamma 2.2
(ours) and decoded back, so half the light is not half the drive level."""

from __future__ import annotations

import numpy as np

from camlab88.apps.snooker.render.gamma import decode, encode


def test_half_the_light_is_drive_level_186_and_decodes_back() -> None:
    assert int(encode(np.array([0.5]))[0]) == round(255 * 0.5 ** (1 / 2.2))  # 186, not 128
    levels = np.arange(2, 256)  # (level 1 is below the table's 16-bit linear step)
    assert np.array_equal(encode(decode(levels)), levels)
    assert int(encode(np.array([0.0]))[0]) == 0 and int(encode(np.array([1.0]))[0]) == 255
