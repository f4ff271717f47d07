"""The replay page in a real browser (Debian's Chromium through Playwright): it loads from
file:// and from a web server, plays, seeks by the timeline, the scrubber, the keyboard and
the lists' rows, and the frame it shows is the emulator's own frame at that time (within
the codec's tolerance: tests/replay_web/helpers.py); the console stays free of errors.
Skipped, saying why, where no Chromium or Playwright is installed."""

from __future__ import annotations

import functools
import http.server
import os
import threading
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pytest

from tests.replay_web.browser import Page, browser, chromium
from tests.replay_web.helpers import (
    SESSIONS,
    Made,
    assert_shows,
    make,
    mean_error,
    psnr,
    shown_at_or_after,
    shown_at_video_frame,
)

pytestmark = pytest.mark.xdist_group("chromium")  # one browser, one set of pages
DOCS_SHOT = Path(__file__).resolve().parents[2] / "docs" / "images" / "replay-web.png"


@pytest.fixture(scope="module")
def ctx() -> Iterator:
    chromium()  # skips, saying why, before any page is made
    with browser() as c:
        yield c


@pytest.fixture(scope="module")
def kas(tmp_path_factory) -> Made:
    """A Sigma session: KAS's editor driven by its script (input events and orders)."""
    return make("kas_edit.session", tmp_path_factory.mktemp("kas") / "kas_edit.html")


@pytest.fixture(scope="module")
def ca(tmp_path_factory) -> Made:
    """A Rainbow session: the CA program, its inspector panel beside the screen."""
    return make("ca_program.session", tmp_path_factory.mktemp("ca") / "ca_program.html")


@pytest.fixture
def open_page(ctx) -> Iterator:
    pages: list[Page] = []

    def opener(url: str) -> Page:
        pages.append(Page(ctx, url))
        return pages[-1]

    yield opener
    for p in pages:
        assert p.errors == [], p.errors  # the console free of errors, whatever was done
        p.close()


def _url(made: Made) -> str:
    return made.html.as_uri()


def test_plays_then_pauses_on_the_emulators_frame(kas: Made, open_page) -> None:
    p = open_page(_url(kas))
    assert p.shown() == 0 and "paused" in p.status()
    assert_shows(kas, p.grab(), 0)
    p.page.click("#play")
    p.page.wait_for_function("+document.getElementById('status').dataset.frame >= 20",
                             timeout=30_000)
    assert "playing" in p.status()
    p.page.keyboard.press("Space")  # the page has focus on the Play button: it pauses
    p.page.wait_for_function("document.getElementById('video').paused")
    p.page.wait_for_function("document.getElementById('status').textContent"
                             ".includes('paused')")
    shown = p.shown()
    assert shown >= 20
    assert_shows(kas, p.grab(), shown)


def test_clicking_the_timeline_seeks_there(kas: Made, open_page) -> None:
    p = open_page(_url(kas))
    box = p.page.locator("#timeline").bounding_box()
    total = kas.data["videoFrames"]
    for frac in (0.75, 0.3):
        k = int(frac * total)
        x = (k + 0.5) / total * box["width"]
        p.page.click("#timeline", position={"x": x, "y": box["height"] / 2})
        p.settle()
        want = shown_at_video_frame(kas.data, k)
        assert p.shown() == want
        assert_shows(kas, p.grab(), want)


def test_the_keyboard_seeks_steps_and_sets_the_speed(kas: Made, open_page) -> None:
    p = open_page(_url(kas))
    frames = kas.data["frames"]
    p.page.locator("h1").click()  # the page, not a control, has the keys
    kb = p.page.keyboard
    kb.press("End")
    p.settle()
    assert p.shown() == len(frames) - 1
    assert_shows(kas, p.grab(), len(frames) - 1)
    kb.press("Home")
    p.settle()
    assert p.shown() == 0
    kb.press("ArrowRight")  # one second on
    p.settle()
    one_second = shown_at_or_after(kas.data, frames[0][1] + 1)
    assert p.shown() == one_second
    assert_shows(kas, p.grab(), one_second)
    kb.press("F6")  # the emulator's step key: one frame on
    p.settle()
    assert p.shown() == one_second + 1
    assert_shows(kas, p.grab(), one_second + 1)
    kb.press(",")
    p.settle()
    assert p.shown() == one_second
    for key, speed in (("F8", "2×"), ("F8", "4×"), ("F8", "8×"), ("F8", "8×"),
                       ("F7", "4×"), ("F7", "2×"), ("F7", "1×"), ("F7", "0.5×"),
                       ("F7", "0.25×"), ("F7", "0.25×")):
        kb.press(key)
        assert f" {speed} " in p.status(), (key, p.status())
    assert p.page.evaluate("document.getElementById('video').playbackRate") == 0.25
    kb.press("F5")  # the emulator's pause key plays and pauses (never reloads the page)
    p.page.wait_for_function("!document.getElementById('video').paused")
    kb.press("F5")
    p.page.wait_for_function("document.getElementById('video').paused")
    assert p.page.evaluate("performance.getEntriesByType('navigation').length") == 1


def test_the_scrubber_seeks(kas: Made, open_page) -> None:
    p = open_page(_url(kas))
    scrub = p.page.locator("#scrub")
    scrub.focus()
    p.page.keyboard.press("End")  # a range input's own keys
    p.settle()
    assert p.shown() == len(kas.data["frames"]) - 1
    p.page.keyboard.press("ArrowLeft")
    p.settle()
    assert p.shown() == len(kas.data["frames"]) - 2


