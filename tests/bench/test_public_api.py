"""The public API: exactly camlab88.__all__, loaded lazily, usable from a fresh interpreter.
These tests import nothing but ``camlab88``'s public names and the plugin's fixtures."""

from __future__ import annotations

import numpy as np
import pytest

import camlab88
from camlab88 import ProtocolError, Rainbow, Sigma, TraceEvent
from tests.support.processes import fresh_python

BOX = b"\r+-*/HI2GI200200GJ600200600400200400200200BH"


def test_all_names_exactly_the_public_api():
    assert sorted(camlab88.__all__) == ["ProtocolError", "Rainbow", "RainbowRefused", "Sigma",
                                       "TraceEvent"]
    for name in camlab88.__all__:
        assert getattr(camlab88, name) is not None
    with pytest.raises(AttributeError, match="no attribute 'Terminal'"):
        camlab88.Terminal  # noqa: B018


def test_importing_camlab88_loads_no_device_code():
    code = ("import sys, camlab88; heavy = [m for m in ('numpy', 'emulator', 'numba') "
            "if m in sys.modules]; print(heavy)")
    assert fresh_python(code).strip() == "[]"


def test_sigma_draws_what_it_is_sent_and_traces_every_order(sigma, assert_no_protocol_errors):
    t = sigma.send(BOX)
    assert t == pytest.approx(len(BOX) / 960)
    assert not sigma.screen.any()  # nothing has arrived yet: time is virtual
    sigma.run()
    assert sigma.now >= t
    lit = np.argwhere(sigma.screen.any(axis=2))
    assert lit[:, 1].min() == 100 and lit[:, 1].max() == 500  # x 100..500
    assert lit[:, 0].min() == 511 - 300 and lit[:, 0].max() == 511 - 100  # y up
    assert_no_protocol_errors(sigma)
    pairs = [ev.args for ev in sigma.trace if ev.order == "pair"]
    assert pairs[0] == {"x": 100, "y": 100, "pen": "move"}
    assert pairs[1] == {"x": 500, "y": 100, "pen": "draw"}
    assert [ev.offset for ev in sigma.trace if ev.order in ("GI", "GJ")] == [8, 16]


def test_a_cursor_read_answers_up_the_line(sigma):
    sigma.send(b"\r+-*/GHBH+-*/GICECA484356CFHF")
    sigma.run()
    sigma.cursor(468, 356)
    sigma.key("A")
    sigma.run()
    assert sigma.received() == b"A468,356\r"
    assert sigma.received() == b""


def test_a_bad_order_is_a_trace_warning_naming_its_offset(sigma):
    sigma.send(b"\r+-*/GI200200QXGJ300300BH")
    sigma.run()
    (bad, *more) = sigma.problems
    assert bad.offset == 13 and bad.kind == "unknown" and "0x51" in bad.warning
    assert [p.offset for p in more] == [14]  # X is unknown too


def test_strict_raises_at_the_first_problem_with_where_and_what():
    sigma = Sigma(strict=True)
    sigma.send(b"\r+-*/JG3F0BH")  # JG wants 5 hex digits
    with pytest.raises(ProtocolError) as err:
        sigma.run()
    ev = err.value.event
    assert isinstance(ev, TraceEvent)
    assert ev.kind == "malformed" and ev.offset == 5
    assert "JG then index: 1 hex digit(s)" in ev.expected
    assert "byte 5 (t=" in str(err.value) and "b'\\r+-*/JG3F0BH'" in str(err.value)


def test_out_of_range_orders_are_warnings():
    sigma = Sigma()
    sigma.send(b"\r+-*/KQ1BH")  # a T5684 has no views
    sigma.run()
    assert [p.kind for p in sigma.problems] == ["out of range"]
    assert "T5688" in sigma.problems[0].expected


def test_sigma_state_round_trip_continues_identically():
    a = Sigma()
    a.send(BOX * 2)
    a.run(0.02)
    saved = a.save_state()
    b = Sigma()
    b.load_state(saved)
    a.run()
    b.run()
    assert np.array_equal(a.screen, b.screen) and a.now == b.now


def test_screenshot_writes_the_screen(sigma, tmp_path):
    from PIL import Image

    sigma.send(BOX)
    sigma.run()
    path = sigma.screenshot(tmp_path / "shot.png")
    assert np.array_equal(np.asarray(Image.open(path).convert("RGB")), sigma.screen)


def test_rainbow_client_draws_and_is_traced(rainbow, assert_no_protocol_errors):
    lib = rainbow.client
    pad = lib.create_pad(100, 50, 2)
    arc = lib.map(0, pad, 10, 20, priority=1)
    lib.set_lut(0, [(0, 0, 0), "#ff0000"])
    lib.clear(pad, 1)
    assert rainbow.run() == 1
    assert tuple(rainbow.screen[20, 10]) == (255, 0, 0)
    lib.move(arc, 400, 300)
    rainbow.run(0.1)
    assert tuple(rainbow.screen[300, 400]) == (255, 0, 0)
    assert rainbow.trace.orders() == ["create_pad", "map", "set_lut", "clear", "move"]
    assert rainbow.trace[1].args == {"arc": arc, "parent": 0, "child": pad, "x": 10, "y": 20,
                                     "priority": 1, "on": 1}
    assert_no_protocol_errors(rainbow)


def test_rainbow_refusals_are_warnings_or_strict_errors():
    loose = Rainbow()
    with pytest.raises(Exception, match="no node 42"):
        loose.client.destroy(42)
    assert loose.problems[0].kind == "refused" and loose.problems[0].order == "destroy"
    strict = Rainbow(strict=True)
    with pytest.raises(ProtocolError, match="byte 0 .*no node 42"):
        strict.client.destroy(42)


def test_rainbow_input_reaches_the_program(rainbow):
    rainbow.mouse(5, 6, buttons=1, button=1, pressed=True)
    rainbow.key("a", "a")
    events = rainbow.client.poll_events()
    assert [type(e).__name__ for e in events] == ["MouseEvent", "KeyEvent"]
    assert (events[0].x, events[0].y) == (5, 6)


def test_rainbow_state_round_trip(rainbow):
    pad = rainbow.client.create_pad(64, 64, 1)
    rainbow.client.map(0, pad)
    rainbow.client.set_lut(0, [(0, 0, 0), (1, 2, 3)])
    rainbow.client.clear(pad, 1)
    rainbow.run()
    other = Rainbow()
    other.load_state(rainbow.save_state())
    assert np.array_equal(other.screen, rainbow.screen) and other.now == rainbow.now
    assert other.client.create_pad(8, 8, 1) == pad + 1  # the client's ids carry on


def test_after_a_strict_error_the_sigma_carries_on_consistently():
    sigma = Sigma(strict=True)
    sigma.send(b"\r+-*/QGI200200GJ300300BH")
    with pytest.raises(ProtocolError, match="byte 5"):
        sigma.run()
    sigma.run()  # the rest of the stream was not lost
    plain = Sigma(trace=False)
    plain.send(b"\r+-*/QGI200200GJ300300BH")
    plain.run()
    assert np.array_equal(sigma.screen, plain.screen) and sigma.screen.any()
    assert sigma.stats["bytes"] == plain.stats["bytes"]
