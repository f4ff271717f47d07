"""Save / load state: exact continuation from a save at ANY byte of a stream, and its errors."""

from __future__ import annotations

import json

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from camlab88.emulator.sigma import Terminal
from camlab88.emulator.sigma.state import MAGIC
from tests.sigma.streams import gks_plot, pgplot_plot


def _chained(model: str, data: bytes) -> tuple[Terminal, Terminal]:
    """(uninterrupted, saved-and-reloaded into a fresh terminal before EVERY byte)."""
    ref = Terminal(model)
    ref.feed(data)
    t = Terminal(model)
    for k in range(len(data)):
        saved = t.save_state(compress=k % 16 == 0)  # deflating every state would be slow
        t = Terminal(model)
        t.load_state(saved)
        t.feed(data[k:k + 1])
    return ref, t


STREAMS = {
    "gks": lambda model: gks_plot(high_res=model == "t5688"),
    "pgplot": lambda model: pgplot_plot(),
    # abbreviated mode, DJ runs, BA text, a cursor prompt and 4-digit pairs in one stream
    "mixed": lambda model: (b"\r+-*/GHIODAHI3GIJH" + b" `!@ \x7fa#A$B\x1fDJ12AB3Z"
                            b"GI01000100BAHELLO\rJH8BZ#d 8i\x1b M924\x1f  GJ01500150"
                            b"DJ5F0BH+-*/IPHI2GI100100GJ300300"),
}


@pytest.mark.parametrize("model", ["t5684", "t5688"])
@pytest.mark.parametrize("stream", sorted(STREAMS))
def test_save_at_every_byte_continues_to_the_same_picture(model: str, stream: str) -> None:
    data = STREAMS[stream](model)
    ref, t = _chained(model, data)
    assert np.array_equal(ref.planes, t.planes)
    assert np.array_equal(ref.frame(), t.frame())
    assert ref.reg == t.reg and ref.errors == t.errors
    a, b = ref.decoder.get_state(), t.decoder.get_state()
    # the command count depends on how the bytes were split (one AgsPoints per feed)
    a["stats"].pop("commands")
    b["stats"].pop("commands")
    assert a == b


def test_partial_state_is_saved_and_restored() -> None:
    t = Terminal("t5688")
    t.feed(b"+-*/IOJH8i#c")  # mid-way through an abbreviated point, 4-digit coordinates
    s = t.decoder.get_state()
    u = Terminal("t5688")
    u.load_state(t.save_state())
    assert u.decoder.get_state() == s
    assert s["mode"] == "ags" and s["ags"][5] > 0 and s["coord_digits"] == 4


def _edit(saved: bytes, fn) -> bytes:
    off = len(MAGIC)
    n = int.from_bytes(saved[off:off + 4], "big")
    header = json.loads(saved[off + 4:off + 4 + n])
    fn(header)
    head = json.dumps(header).encode()
    return MAGIC + len(head).to_bytes(4, "big") + head + saved[off + 4 + n:]


def test_load_state_errors_are_clear() -> None:
    t = Terminal("t5684")
    with pytest.raises(ValueError, match="bad magic"):
        t.load_state(b"nonsense")
    saved = Terminal("t5688").save_state()
    with pytest.raises(ValueError, match="is for t5688"):
        t.load_state(saved)
    with pytest.raises(ValueError, match="corrupt"):
        t.load_state(t.save_state()[:-40])
    good = t.save_state()
    with pytest.raises(ValueError, match="unknown register 'pen_colour'"):
        t.load_state(_edit(good, lambda h: h["registers"].update(pen_colour=3)))
    with pytest.raises(ValueError, match="register 'colour' is missing"):
        t.load_state(_edit(good, lambda h: h["registers"].pop("colour")))
    with pytest.raises(ValueError, match="'pen_x'"):
        t.load_state(_edit(good, lambda h: h["registers"].update(pen_x="12")))
    with pytest.raises(ValueError, match="unknown decoder state entry 'bogus'"):
        t.load_state(_edit(good, lambda h: h["decoder"].update(bogus=1)))
    with pytest.raises(ValueError, match="'spec'"):
        t.load_state(_edit(good, lambda h: h["decoder"].update(spec="ZZ")))
    with pytest.raises(ValueError, match="'text'"):
        t.load_state(_edit(good, lambda h: h["decoder"].update(text="x" * 1000)))
    with pytest.raises(ValueError, match="version 9"):
        t.load_state(_edit(good, lambda h: h.update(version=9)))
    t.load_state(good)  # a refused state left the terminal usable


ORDERISH = st.sampled_from(list(b"+-*/\r\n\x1f\x1b\x00ZABCDEFGHIJKMOQ0123456789 @`~\x7f"))


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(ORDERISH, max_size=400).map(bytes), st.integers(0, 400))
def test_save_anywhere_in_noise_continues_identically(data: bytes, cut: int) -> None:
    """Order-like noise: whatever the decoder holds at the cut survives save/load."""
    data = b"\r+-*/" + data
    cut = min(cut, len(data))
    ref = Terminal("t5684")
    ref.feed(data)
    a = Terminal("t5684")
    a.feed(data[:cut])
    b = Terminal("t5684")
    b.load_state(a.save_state())
    b.feed(data[cut:])
    assert np.array_equal(ref.planes, b.planes) and ref.reg == b.reg
    s, u = ref.decoder.get_state(), b.decoder.get_state()
    s["stats"].pop("commands")
    u["stats"].pop("commands")
    assert s == u
