"""Hypothesis: the decoder and the terminal take any bytes, split anywhere, and stay bounded."""

from __future__ import annotations

import numpy as np
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from camlab88.emulator.sigma import Terminal
from camlab88.protocols.sigma import Decoder
from tests.sigma.streams import gks_plot, pgplot_plot

PGPLOT = pgplot_plot()
GKS = gks_plot()
# a byte alphabet rich in the characters that matter to the decoder
SIGMA_BYTES = st.sampled_from(list(b"+-*/\r\n\x1f\x1b\x00ZABCDEFGHIJKMO0123456789 @`~\x7f"))
FAST = settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])


def _bounded(d: Decoder) -> None:
    assert len(d._text) <= d.MAX_TEXT
    assert d._buf is None and d._xy is None  # nothing held between feeds but registers
    assert len(d._pair) < 8
    assert len(d.stats.unknown_codes) <= 64


@FAST
@given(st.binary(max_size=2000))
def test_decoder_never_raises_on_random_bytes(data: bytes) -> None:
    d = Decoder()
    d.feed(data)
    _bounded(d)
    d.feed(b"\r+-*/GA")  # and still resynchronises afterwards
    _bounded(d)


@FAST
@given(st.lists(SIGMA_BYTES, max_size=600).map(bytes), st.sampled_from(["t5684", "t5688"]))
def test_terminal_never_raises_on_order_like_noise(data: bytes, model: str) -> None:
    t = Terminal(model)
    t.feed(b"\r+-*/" + data)
    t.frame()
    _bounded(t.decoder)


def _mutate(data: bytes, ops: list[tuple[int, int, int]]) -> bytes:
    b = bytearray(data)
    for kind, pos, val in ops:
        pos %= max(len(b), 1)
        if kind == 0:
            b[pos] = val
        elif kind == 1:
            b.insert(pos, val)
        elif b:
            del b[pos]
    return bytes(b)


@FAST
@given(st.sampled_from([PGPLOT, GKS]),
       st.lists(st.tuples(st.integers(0, 2), st.integers(0, 10**6), st.integers(0, 255)),
                min_size=1, max_size=12),
       st.sampled_from(["t5684", "t5688"]))
def test_terminal_survives_mutated_driver_streams(base: bytes, ops, model: str) -> None:
    t = Terminal(model)
    t.feed(_mutate(base, ops))
    assert t.frame().shape == (512, 768, 3)
    _bounded(t.decoder)


@FAST
@given(st.sampled_from([PGPLOT, GKS]), st.lists(st.integers(1, 300), min_size=1, max_size=40))
def test_split_anywhere_gives_the_same_picture(base: bytes, cuts: list[int]) -> None:
    whole = Terminal("t5684")
    whole.feed(base)
    parts = Terminal("t5684")
    i = 0
    k = 0
    while i < len(base):
        step = cuts[k % len(cuts)]
        parts.feed(base[i:i + step])
        i += step
        k += 1
    assert np.array_equal(whole.planes, parts.planes)
    assert np.array_equal(whole.frame(), parts.frame())


@FAST
@given(st.lists(st.sampled_from(list(range(0x18, 0x80)) + [0x1F, 0x1B, 0x0D, 0x00, 0xC1]),
                max_size=400).map(bytes))
def test_compiled_ags_scanner_matches_the_protocol_definition(body: bytes) -> None:
    from camlab88.emulator.sigma.fast import scan_points_fast

    data = b"+-*/JH" + body
    plain, fast = Decoder(), Decoder(ags_scanner=scan_points_fast)
    assert plain.feed(data) == fast.feed(data)
    assert plain.stats == fast.stats