def test_clicking_an_order_or_an_event_seeks_to_its_time(kas: Made, open_page) -> None:
    p = open_page(_url(kas))
    orders, events = kas.data["orders"], kas.data["events"]
    assert len(orders) > 100 and len(events) > 10
    for row in (len(orders) // 2, len(orders) - 1):
        p.page.locator(f"#orders button[data-i='{row}']").click()
        p.settle()
        want = shown_at_or_after(kas.data, orders[row][1])
        assert p.shown() == want
        cls = p.page.locator("#orders li").nth(row).get_attribute("class")
        assert "current" in cls or "now" in cls  # drawn in the frame on show
        assert_shows(kas, p.grab(), want)
    row = len(events) // 3
    p.page.locator(f"#events button[data-i='{row}']").click()
    p.settle()
    assert p.shown() == shown_at_or_after(kas.data, events[row][0])


def test_a_rainbow_page_shows_the_inspector_panel_of_the_frame(ca: Made, open_page,
                                                               tmp_path) -> None:
    from PIL import Image

    from camlab88.cli import main

    sw, sh = ca.data["screen"]
    assert ca.data["panel"] and ca.data["size"][0] > sw
    panels = tmp_path / "panels"
    assert main(["replay", str(SESSIONS / "ca_program.session"), "--headless",
                 "--inspect-out", str(panels)]) == 0
    p = open_page(_url(ca))
    p.page.locator("h1").click()
    p.page.keyboard.press("End")
    p.settle()
    last = len(ca.data["frames"]) - 1
    grabbed = p.grab()
    assert_shows(ca, grabbed, last)
    want_panel = np.asarray(Image.open(panels / f"frame_{last:05d}.png").convert("RGB"))
    got_panel = grabbed[:sh, sw:sw + want_panel.shape[1]]
    # the panel's small coloured text loses a little more to the halved chroma
    assert mean_error(got_panel, want_panel) <= 6.0 and psnr(got_panel, want_panel) >= 25
    assert len(ca.data["events"]) > 0  # the script's clicks, as the program was given them


def test_page_says_what_made_it_and_how_to_replay(kas: Made, open_page) -> None:
    p = open_page(_url(kas))
    text = p.page.inner_text("body")
    for words in ("Sigma T5684", "kas edit key.kas", "recorded", "camlab88 0.",
                  "camlab88 replay kas_edit.session"):
        assert words in text


def test_controls_are_labelled_and_reached_by_tab(kas: Made, open_page) -> None:
    p = open_page(_url(kas))
    unnamed = p.page.evaluate("""() => [...document.querySelectorAll(
        'button, input, select, [role=slider]')].filter(e => !(e.getAttribute('aria-label')
        || e.textContent.trim() || (e.id && document.querySelector(`label[for=${e.id}]`))))
        .map(e => e.outerHTML.slice(0, 80))""")
    assert unnamed == []
    keys = p.page.eval_on_selector_all("[aria-keyshortcuts]", "es => es.map(e => "
                                       "e.getAttribute('aria-keyshortcuts')).join(' ')")
    assert {"F5", "F6", "F7", "F8", "Space"} <= set(keys.split())
    reached = []
    p.page.locator("h1").click()
    for _ in range(12):
        p.page.keyboard.press("Tab")
        reached.append(p.page.evaluate("document.activeElement.id"))
    for control in ("play", "back", "step", "slower", "faster", "speed", "scrub", "timeline"):
        assert control in reached, reached
    p.page.locator("#timeline").focus()
    p.page.keyboard.press("End")
    p.settle()
    assert p.shown() == len(kas.data["frames"]) - 1


def test_the_page_plays_from_a_web_server_as_a_directory(tmp_path, open_page) -> None:
    made = make("sigma_run.session", tmp_path / "site")
    assert sorted(f.name for f in (tmp_path / "site").iterdir()) == ["index.html",
                                                                      "session.mp4"]
    handler = functools.partial(http.server.SimpleHTTPRequestHandler,
                                directory=str(tmp_path / "site"))
    handler.log_message = lambda *a: None
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    thread = threading.Thread(target=server.serve_forever, daemon=True)
    thread.start()
    try:
        p = open_page(f"http://127.0.0.1:{server.server_address[1]}/index.html")
        p.page.locator("h1").click()
        p.page.keyboard.press("End")
        p.settle()
        last = len(made.data["frames"]) - 1
        assert p.shown() == last
        assert_shows(made, p.grab(), last)
        p.page.keyboard.press("Home")
        p.settle()
        assert_shows(made, p.grab(), 0)
    finally:
        server.shutdown()
        server.server_close()


def test_screenshot_for_the_docs(kas: Made, open_page, tmp_path) -> None:
    """The page in Chromium, paused mid-session (docs/replay-web.md shows it); written into
    docs/images with CAMLAB88_REGEN_GOLDEN=1, else only taken and checked."""
    p = open_page(_url(kas))
    row = len(kas.data["orders"]) // 2
    p.page.locator(f"#orders button[data-i='{row}']").click()
    p.settle()
    shot = tmp_path / "replay-web.png"
    p.page.screenshot(path=str(shot), full_page=True)
    from PIL import Image

    img = np.asarray(Image.open(shot).convert("RGB"))
    assert img.shape[1] == 1400 and img.std() > 10
    if os.environ.get("CAMLAB88_REGEN_GOLDEN") == "1":
        DOCS_SHOT.write_bytes(shot.read_bytes())
    assert DOCS_SHOT.is_file()
    assert_shows(kas, p.grab(), p.shown())
