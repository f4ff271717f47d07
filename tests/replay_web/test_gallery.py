"""``camlab88 figures --html DIR``: every figure of the catalogue in the index (those with a
recording as a page of their own, headed by number, section, caption and what differs), the
whole gallery within its 60 MB, and the index opening offline in Chromium with every link
leading to a page that plays."""

from __future__ import annotations

import html
import re
from pathlib import Path

import pytest

from camlab88.cli import main
from camlab88.commands.figures import recording
from camlab88.figure_catalogue import figures
from tests.replay_web.browser import Page, browser, chromium
from tests.replay_web.helpers import page_data

pytestmark = pytest.mark.xdist_group("gallery")
GALLERY_LIMIT = 60_000_000  # bytes, the whole gallery


@pytest.fixture(scope="module")
def gallery(tmp_path_factory) -> Path:
    out = tmp_path_factory.mktemp("gallery") / "figures"
    assert main(["figures", "--html", str(out)]) == 0
    return out


def test_every_figure_is_in_the_index_with_its_page(gallery: Path) -> None:
    index = (gallery / "index.html").read_text(encoding="utf-8")
    recorded = [f for f in figures() if recording(f.number).is_file()]
    assert len(recorded) >= 17
    for fig in figures():
        assert f"Figure {fig.number} " in index
        assert html.escape(fig.caption) in index
        if fig.differs:
            assert html.escape(fig.differs) in index
        page = gallery / f"fig-{fig.number}.html"
        if fig in recorded:
            assert f'href="fig-{fig.number}.html"' in index and page.is_file()
            text = page.read_text(encoding="utf-8")
            assert f"Figure {fig.number}</strong> ({html.escape(fig.section_label)})" in text
            assert f"camlab88 replay examples/figures/fig-{fig.number}.session" in text
            assert len(page_data(page)["frames"]) > 0
        else:
            assert "not recorded yet" in index and not page.exists()
    assert not re.search(r"(src|href)\s*=\s*[\"'](https?:)?//", index)


def test_the_gallery_keeps_within_its_size(gallery: Path) -> None:
    size = sum(p.stat().st_size for p in gallery.iterdir())
    assert size <= GALLERY_LIMIT, f"{size / 1e6:.1f} MB"


def test_one_figure_makes_a_gallery_of_one(tmp_path, capsys) -> None:
    out = tmp_path / "one"
    assert main(["figures", "7.3", "--html", str(out)]) == 0
    assert sorted(p.name for p in out.iterdir()) == ["fig-7.3.html", "fig-7.3.png",
                                                      "index.html"]
    assert "gallery" in capsys.readouterr().err
    assert main(["figures", "9.9", "--html", str(out)]) == 2


def test_the_index_opens_offline_and_its_links_play(gallery: Path) -> None:
    chromium()
    with browser() as ctx:
        errors: list[str] = []
        page = ctx.new_page()
        page.on("console", lambda m: errors.append(m.text) if m.type == "error" else None)
        page.on("pageerror", lambda e: errors.append(str(e)))
        page.goto((gallery / "index.html").as_uri())
        links = page.eval_on_selector_all(".card a", "as => as.map(a => a.href)")
        assert len(links) == len([f for f in figures() if recording(f.number).is_file()])
        page.wait_for_load_state("load")
        broken = page.evaluate("""() => [...document.images].filter(
            i => !i.complete || i.naturalWidth === 0).map(i => i.src)""")
        assert broken == []
        page.locator(".card a").first.click()
        page.wait_for_function("document.getElementById('video').readyState >= 2")
        assert "Figure 3.1" in page.inner_text("h1")
        page.close()
        assert errors == []
        for link in links[-3:]:  # the CA figures: the Rainbow's panel beside the screen
            p = Page(ctx, link)
            p.page.locator("h1").click()
            p.page.keyboard.press("End")
            p.settle()
            assert p.grab().std() > 5  # a picture, not a blank video
            assert p.errors == []
            p.close()
