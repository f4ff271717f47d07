"""A real browser for the replay pages: the system's Chromium (Debian's ``chromium``, or
``CAMLAB88_CHROMIUM``) driven by Playwright with that executable (no browser download).
Where either is missing the tests skip, saying which and how to get it."""

from __future__ import annotations

import base64
import io
import os
import shutil
import tempfile
from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any

import numpy as np
import pytest

# what this machine needs (no GPU, no sandbox as root, no traffic beyond the page)
FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
         "--disable-background-networking", "--disable-component-update", "--disable-sync"]


def chromium() -> str:
    """The Chromium executable, or a skip naming what is missing."""
    path = os.environ.get("CAMLAB88_CHROMIUM") or shutil.which("chromium") \
        or shutil.which("chromium-browser")
    if not path:
        pytest.skip("no Chromium: install Debian's chromium (apt-get install chromium; "
                    ".ci/run does) or point CAMLAB88_CHROMIUM at one")
    try:
        import playwright.sync_api  # noqa: F401
    except ImportError:
        pytest.skip("no Playwright: pip install -e '.[test]'")
    return path


@contextmanager
def browser() -> Iterator[Any]:
    """A fresh Chromium profile, its context (1400 x 1000 CSS pixels, scale 1)."""
    from playwright.sync_api import sync_playwright

    exe = chromium()
    with tempfile.TemporaryDirectory(prefix="camlab88-chromium-") as profile, \
            sync_playwright() as p:
        ctx = p.chromium.launch_persistent_context(
            profile, executable_path=exe, args=FLAGS, headless=True,
            viewport={"width": 1400, "height": 1000}, device_scale_factor=1)
        try:
            yield ctx
        finally:
            ctx.close()


class Page:
    """One page open in the browser, with every console error and page error kept."""

    def __init__(self, ctx: Any, url: str) -> None:
        self.errors: list[str] = []
        self.page = ctx.new_page()
        self.page.on("console", lambda m: self.errors.append(f"console: {m.text}")
                     if m.type == "error" else None)
        self.page.on("pageerror", lambda e: self.errors.append(f"page error: {e}"))
        self.page.goto(url)
        self.page.wait_for_function("document.getElementById('video').readyState >= 2",
                                    timeout=30_000)
        self.settle()

    def settle(self) -> None:
        """Wait until a seek has landed and the status shows where."""
        self.page.wait_for_function(
            "(() => { const v = document.getElementById('video');"
            " return !v.seeking && v.readyState >= 2; })()", timeout=30_000)

    def shown(self) -> int:
        return int(self.page.get_attribute("#status", "data-frame"))

    def status(self) -> str:
        return self.page.inner_text("#status")

    def grab(self) -> np.ndarray:
        """The video frame on show, through a canvas (exact pixels, no page scaling)."""
        self.settle()
        url = self.page.evaluate("""() => { const v = document.getElementById('video');
            const c = document.createElement('canvas');
            c.width = v.videoWidth; c.height = v.videoHeight;
            c.getContext('2d').drawImage(v, 0, 0); return c.toDataURL('image/png'); }""")
        from PIL import Image

        png = base64.b64decode(url.split(",", 1)[1])
        return np.asarray(Image.open(io.BytesIO(png)).convert("RGB"))

    def close(self) -> None:
        self.page.close()
