"""``camlab88 replay FILE --html OUT`` without a browser: the two forms, the data in the
page (frames, events, orders) against the replay itself, no network anywhere in the page,
a session's text that cannot break out of the page, the codecs, and refusals."""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

from camlab88.cli import main
from camlab88.emulator.harness.web_capture import Capture, describe_event
from camlab88.replay_page import PageText, render
from tests.replay_web.helpers import SESSIONS, page_data


def test_one_file_holds_the_page_and_the_video(tmp_path, capsys) -> None:
    out = tmp_path / "sigma.html"
    assert main(["replay", str(SESSIONS / "sigma_run.session"), "--html", str(out)]) == 0
    err = capsys.readouterr().err
    assert f"web page {out}" in err and "one self-contained file" in err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["sigma.html"]
    text = out.read_text(encoding="utf-8")
    assert 'id="video-data" data-mime="video/mp4"' in text
    # nothing is fetched from anywhere: no URL with a scheme, no CDN, no @import
    assert not re.search(r"(src|href)\s*=\s*[\"'](https?:)?//", text)
    assert "@import" not in text and "url(http" not in text
    data = page_data(out)
    assert data["fps"] == 25 and data["screen"] == [768, 512] and not data["panel"]
    assert len(data["frames"]) == 76  # the recording's end: frame 76
    firsts = [k for k, _t in data["frames"]]
    assert firsts == sorted(firsts) and data["videoFrames"] >= len(firsts)
    offsets = [o[0] for o in data["orders"]]
    assert len(offsets) > 200 and offsets == sorted(offsets)
    assert all(o[1] <= 3.0 for o in data["orders"])


def test_a_directory_gets_the_page_beside_the_video(tmp_path, capsys) -> None:
    out = tmp_path / "site"
    assert main(["replay", str(SESSIONS / "sigma_run.session"), "--html", str(out)]) == 0
    assert "a directory: index.html beside the video" in capsys.readouterr().err
    assert sorted(p.name for p in out.iterdir()) == ["index.html", "session.mp4"]
    mp4 = (out / "session.mp4").read_bytes()
    assert mp4[4:8] == b"ftyp" and b"avc1" in mp4[:4096]  # H.264 in MP4, moov first
    assert 'data-src="session.mp4"' in (out / "index.html").read_text(encoding="utf-8")


def test_vp9_in_webm(tmp_path) -> None:
    out = tmp_path / "site"
    assert main(["replay", str(SESSIONS / "sigma_run.session"), "--html", str(out),
                 "--html-codec", "vp9"]) == 0
    webm = (out / "session.webm").read_bytes()
    assert webm[:4] == b"\x1a\x45\xdf\xa3" and b"V_VP9" in webm[:4096]


def test_a_sigma_programs_script_is_the_input_timeline(tmp_path) -> None:
    out = tmp_path / "kas.html"
    assert main(["replay", str(SESSIONS / "kas_edit.session"), "--html", str(out)]) == 0
    events = page_data(out)["events"]
    assert events[0][1].startswith(("stylus", "key"))
    assert any(text == "key escape" for _t, text in events)
    times = [t for t, _ in events]
    assert times == sorted(times)


def test_a_rainbow_page_has_the_panel_in_its_video(tmp_path) -> None:
    out = tmp_path / "snooker.html"
    assert main(["replay", str(SESSIONS / "snooker_play.session"), "--html", str(out)]) == 0
    data = page_data(out)
    assert data["panel"] and data["size"] == [768 + 384, 576] and data["screen"] == [768, 576]
    assert data["orders"] == [] and len(data["events"]) > 10
    assert data["events"][1][1] == "press middle 175,325"


def _capture(text: str) -> Capture:
    return Capture(fps=25, size=(768, 512), screen=(768, 512), device="Sigma T5684",
                   frames=[(0, 0.04)], video_frames=1, events=[(0.0, text)],
                   orders=[(0, 0.01, text, True)])


@pytest.mark.parametrize("text", ["</script><script>alert(1)</script>", "@VIDEO_DATA@",
                                  "<!--", "a & b \u2028 c"])
