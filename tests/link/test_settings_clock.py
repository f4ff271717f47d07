from __future__ import annotations

from fractions import Fraction

import pytest

from camlab88.protocols.link import LineSettings, Throttle, VirtualClock, to_time


def test_default_is_9600_8n1_960_chars_per_second() -> None:
    s = LineSettings()
    assert (s.baud, s.data_bits, s.parity, s.stop_bits) == (9600, 8, "N", 1)
    assert s.bits_per_char == 10
    assert s.char_time == Fraction(1, 960)
    assert s.char_seconds == 1 / 960
    assert str(s) == "9600 8N1"


@pytest.mark.parametrize(
    ("text", "bits", "char_time"),
    [
        ("9600 7E1", 10, Fraction(1, 960)),
        ("9600 8N2", 11, Fraction(11, 9600)),
        ("9600 8O1", 11, Fraction(11, 9600)),
        ("1200 7E2", 11, Fraction(11, 1200)),
        ("110 8N1.5", Fraction(21, 2), Fraction(21, 220)),
        ("300 5N1", 7, Fraction(7, 300)),
    ],
)
def test_framing_gives_exact_character_time(text: str, bits: Fraction, char_time: Fraction) -> None:
    s = LineSettings.parse(text)
    assert s.bits_exact == bits
    assert s.char_time == char_time
    assert str(s) == text
    assert LineSettings.parse(str(s)) == s


@pytest.mark.parametrize(
    "kwargs",
    [{"baud": 0}, {"baud": 9600.5}, {"data_bits": 9}, {"parity": "X"}, {"stop_bits": 3}],
)
def test_bad_settings_are_rejected(kwargs: dict[str, object]) -> None:
    with pytest.raises(ValueError):
        LineSettings(**kwargs)


def test_parse_rejects_garbage() -> None:
    with pytest.raises(ValueError, match="9600 8N1"):
        LineSettings.parse("fast please")


def test_pyserial_kwargs() -> None:
    kw = LineSettings.parse("1200 7E2").pyserial_kwargs()
    assert kw == {"baudrate": 1200, "bytesize": 7, "parity": "E", "stopbits": 2}
    assert LineSettings.parse("110 8N1.5").pyserial_kwargs()["stopbits"] == 1.5


def test_clock_is_exact_and_monotonic() -> None:
    c = VirtualClock()
    for _ in range(25):
        c.advance(0.04)
    assert c.exact == 1  # no float drift: 0.04 is read as 1/25
    c.advance_to(Fraction(3, 2))
    assert c.now == 1.5
    with pytest.raises(ValueError):
        c.advance(-0.001)
    with pytest.raises(ValueError):
        c.advance_to(1)


def test_to_time() -> None:
    assert to_time(1 / 960) == Fraction(1, 960)
    assert to_time(0.1 + 0.2) == Fraction(3, 10)
    assert to_time(Fraction(1, 3)) == Fraction(1, 3)
    with pytest.raises(ValueError):
        to_time(float("nan"))
    with pytest.raises(TypeError):
        to_time("1")


def test_throttle_maps_virtual_to_wall_time_with_a_fake_clock() -> None:
    wall = [100.0]
    slept: list[float] = []

    def sleep(dt: float) -> None:
        slept.append(dt)
        wall[0] += dt

    t = Throttle(speed=2.0, monotonic=lambda: wall[0], sleep=sleep)
    t.pace(0)  # anchors
    t.pace(1)  # 1 virtual second at 2x = 0.5 wall seconds
    assert slept == [0.5]
    wall[0] += 10  # the program fell behind: no sleep, lag reported
    t.pace(2)
    assert slept == [0.5] and t.behind == pytest.approx(9.5)
    flat = Throttle(speed=None, monotonic=lambda: wall[0], sleep=sleep)
    flat.pace(1000)
    assert slept == [0.5]
