from __future__ import annotations

from fractions import Fraction

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from camlab88.protocols.link import LineSettings, SerialLine, VirtualClock
from tests.link.naive import simulate

CT = Fraction(1, 960)


def per_byte(runs: list[tuple[Fraction, bytes]], ct: Fraction) -> list[tuple[Fraction, int]]:
    out = []
    for last, data in runs:
        for j, b in enumerate(data):
            out.append((last - (len(data) - 1 - j) * ct, b))
    return out


def test_960_bytes_take_exactly_one_second() -> None:
    line = SerialLine()
    assert line.host.write(bytes(960)) == 1.0
    assert line.host.drain_time() == 1.0
    assert line.device.read(until=Fraction(959, 960)) == bytes(959)
    assert line.device.read(until=Fraction(1919, 1920)) == b""
    assert line.device.read(until=1) == bytes(1)


@pytest.mark.parametrize(("framing", "seconds"), [("9600 7E1", 1), ("9600 8N2", Fraction(11, 10))])
def test_framing_changes_pace(framing: str, seconds: Fraction) -> None:
    line = SerialLine(LineSettings.parse(framing))
    line.host.write(b"A" * 960)
    assert line.host.drain_time_exact() == seconds


def test_every_byte_arrives_one_character_after_it_starts() -> None:
    line = SerialLine()
    line.clock.advance_to(Fraction(1, 3))
    line.host.write(b"abc")
    runs = line.device.read_timed(until=10, exact=True)
    assert per_byte(runs, CT) == [(Fraction(1, 3) + k * CT, b) for k, b in enumerate(b"abc", 1)]


def test_reads_default_to_clock_now_and_are_split_anywhere() -> None:
    line = SerialLine()
    line.host.write(b"hello world")
    got = b""
    for k in range(1, 12):
        line.clock.advance_to(Fraction(k, 960))
        got += line.device.read()
        assert got == b"hello world"[:k]
    assert line.device.read() == b""


def test_writes_queue_behind_each_other_and_gaps_stay_gaps() -> None:
    line = SerialLine()
    line.host.write(b"ab")
    assert line.host.write(b"cd") == pytest.approx(4 / 960)
    assert line.host.write(b"e", at=1) == pytest.approx(1 + 1 / 960)
    runs = line.device.read_timed(until=2, exact=True)
    assert per_byte(runs, CT)[-1] == (1 + CT, ord("e"))
    line.clock.advance_to(1)
    with pytest.raises(ValueError, match="past"):
        line.host.write(b"x", at=0.5)


def test_both_directions_are_independent() -> None:
    line = SerialLine()
    line.host.write(b"down")
    line.device.write(b"up")
    assert line.host.read(until=1) == b"up"
    assert line.device.read(until=1) == b"down"


def test_seven_bit_line_drops_the_top_bit() -> None:
    line = SerialLine(LineSettings.parse("9600 7E1"))
    line.host.write(bytes([0xC1, 0x41, 0xFF]))
    assert line.device.read(until=1) == bytes([0x41, 0x41, 0x7F])


def test_xoff_pauses_the_other_direction_from_its_arrival_and_xon_resumes() -> None:
    line = SerialLine()
    line.device.write(b"\x13")  # arrives at the host at 1/960
    assert line.host.write(b"a" * 100) == float("inf")  # no XON known: never drains
    line.clock.advance_to(Fraction(1, 2))
    # The first character started at 0, before the DC3 arrived, so it completes.
    assert line.device.read_timed(exact=True) == [(CT, b"a")]
    assert line.host.paused
    line.device.write(b"\x11")  # arrives at 1/2 + 1/960: transmission resumes then
    assert line.host.drain_time_exact() == Fraction(1, 2) + 100 * CT
    runs = line.device.read_timed(until=2, exact=True)
    assert runs == [(Fraction(1, 2) + 100 * CT, b"a" * 99)]
    assert line.host.read(until=2) == b""  # flow bytes are consumed by the line
    assert line.stats["device_to_host_flow"] == 2


