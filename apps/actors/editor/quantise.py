"""A true-colour picture into one 8-bit pad: 256 pixel values and the LUT page they index.

The Rainbow shows 8 bits a pixel through a 4096-entry LUT, so the turning preview gets its
own page and an adaptive palette each frame: colours are counted in bins of 5 bits a
channel, the 256 most common bins (ties: the lower bin number) become the palette (each the
mean of its pixels), and every other bin takes the nearest palette entry. Deterministic and
cheap: the nearest-entry search runs over the occupied bins, not over the pixels. A lit solid
of one colour on a grey floor occupies a few hundred bins, so little is lost.
"""

from __future__ import annotations

import numpy as np

SIZE = 256
CHUNK = 1024  # bins matched to the palette at a time


def quantise(rgb: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(h, w, 3) uint8 -> ((h, w) uint8 values, (256, 3) uint8 palette)."""
    px = rgb.reshape(-1, 3).astype(np.int64)
    key = ((px[:, 0] >> 3) << 10) | ((px[:, 1] >> 3) << 5) | (px[:, 2] >> 3)
    bins, inverse, counts = np.unique(key, return_inverse=True, return_counts=True)
    sums = np.zeros((len(bins), 3), np.int64)
    np.add.at(sums, inverse, px)
    means = sums // counts[:, None]
    order = np.lexsort((bins, -counts))  # most common first, then the lower bin
    chosen = order[:SIZE]
    palette = np.zeros((SIZE, 3), np.uint8)
    palette[:len(chosen)] = means[chosen]
    entry = np.empty(len(bins), np.int64)
    entry[chosen] = np.arange(len(chosen))
    rest = order[SIZE:]
    pal = means[chosen]
    for k in range(0, len(rest), CHUNK):  # bounded memory whatever the picture
        part = rest[k:k + CHUNK]
        d = ((means[part][:, None, :] - pal[None, :, :]) ** 2).sum(axis=2)
        entry[part] = np.argmin(d, axis=1)
    values = entry[inverse].astype(np.uint8).reshape(rgb.shape[:2])
    return values, palette
