"""Argument types that more than one command area parses the same way (argparse ``type=``):
a frame size, a film file and a Dask address. Command areas may not import each other, so
they meet here."""

from __future__ import annotations

import argparse
from collections.abc import Callable
from pathlib import Path

FILM_SUFFIXES = (".mp4", ".gif")


def frame_size(text: str) -> tuple[int, int]:
    """``--size WxH`` of the rendering actions: each side 8..8192 pixels."""
    w, sep, h = text.lower().partition("x")
    if not (sep and w.isascii() and w.isdigit() and h.isascii() and h.isdigit()):
        raise argparse.ArgumentTypeError(f"expected WxH such as 768x512, not {text!r}")
    if not (8 <= int(w) <= 8192 and 8 <= int(h) <= 8192):
        raise argparse.ArgumentTypeError(f"{text}: each side must be 8..8192 pixels")
    return int(w), int(h)


def film_path(text: str) -> Path:
    """A film to write: .mp4 or .gif (the suffix picks the encoder)."""
    if Path(text).suffix.lower() not in FILM_SUFFIXES:
        raise argparse.ArgumentTypeError(f"{text}: the film is .mp4 or .gif")
    return Path(text)


def film_of_kind(ext: str) -> Callable[[str], Path]:
    """An argparse type for a film of one kind (``--mp4 FILE``, ``--gif FILE``)."""
    def check(text: str) -> Path:
        if Path(text).suffix.lower() != ext:
            raise argparse.ArgumentTypeError(f"{text}: expected a {ext} file")
        return Path(text)
    return check


def dask_address(text: str) -> str:
    """``--dask ADDRESS|local``: Dask's ``distributed`` is an extra; without it, say which."""
    import importlib.util

    if importlib.util.find_spec("distributed") is None:
        raise argparse.ArgumentTypeError(
            "rendering on Dask needs the dask extra: pip install 'camlab88[dask]'")
    return text


mp4_file = film_of_kind(".mp4")
gif_file = film_of_kind(".gif")
