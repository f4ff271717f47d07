"""Pages made from the shipped recordings, the emulator's own frames beside them, and the
comparison of a browser's video frame with the emulator's."""

from __future__ import annotations

import json
import re
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from PIL import Image

from camlab88.cli import main

SESSIONS = Path(__file__).resolve().parents[1] / "data" / "sessions"

# H.264 (yuv420p, CRF 23) against the emulator's RGB frame: chroma is kept at half
# resolution, so a one-pixel coloured line loses colour at its edges; measured on the
# shipped sessions: mean absolute error 0.3-1.7 levels of 255 on the Sigma (PSNR 28.8-37
# dB), 3.4 on the CA's fine grey grid (PSNR 31.9 dB).
MEAN_TOL = 4.0   # mean absolute difference per channel, levels of 255
PSNR_MIN = 28.0  # dB


@dataclass
class Made:
    html: Path
    frames: Path           # the emulator's frames: frame_NNNNN.png, one per frame shown
    data: dict


def page_data(html: Path) -> dict:
    text = html.read_text(encoding="utf-8")
    m = re.search(r'<script type="application/json" id="data">(.*?)</script>', text, re.S)
    assert m, f"{html}: no data"
    return json.loads(m[1])


def make(session: str, out: Path, *more: str) -> Made:
    """The page of a shipped recording (OUT as given: .html or a directory) and its frames."""
    rec = SESSIONS / session
    assert main(["replay", str(rec), "--html", str(out), *more]) == 0
    frames = out.parent / f"{out.stem}_frames"
    assert main(["replay", str(rec), "--headless", "--frames", str(frames)]) == 0
    html = out if out.suffix == ".html" else out / "index.html"
    return Made(html, frames, page_data(html))


def emulator_frame(made: Made, shown: int) -> np.ndarray:
    return np.asarray(Image.open(made.frames / f"frame_{shown:05d}.png").convert("RGB"))


def mean_error(a: np.ndarray, b: np.ndarray) -> float:
    h, w = min(a.shape[0], b.shape[0]), min(a.shape[1], b.shape[1])
    return float(np.abs(a[:h, :w].astype(np.int16) - b[:h, :w].astype(np.int16)).mean())


def psnr(a: np.ndarray, b: np.ndarray) -> float:
    h, w = min(a.shape[0], b.shape[0]), min(a.shape[1], b.shape[1])
    mse = float(((a[:h, :w].astype(np.float64) - b[:h, :w]) ** 2).mean())
    return 99.0 if mse == 0 else 10 * np.log10(255 ** 2 / mse)


def assert_shows(made: Made, grabbed: np.ndarray, shown: int) -> None:
    """The browser's frame is the emulator's frame ``shown`` within the codec's tolerance,
    and nearer it than any frame of the session that looks clearly different."""
    w, h = made.data["screen"]
    got = grabbed[:h, :w]
    want = emulator_frame(made, shown)
    err = mean_error(got, want)
    assert err <= MEAN_TOL and psnr(got, want) >= PSNR_MIN, \
        f"frame {shown}: mean error {err:.2f}, PSNR {psnr(got, want):.1f} dB"
    n = len(made.data["frames"])
    for other in sorted({0, n // 3, 2 * n // 3, n - 1} - {shown}):
        theirs = emulator_frame(made, other)
        if mean_error(want, theirs) > 4 * MEAN_TOL:  # a frame that looks different
            assert mean_error(got, theirs) > err, f"frame {shown} looks like frame {other}"


def shown_at_video_frame(data: dict, k: int) -> int:
    """The page's own mapping: the shown frame that video frame ``k`` belongs to."""
    return max(i for i, (first, _t) in enumerate(data["frames"]) if first <= k)


def shown_at_or_after(data: dict, t: float) -> int:
    frames = data["frames"]
    return next((i for i, (_k, ft) in enumerate(frames) if ft >= t - 1e-9), len(frames) - 1)
