"""The control keys, driven headless by a scripted window: F5 pause/resume, F6 one frame,
F7/F8 half/double speed, F12 screenshot, F1 the key overlay; none reaches the program."""

from __future__ import annotations

from fractions import Fraction

import numpy as np
import pytest
from PIL import Image

from camlab88.emulator.harness import Plugin
from camlab88.emulator.host_input import KeyDown, KeyUp, Quit
from tests.controls.fakes import FakeClock, FakeWindow, harness_with
from tests.support.targets import Counter


def key(name: str) -> list:
    return [KeyDown(name, ""), KeyUp(name)]


def test_pause_holds_virtual_time_until_resumed() -> None:
    clock = FakeClock()
    # poll 3 (before tick 4) pauses; polls 4..9 happen paused; poll 10 resumes
    window = FakeWindow({3: key("f5"), 10: key("f5")})
    h = harness_with(Counter(20), window, clock, speed=1.0)
    times = []
    h.plugins.append(type("T", (Plugin,), {
        "post_tick": lambda self, hh: times.append(hh.target.time())})())
    h.run()
    # one poll a tick, and seven more while paused (polls 4..10) with no tick between
    assert h.ticks == 20 and window.polls == 20 + 7
    assert clock.slept[:7] == [pytest.approx(1 / 50)] * 7  # paused: polled each 1/50 s
    assert times == [Fraction(k, 50) for k in range(1, 21)]
    assert any("PAUSED" in c for c in window.captions)


def test_advance_shows_exactly_one_frame_then_pauses_again() -> None:
    clock = FakeClock()
    # F6 at poll 0: one frame (two ticks at 25 fps of 50 Hz ticks), then paused; polls
    # while paused: F6 again at poll 5 (one more frame), F5 at poll 9 resumes
    window = FakeWindow({0: key("f6"), 5: key("f6"), 9: key("f5")})
    h = harness_with(Counter(12), window, clock)
    shown_at = []
    h.plugins.append(type("F", (Plugin,), {
        "on_frame": lambda self, hh, f: shown_at.append((window.polls, hh.ticks))})())
    h.run()
    # a frame at tick 1 (frames at odd ticks); paused through polls 2..5; F6 again: ticks
    # 2 and 3 until the next frame (after poll 6); paused through polls 8..9; then freely
    assert shown_at == [(1, 1), (7, 3), (11, 5), (13, 7), (15, 9), (17, 11), (18, 12)]


def test_control_keys_never_reach_the_program_and_other_keys_do() -> None:
    window = FakeWindow({1: [*key("f7"), KeyDown("a", "a"), *key("f8"), *key("f1"),
                             *key("f1")]})
    target = Counter(6)
    harness_with(target, window, FakeClock(), speed=4.0).run()
    assert target.got == [KeyDown("a", "a")]


def test_slower_and_faster_halve_and_double_the_speed() -> None:
    window = FakeWindow({1: key("f7"), 2: key("f7"), 3: key("f8"), 4: key("f8"),
                         5: key("f8")})
    clock = FakeClock()
    h = harness_with(Counter(10), window, clock, speed=4.0)
    speeds = []
    poll = window.poll
    window.poll = lambda: (speeds.append(h.pacer.speed), poll())[1]
    h.run()
    assert speeds[2:7] == [2.0, 1.0, 2.0, 4.0, 8.0]
    assert any("speed x8" in c for c in window.captions)


def test_faster_beyond_the_top_speed_is_flat_out_and_slower_starts_from_what_it_ran_at(
) -> None:
    window = FakeWindow({1: key("f8"), 5: key("f7")})
    clock = FakeClock()
    h = harness_with(Counter(10), window, clock, speed=1000.0)
    h.run()
    assert h.pacer.speed is not None and h.pacer.speed <= 1000.0
    assert any("flat out" in c for c in window.captions)


def test_screenshot_key_writes_a_new_png_each_time_and_names_it(tmp_path, capsys) -> None:
    window = FakeWindow({4: key("f12"), 6: key("f12")})
    h = harness_with(Counter(10), window, FakeClock(), shots=tmp_path)
    h.run()
    names = sorted(p.name for p in tmp_path.iterdir())
    assert names == ["camlab88-00002.png", "camlab88-00003.png"]
    img = np.asarray(Image.open(tmp_path / "camlab88-00002.png"))
    assert img.shape == (3, 4, 3) and (img == 3).all()  # the frame shown at tick 3
    err = capsys.readouterr().err
    assert f"screenshot {tmp_path / 'camlab88-00002.png'}" in err
    assert any("screenshot camlab88-00003.png" in c for c in window.captions)


def test_help_overlay_lists_the_controls_and_the_programs_keys() -> None:
    from camlab88.emulator.harness.help import key_lines

    window = FakeWindow({2: key("f1")})
    h = harness_with(Counter(8, size=(768, 512)), window, FakeClock())
    h.run()
    groups = dict(key_lines(h))
    assert ("F5", "pause / resume") in groups["Emulator controls"]
    assert groups["The program"] == [("", "a: a key"), ("", "b: another")]
    plain, covered = window.shown[0], window.shown[-1]
    assert not np.array_equal(plain[:40], covered[:40])  # the overlay is drawn
    assert covered.shape == plain.shape


def test_a_plugins_keys_are_in_the_help() -> None:
    from camlab88.emulator.harness.help import key_lines

    class States(Plugin):
        keys = [("F2", "save a state")]
        keys_title = "States"

    h = harness_with(Counter(2), None, FakeClock())
    h.plugins.append(States())
    assert ("States", [("F2", "save a state")]) in key_lines(h)


def test_quit_while_paused_ends_the_run() -> None:
    window = FakeWindow({1: key("f5"), 4: [Quit()]})
    h = harness_with(Counter(100), window, FakeClock())
    h.run()
    assert h.quit and h.ticks == 1


def test_every_window_shows_frame_time_and_keys_in_its_title() -> None:
    window = FakeWindow()
    harness_with(Counter(5), window, FakeClock()).run()
    assert window.captions[-1].startswith("counter | frame 3  t 0.10 s  a: a key")
    assert window.captions[-1].endswith("| F1 keys")


def test_a_signal_while_paused_ends_the_run_after_one_tick(monkeypatch) -> None:
    from camlab88.emulator.harness.signals import DeferredSignals

    delivered = []
    monkeypatch.setattr(DeferredSignals, "deliver", lambda self: delivered.append(self.caught))
    window = FakeWindow({1: key("f5")})
    h = harness_with(Counter(100), window, FakeClock())
    poll = window.poll

    def poll_then_signal() -> list:
        if window.polls == 4:  # paused: Ctrl-C arrives (DeferredSignals notes it)
            h.signals.caught = 2
        return poll()

    window.poll = poll_then_signal
    h.run()
    assert h.ticks == 2 and window.polls == 5 and delivered == [2]