def test_flow_bytes_are_data_when_xonxoff_is_off() -> None:
    line = SerialLine(xonxoff=False)
    line.device.write(b"\x13")
    assert line.host.write(b"ab") == pytest.approx(2 / 960)
    assert line.host.read(until=1) == b"\x13"
    assert line.device.read(until=1) == b"ab"


def test_paused_end_still_sends_flow_bytes_at_the_head_of_its_queue() -> None:
    line = SerialLine()
    line.device.write(b"\x13")
    line.host.write(b"\x13")  # both ends pause each other...
    line.clock.advance_to(Fraction(10, 960))
    line.host.write(b"x")
    line.device.write(b"\x11")  # ...the device's DC1 still goes out
    assert line.device.read(until=1) == b"x"


def test_stream_with_inline_xoff_from_device_mid_transfer() -> None:
    line = SerialLine()
    line.host.write(b"0123456789")
    line.clock.advance_to(Fraction(3, 960))
    line.device.write(b"\x13")  # arrives at 4/960: bytes started before then complete
    line.clock.advance_to(Fraction(20, 960))
    assert line.device.read() == b"0123"
    line.device.write(b"\x11")  # arrives at 21/960
    runs = line.device.read_timed(until=1, exact=True)
    assert runs == [(Fraction(27, 960), b"456789")]


writes_strategy = st.lists(
    st.tuples(
        st.integers(0, 40),  # write time in half characters
        st.sampled_from(">"),
        st.binary(max_size=12).map(lambda b: bytes(x % 4 + 0x10 for x in b)),  # many DC1/DC3
    )
    | st.tuples(
        st.integers(0, 40),
        st.sampled_from("<"),
        st.binary(max_size=12).map(lambda b: bytes(x % 4 + 0x10 for x in b)),
    ),
    max_size=8,
)


@settings(max_examples=150, deadline=None)
@given(writes_strategy, st.booleans())
def test_schedule_matches_an_independent_byte_at_a_time_model(
    writes: list[tuple[int, str, bytes]], xonxoff: bool
) -> None:
    timed = sorted(((Fraction(t, 1920), d, data) for t, d, data in writes), key=lambda w: w[0])
    want = simulate(CT, timed, xonxoff)
    line = SerialLine(xonxoff=xonxoff, clock=VirtualClock())
    for t, d, data in timed:
        line.clock.advance_to(t)
        (line.host if d == ">" else line.device).write(data)
    drained = want.pop("drained")
    for end, d in ((line.host, ">"), (line.device, "<")):
        predicted = end.drain_time_exact()  # before anything is fixed: a prediction
        assert predicted == (float("inf") if drained[d] is None else drained[d])
    line.finish()
    got_down = per_byte(line.device.read_timed(until=10**6, exact=True), CT)
    got_up = per_byte(line.host.read_timed(until=10**6, exact=True), CT)
    assert got_down == want[">"]
    assert got_up == want["<"]


@settings(max_examples=100, deadline=None)
@given(writes_strategy, st.lists(st.integers(0, 60), max_size=6))
def test_reading_at_any_times_gives_the_same_bytes(
    writes: list[tuple[int, str, bytes]], read_times: list[int]
) -> None:
    """Where the reads happen (at the clock) never changes what arrives when."""
    timed = sorted(((Fraction(t, 1920), d, data) for t, d, data in writes), key=lambda w: w[0])
    want = simulate(CT, timed)
    want.pop("drained")
    line = SerialLine()
    events = sorted([(t, 0, d, data) for t, d, data in timed] + [
        (Fraction(r, 1920), 1, "", b"") for r in read_times
    ], key=lambda e: (e[0], e[1]))
    got: dict[str, list[tuple[Fraction, int]]] = {">": [], "<": []}
    for t, kind, d, data in events:
        line.clock.advance_to(max(t, line.clock.exact))
        if kind == 0:
            (line.host if d == ">" else line.device).write(data)
        else:
            got[">"] += per_byte(line.device.read_timed(exact=True), CT)
            got["<"] += per_byte(line.host.read_timed(exact=True), CT)
    line.finish()
    got[">"] += per_byte(line.device.read_timed(until=10**6, exact=True), CT)
    got["<"] += per_byte(line.host.read_timed(until=10**6, exact=True), CT)
    assert got == want


