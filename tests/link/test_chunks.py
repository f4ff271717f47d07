from __future__ import annotations

from fractions import Fraction

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from camlab88.protocols.link import LineSettings, SerialLine, chunks_by_period


def test_one_second_of_9600_baud_in_25ths() -> None:
    data = bytes(range(256)) * 4  # 1024 bytes: 1.0667 s
    chunks = list(chunks_by_period(data, LineSettings(), 0.04))
    # 960/25 = 38.4 characters per period: the boundaries fall exactly where they should.
    sizes = [len(c) for _, c in chunks]
    assert [k for k, _ in chunks] == list(range(27))
    assert sizes[:5] == [38, 38, 39, 38, 39]  # floor(38.4 k) differences
    assert sum(sizes[:25]) == 960  # byte 960 arrives at exactly 1 s: in period 24
    assert b"".join(c for _, c in chunks) == data


def test_empty_periods_are_yielded() -> None:
    chunks = list(chunks_by_period(b"ab", LineSettings(baud=110), 0.04))
    # 110 8N1: 1/11 s per character
    assert chunks == [(0, b""), (1, b""), (2, b"a"), (3, b""), (4, b"b")]


def test_empty_stream_yields_nothing_and_bad_period_is_rejected() -> None:
    assert list(chunks_by_period(b"", LineSettings(), 0.04)) == []
    with pytest.raises(ValueError):
        list(chunks_by_period(b"x", LineSettings(), 0))


@settings(max_examples=60, deadline=None)
@given(
    st.binary(min_size=1, max_size=300),
    st.sampled_from(["9600 8N1", "1200 7E2", "110 8N1.5", "19200 8O1"]),
    st.sampled_from([Fraction(1, 25), Fraction(1, 50), Fraction(1, 7), Fraction(1, 960)]),
)
def test_chunks_agree_with_reading_a_line_each_period(
    data: bytes, framing: str, period: Fraction
) -> None:
    s = LineSettings.parse(framing)
    data = bytes(b & s.data_mask for b in data if b & s.data_mask not in (0x11, 0x13))
    line = SerialLine(s)
    line.host.write(data)
    for k, chunk in chunks_by_period(data, s, period):
        line.clock.advance_to((k + 1) * period)
        assert line.device.read() == chunk