def test_the_sessions_text_stays_data(tmp_path, text: str) -> None:
    video = tmp_path / "v.mp4"
    video.write_bytes(b"\0" * 16)
    page = render(_capture(text), PageText("t <b>", "r.session", f"ca {text}", "Sigma",
                                           "today", "0"), video, inline=True)
    assert page.count("<script") == 3  # the data, the video, the player: no more
    assert "t &lt;b&gt;" in page
    if "<" in text:  # escaped everywhere: as HTML in the text, as \u003c in the data
        assert text not in page
    m = re.search(r'<script type="application/json" id="data">(.*?)</script>', page, re.S)
    data = json.loads(m[1])
    assert data["events"] == [[0.0, text]] and data["orders"][0][2] == text
    assert page.count('id="video-data"') == 1 and "AAAAAAAAAAAAAAAAAAAAAA==" in page


def test_events_are_told_in_words() -> None:
    from camlab88.emulator.host_input import KeyDown, PointerButton
    from camlab88.protocols.rainbow.events import KeyEvent, MouseEvent

    assert describe_event(KeyDown("f2", "")) == "key f2"
    assert describe_event(PointerButton(3, 4, 2, True)) == "press middle 3,4"
    assert describe_event(MouseEvent(0, 5, 6, 0)) == "mouse 5,6"
    assert describe_event(MouseEvent(0, 5, 6, 4, 3, False)) == "release right 5,6"
    assert describe_event(KeyEvent(0, "y", "y")) == "key y"


@pytest.mark.parametrize("more, says", [
    (["--seek", "1"], "it does not take --seek"),
    (["--frames", "f"], "it does not take --frames"),
])
def test_html_alone(tmp_path, capsys, more: list[str], says: str) -> None:
    out = tmp_path / "p.html"
    assert main(["replay", str(SESSIONS / "sigma_run.session"), "--html", str(out),
                 *more]) == 2
    assert says in capsys.readouterr().err
    assert not out.exists()


def test_outputs_that_cannot_be_written_are_refused_at_once(tmp_path, capsys) -> None:
    rec = str(SESSIONS / "sigma_run.session")
    with pytest.raises(SystemExit, match="no such directory"):
        main(["replay", rec, "--html", str(tmp_path / "no" / "p.html")])
    (tmp_path / "file").write_text("keep")
    assert main(["replay", rec, "--html", str(tmp_path / "file")]) == 2
    assert "not a directory" in capsys.readouterr().err
    assert (tmp_path / "file").read_text() == "keep"


def test_a_damaged_recording_is_refused_naming_it(tmp_path, capsys) -> None:
    bad = tmp_path / "bad.session"
    bad.write_bytes((SESSIONS / "sigma_run.session").read_bytes()[:-40])
    assert main(["replay", str(bad), "--html", str(tmp_path / "p.html")]) == 2
    assert str(bad) in capsys.readouterr().err
    assert not (tmp_path / "p.html").exists()


def test_pages_differ_only_by_what_differs(tmp_path) -> None:
    """Deterministic: the same recording makes the same page."""
    a, b = tmp_path / "a.html", tmp_path / "b.html"
    for out in (a, b):
        assert main(["replay", str(SESSIONS / "sigma_run.session"), "--html", str(out)]) == 0
    assert a.read_bytes() == b.read_bytes()


def test_the_page_files_ship_in_the_package() -> None:
    from importlib import resources

    names = {p.name for p in resources.files("camlab88.replay_page").iterdir()}
    assert {"head.html", "page.html", "player.js", "player.css"} <= names
    root = Path(__file__).resolve().parents[2]
    assert '"*.js"' in (root / "pyproject.toml").read_text()


def test_the_painting_programs_script_is_the_input_timeline(tmp_path) -> None:
    """kas paint plays its --script a command at a time: each is an event of the page."""
    figure = Path(__file__).resolve().parents[2] / "examples" / "figures" / "fig-3.8.session"
    out = tmp_path / "paint.html"
    assert main(["replay", str(figure), "--html", str(out)]) == 0
    data = page_data(out)
    words = [text for _t, text in data["events"]]
    assert words[:3] == ["colour 10", "select 0.0 -2.5", "fill"]
    assert len(data["orders"]) > 1000  # the T5688's painting orders, decoded
