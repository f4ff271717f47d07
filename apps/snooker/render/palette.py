"""The T5688's 256 colours (thesis 6.4.1: "only possible to display 2^8 (i.e. 256) colours
simultaneously ... infeasible to use anything but a fixed palette of colours").

``fixed_palette`` is the period answer: chosen before any picture is computed, from the
scene model (see its docstring). ``adaptive_palette`` is what the thesis wished for:
"calculate the image using a higher colour resolution and only decide after the image had
been calculated which would be the most useful 256 colours" — k-means in L*a*b* over the
true-colour frames of the whole sequence, seeded by median cut. One palette for the whole
sequence is the continuity the thesis asks for ("so that objects didn't undergo annoying
slight changes of colour"): a colour that does not change maps to the same entry in every
frame.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from camlab88.apps.snooker.render.colour import lab, lab_to_linear
from camlab88.apps.snooker.render.gamma import encode
from camlab88.apps.snooker.render.materials import BACKGROUND, BALL_ALBEDO, SURFACES
from camlab88.apps.snooker.render.scene import Scene
from camlab88.apps.snooker.render.shading import constant_colour, light_terms
from camlab88.apps.snooker.render.tablemodel import SIDES, table_faces

SIZE = 256
_CHUNK = 8192


@dataclass(frozen=True, eq=False)
class Palette:
    """256 linear colours; the LUT holds them gamma-encoded."""

    linear: np.ndarray  # (256, 3)

    @property
    def lut(self) -> np.ndarray:
        """(256, 3) uint8 gamma-corrected LUT entries (thesis 6.4)."""
        return encode(self.linear)

    @property
    def shown(self) -> np.ndarray:
        """(256, 3) linear light the monitor shows for each entry (after the 8-bit LUT)."""
        return (self.lut.astype(np.float64) / 255.0) ** 2.2

    def index(self, linear: np.ndarray) -> np.ndarray:
        """(..., 3) linear colours -> (...) uint8 nearest entries in L*a*b* (ties: lowest)."""
        flat = np.asarray(linear, dtype=np.float64).reshape(-1, 3)
        keys = encode(flat).astype(np.int64) @ np.array([65536, 256, 1])
        uniq, inverse = np.unique(keys, return_inverse=True)
        rgb = np.stack([uniq >> 16, (uniq >> 8) & 255, uniq & 255], axis=1) / 255.0
        best = nearest(lab(rgb ** 2.2), lab(self.shown))
        return best[inverse].reshape(np.shape(linear)[:-1]).astype(np.uint8)


def nearest(points_lab: np.ndarray, entries_lab: np.ndarray) -> np.ndarray:
    """Index of the nearest entry for every point (squared distance, in chunks)."""
    out = np.empty(len(points_lab), dtype=np.int64)
    e2 = np.sum(entries_lab ** 2, axis=1)
    for s in range(0, len(points_lab), _CHUNK):
        p = points_lab[s:s + _CHUNK]
        d = e2[None, :] - 2.0 * p @ entries_lab.T
        out[s:s + _CHUNK] = np.argmin(d, axis=1)
    return out


def fixed_palette(scene: Scene) -> Palette:
    """Chosen from the scene model before any frame is computed (constant shading makes
    every face's colour known in advance): the faces' colours, the baize under 0..4
    shadows, a ramp from dark to highlight for each ball colour, and blends for the
    boundaries the table model has (cushion / rail / apron / room, baize / cushion /
    pocket, each ball over the baize) — the thesis's point that a palette need only blend
    the colours that meet."""
    lights = scene.lights
    faces = table_faces(scene.table)
    flat = {f.name: constant_colour(np.array(SURFACES[f.material]), f.centre, f.normal, lights)
            for f in faces}
    baize = flat["playing surface"]
    entries = [np.asarray(BACKGROUND), *flat.values()]
    removed = np.array(SURFACES["baize"]) * light_terms(np.zeros(3), np.array([0.0, 0, 1]),
                                                        lights)
    for k in range(1, 2 * len(removed) + 1):  # half-shadow steps, as AA edges give
        entries.append(np.maximum(baize - removed.mean(axis=0) * k / 2.0, 0.0))
    top = float(lights.ambient.mean() + lights.colours.sum(axis=0).mean())
    for albedo in BALL_ALBEDO[:8]:  # the reds share one ramp
        entries += list(_ramp(albedo, 12, top)) + list(_to_white(albedo * top, 4))
        entries += _blends(albedo * top * 0.45, baize, 3)
    for s in SIDES:
        names = [f"{s} cushion face", f"{s} cushion top", f"{s} rail", f"{s} apron"]
        pairs = [("playing surface", names[0]), ("playing surface", names[1]),
                 (names[0], names[1]), (names[1], names[2]), (names[2], names[3])]
        for a, b in pairs:
            entries += _blends(flat[a], flat[b], 5)
        for n in names[2:]:
            entries += _blends(flat[n], np.asarray(BACKGROUND), 5)
    entries += _blends(baize, flat[next(n for n in flat if n.startswith("pocket"))], 3)
    out = _distinct(np.clip(np.array(entries), 0.0, 1.0))[:SIZE]
    if len(out) < SIZE:  # greys for whatever else
        out = np.concatenate([out, _ramp(np.ones(3), SIZE - len(out), 1.0)])
    return Palette(out)


def _blends(a: np.ndarray, b: np.ndarray, n: int) -> list[np.ndarray]:
    return [a + (b - a) * (k / (n + 1)) for k in range(1, n + 1)]


def _distinct(colours: np.ndarray) -> np.ndarray:
    """Drop entries whose 8-bit LUT value repeats an earlier one (order kept)."""
    keys = encode(colours).astype(np.int64) @ np.array([65536, 256, 1])
    _, first = np.unique(keys, return_index=True)
    return colours[np.sort(first)]


def _ramp(albedo: np.ndarray, n: int, top: float) -> np.ndarray:
    s = np.geomspace(0.04, top, n)  # geometric: even steps of lightness, as the eye sees
    return albedo[None, :] * s[:, None]


def _to_white(lit: np.ndarray, n: int) -> np.ndarray:
    t = np.linspace(0.0, 1.0, n + 1)[1:, None] * 0.85  # towards, not at, white
    return np.clip(lit, 0, 1) * (1 - t) + t


def adaptive_palette(frames_linear: list[np.ndarray], iterations: int = 10,
                     exact_share: float = 1e-4) -> Palette:
    """The 256 colours that serve these frames best: every colour covering at least
    ``exact_share`` of all pixels gets an entry of its own (the constant-shaded faces), and
    the rest are k-means (Lloyd) centres in L*a*b* over the remaining colours weighted by
    how many pixels have them, seeded by a weighted median cut. Deterministic."""
    keys = np.concatenate([_keys(f) for f in frames_linear])
    uniq, count = np.unique(keys, return_counts=True)
    common = count >= exact_share * keys.size
    order = np.argsort(-count[common], kind="stable")[: SIZE // 4]
    exact = uniq[common][order]
    rest, weight = uniq[~np.isin(uniq, exact)], count[~np.isin(uniq, exact)].astype(float)
    chosen = [_key_lab(exact)]
    k = SIZE - len(exact)
    if len(rest) <= k:
        chosen.append(_key_lab(rest))
    else:
        chosen.append(_cluster(_key_lab(rest), weight, k, iterations))
    lab_all = np.concatenate(chosen)
    if len(lab_all) < SIZE:
        lab_all = np.concatenate([lab_all, np.repeat(lab_all[-1:], SIZE - len(lab_all), 0)])
    return Palette(np.clip(lab_to_linear(lab_all), 0.0, 1.0))


def _cluster(data: np.ndarray, weight: np.ndarray, k: int, iterations: int) -> np.ndarray:
    """Lloyd's k-means from a weighted median cut, with the cheapest clusters moved to where
    the error is (LBG-style relocation), then Weiszfeld steps (each centre towards its
    cluster's weighted geometric median: the score is the mean dE, an absolute error,
    which medians minimise and means do not)."""
    centres = median_cut(data, k, weight)
    for _ in range(iterations):
        centres = _lloyd(data, weight, centres, 2, median=False)
        centres = _relocate(data, weight, centres, max(k // 20, 1))
    return _lloyd(data, weight, centres, iterations, median=True)


def _lloyd(data: np.ndarray, weight: np.ndarray, centres: np.ndarray, steps: int,
           median: bool) -> np.ndarray:
    centres = centres.copy()
    for _ in range(steps):
        label = nearest(data, centres)
        w = weight
        if median:
            w = weight / np.maximum(np.linalg.norm(data - centres[label], axis=1), 0.05)
        sums = np.zeros_like(centres)
        np.add.at(sums, label, data * w[:, None])
        total = np.bincount(label, weights=w, minlength=len(centres))
        live = total > 0
        centres[live] = sums[live] / total[live, None]
    return centres


def _relocate(data: np.ndarray, weight: np.ndarray, centres: np.ndarray,
              n: int) -> np.ndarray:
    """Move the n clusters that cost least to keep onto the n worst-served colours."""
    label = nearest(data, centres)
    err = weight * np.linalg.norm(data - centres[label], axis=1)
    cost = np.bincount(label, weights=err, minlength=len(centres))
    mass = np.bincount(label, weights=weight, minlength=len(centres))
    # removing a cluster sends its colours to their next-nearest entry: ~ its mass times the
    # spacing of entries; approximate that by mass * (its error + 1) and drop the cheapest
    cheap = np.argsort(mass * (cost / np.maximum(mass, 1e-12) + 1.0), kind="stable")[:n]
    worst = np.argsort(-err, kind="stable")
    out = centres.copy()
    taken: list[int] = []
    for idx in worst:
        if len(taken) == n:
            break
        if label[idx] in cheap:
            continue
        if all(np.linalg.norm(data[idx] - data[t]) > 1.0 for t in taken):
            taken.append(int(idx))
    for c, idx in zip(cheap, taken):
        out[c] = data[idx]
    return out


def _keys(linear: np.ndarray) -> np.ndarray:
    return encode(linear.reshape(-1, 3)).astype(np.int64) @ np.array([65536, 256, 1])


def _key_lab(keys: np.ndarray) -> np.ndarray:
    rgb = np.stack([keys >> 16, (keys >> 8) & 255, keys & 255], axis=1) / 255.0
    return lab(rgb ** 2.2)


def median_cut(data: np.ndarray, k: int, weight: np.ndarray | None = None) -> np.ndarray:
    """k centres: split the box with the widest extent at its (weighted) median, until k."""
    w = np.ones(len(data)) if weight is None else weight
    boxes = [np.arange(len(data))]
    while len(boxes) < k:
        widths = [float(np.ptp(data[b], axis=0).max()) if len(b) > 1 else -1.0
                  for b in boxes]
        i = int(np.argmax(widths))
        if widths[i] <= 0:
            break
        b = boxes.pop(i)
        axis = int(np.argmax(np.ptp(data[b], axis=0)))
        b = b[np.argsort(data[b, axis], kind="stable")]
        cum = np.cumsum(w[b])
        half = int(np.clip(np.searchsorted(cum, cum[-1] / 2.0), 1, len(b) - 1))
        boxes += [b[:half], b[half:]]
    centres = np.array([np.average(data[b], axis=0, weights=w[b]) for b in boxes])
    if len(centres) < k:  # fewer distinct colours than entries: repeat the last
        centres = np.concatenate([centres, np.repeat(centres[-1:], k - len(centres), 0)])
    return centres