def test_drain_prediction_matches_what_happens() -> None:
    line = SerialLine()
    line.device.write(b"ab\x13cd")
    line.clock.advance_to(Fraction(1, 960))
    predicted = line.host.write(b"0123456789")
    line.device.write(b"\x11", at=Fraction(1, 10))
    predicted_after = line.host.drain_time_exact()
    assert predicted == float("inf")
    runs = line.device.read_timed(until=5, exact=True)
    assert runs[-1][0] == predicted_after


def test_many_small_writes_stay_fast_and_exact() -> None:
    line = SerialLine()
    for _ in range(5000):
        line.host.write(b"abc")
    assert line.host.drain_time_exact() == 15000 * CT
    assert len(line.device.read(until=100)) == 15000


def test_a_write_between_uart_clock_ticks_starts_on_the_next_tick() -> None:
    line = SerialLine()  # 9600 baud: ticks of 1/(32 * 9600) s
    line.clock.advance_to(Fraction(1, 7))
    line.host.write(b"a")
    hz = 32 * 9600
    start = Fraction(-(-hz // 7), hz)  # ceil(hz / 7) / hz
    assert line.device.read_timed(until=1, exact=True) == [(start + CT, b"a")]
    assert line.ticks_per_second == hz


@settings(max_examples=60, deadline=None)
@given(writes_strategy, st.sampled_from([7, 11, 25, 1000]))
def test_schedule_with_unaligned_write_times(writes, denominator: int) -> None:
    hz = 32 * 9600
    timed = sorted(
        ((Fraction(t, denominator), d, data) for t, d, data in writes), key=lambda w: w[0]
    )
    quantized = [(Fraction(-(-t.numerator * hz // t.denominator), hz), d, b) for t, d, b in timed]
    want = simulate(CT, quantized)
    want.pop("drained")
    line = SerialLine()
    for t, d, data in timed:
        line.clock.advance_to(t)
        (line.host if d == ">" else line.device).write(data)
    line.finish()
    assert per_byte(line.device.read_timed(until=10**6, exact=True), CT) == want[">"]
    assert per_byte(line.host.read_timed(until=10**6, exact=True), CT) == want["<"]


def test_reading_ahead_of_the_clock_is_allowed() -> None:
    line = SerialLine()
    line.host.write(b"x" * 100)
    assert len(line.device.read(until=Fraction(1, 20))) == 48  # clock still at 0
    assert line.clock.exact == 0


def test_pacing_to_the_wall_clock_never_changes_what_arrives() -> None:
    """A session paced by a Throttle whose wall clock stutters arbitrarily receives exactly
    what the same session run flat out receives."""
    import random

    from camlab88.protocols.link import Throttle

    def session(throttle: Throttle) -> list[tuple[Fraction, bytes]]:
        line = SerialLine()
        got: list[tuple[Fraction, bytes]] = []
        for k in range(50):
            now = Fraction(k, 25)
            line.clock.advance_to(now)
            if k % 4 == 0:
                line.host.write(b"frame %d\r\n" % k)
            if k == 10:
                line.device.write(b"\x13")
            if k == 20:
                line.device.write(b"\x11")
            got += line.device.read_timed(exact=True)
            throttle.pace(now)
        return got

    rng = random.Random(3)
    wall = [0.0]

    def stutter() -> float:
        wall[0] += rng.choice([0.0, 0.001, 0.5, 2.0])
        return wall[0]

    def fake_sleep(dt: float) -> None:
        wall[0] += dt

    flat = session(Throttle(speed=None))
    paced = session(Throttle(speed=1.0, monotonic=stutter, sleep=fake_sleep))
    assert flat == paced and len(flat) > 5


def test_flow_events_to_an_idle_end_do_not_pile_up() -> None:
    line = SerialLine()
    for k in range(1000):
        line.clock.advance_to(Fraction(k, 100))
        line.device.write(b"\x13\x11")
        line.host.read()
    assert len(line._h2d.control) <= 2
    assert not line.host.paused
    line.host.write(b"go")
    assert line.device.read(until=20) == b"go"
