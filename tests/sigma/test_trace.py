"""The protocol trace changes nothing it watches: any bytes, traced, give the same screen and
counters as untraced; every warning the counters record is a trace line."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from camlab88.emulator.sigma import Terminal
from camlab88.emulator.sigma.trace import SigmaTracer

ORDERS = [b"\r+-*/", b"GI200200", b"GJ300300", b"JH 6s0\x1f", b"DJ12AF3Z", b"BAhi\r", b"BH",
          b"HI3", b"JG3F000", b"KQ1", b"JN1200", b"GH", b"IO", b"QQ", b"\x0c+-*/", b"B+-*/"]


@settings(max_examples=60, deadline=None)
@given(st.lists(st.one_of(st.sampled_from(ORDERS), st.binary(max_size=8)), max_size=30))
def test_tracing_changes_nothing_and_reports_every_problem(parts):
    data = b"".join(parts)
    plain, traced = Terminal(), Terminal()
    plain.feed(data)
    events = []
    tracer = SigmaTracer(traced, events.append)
    tracer.feed(data, 0.0, 1 / 960)
    assert np.array_equal(plain.frame(), traced.frame())
    same = ("unknown", "malformed", "errors", "bytes")  # "commands" counts pieces, not orders
    assert [plain.stats[k] for k in same] == [traced.stats[k] for k in same]
    s = traced.stats
    assert tracer.warnings == s["unknown"] + s["malformed"] + s["errors"]
    offsets = [ev.offset for ev in events]
    assert all(0 <= o < max(len(data), 1) for o in offsets)
    assert all(ev.time >= 0 for ev in events)
