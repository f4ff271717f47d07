"""Whole machines: a state saved at any moment continues bit-identically in a fresh machine
(line with bytes in flight, clock, terminal / device), and a foreign state is refused."""

from __future__ import annotations

from fractions import Fraction

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from camlab88.emulator.machine import MachineStateError, RainbowMachine, SigmaMachine
from camlab88.emulator.machine.state_file import MAGIC
from tests.support.processes import fresh_python

PICTURE = (b"\r+-*/HI2GI200200GJ600200600400200400200200BHtext\r\n+-*/JH 6s0\x1fGIKQ1"
           b"HI5GI150150GJFHBG300300BH")


def _sigma_run(chunks: list[bytes], save_at: int | None) -> tuple[np.ndarray, bytes, float]:
    m = SigmaMachine()
    for k, chunk in enumerate(chunks):
        if k == save_at:
            fresh = SigmaMachine()
            fresh.load_state(m.save_state())
            m = fresh
        m.host.write(chunk)
        m.tick(Fraction(1, 200))
        if k % 3 == 0:
            m.terminal.key("x")  # something up the line, in flight when saved
    m.run_until(m.idle_time() + Fraction(1, 25))
    return m.frame(), m.host.read(), m.clock.now


@settings(max_examples=25, deadline=None)
@given(st.lists(st.integers(0, len(PICTURE)), min_size=1, max_size=6),
       st.binary(max_size=40), st.data())
def test_a_sigma_state_saved_anywhere_continues_bit_identically(cuts, noise, data):
    stream = PICTURE + noise + PICTURE  # random bytes too: half-read orders get saved
    cuts = sorted(set(cuts) | {0, len(stream)})
    chunks = [stream[a:b] for a, b in zip(cuts, cuts[1:])]
    save_at = data.draw(st.integers(0, len(chunks)))
    want = _sigma_run(chunks, None)
    got = _sigma_run(chunks, save_at)
    assert np.array_equal(want[0], got[0])
    assert want[1:] == got[1:]


def test_a_sigma_state_keeps_bytes_still_on_the_line():
    m = SigmaMachine()
    m.host.write(PICTURE)
    m.tick(Fraction(1, 100))  # ~10 of the bytes have arrived
    assert not m.host.drained()
    fresh = SigmaMachine()
    fresh.load_state(m.save_state())
    m.run_until(1)
    fresh.run_until(1)
    assert fresh.host.drained()
    assert np.array_equal(m.frame(), fresh.frame())
    assert fresh.terminal.stats == m.terminal.stats


def test_a_state_from_another_version_or_device_is_refused():
    state = SigmaMachine().save_state()
    n = int.from_bytes(state[len(MAGIC):len(MAGIC) + 4], "big")
    head = state[len(MAGIC) + 4:len(MAGIC) + 4 + n].replace(b'"format_version": 2',
                                                             b'"format_version": 9')
    bumped = MAGIC + len(head).to_bytes(4, "big") + head + state[len(MAGIC) + 4 + n:]
    with pytest.raises(MachineStateError, match="version 9; this camlab88 reads version 2"):
        SigmaMachine().load_state(bumped)
    with pytest.raises(MachineStateError, match="for a 'sigma', not a 'rainbow'"):
        RainbowMachine().load_state(state)
    with pytest.raises(MachineStateError, match="model"):
        SigmaMachine("t5688").load_state(state)
    with pytest.raises(MachineStateError, match="bad magic"):
        SigmaMachine().load_state(b"garbage")


def _rainbow_scene(m: RainbowMachine, step: int) -> None:
    c = m.client
    if step == 0:
        pad = c.create_pad(200, 100, 4, plane=0)
        c.map(0, pad, 50, 40, priority=1)
        c.set_lut(0, [(0, 0, 0), (250, 10, 10), (10, 250, 10)])
        c.clear(pad, 1)
    elif step == 1:
        c.line(1, 0, 0, 199, 99, 2)
        c.set_lut(2, ["#ffff00"])
    else:
        c.move(1, 60 + step, 40 + 2 * step)


@pytest.mark.parametrize("save_at", [0, 1, 2, 4])
def test_a_rainbow_state_saved_between_calls_continues_bit_identically(save_at):
    frames = []
    for saving in (False, True):
        m = RainbowMachine()
        for step in range(6):
            if saving and step == save_at:
                fresh = RainbowMachine()
                fresh.load_state(m.save_state())
                m = fresh
            _rainbow_scene(m, step)
            m.tick()
        frames.append(m.frame())
    assert np.array_equal(frames[0], frames[1])
    assert frames[0].any()


CONTINUE = """
import hashlib, sys
from camlab88.emulator.machine import SigmaMachine
m = SigmaMachine()
m.load_state(open(sys.argv[1], "rb").read())
m.host.write(b"GI100100GJ700500BH")
m.run_until(2)
print(hashlib.sha256(m.frame().tobytes()).hexdigest(), m.clock.exact, m.host.read().hex())
"""


def test_a_sigma_state_continues_identically_in_a_fresh_process(tmp_path):
    import hashlib

    m = SigmaMachine()
    m.host.write(PICTURE)
    m.tick(Fraction(3, 100))
    m.terminal.key("q")  # a key on its way up the line
    path = tmp_path / "state.bin"
    path.write_bytes(m.save_state())
    m.host.write(b"GI100100GJ700500BH")
    m.run_until(2)
    want = f"{hashlib.sha256(m.frame().tobytes()).hexdigest()} {m.clock.exact} " \
           f"{m.host.read().hex()}"
    assert fresh_python(CONTINUE, str(path)).strip() == want


def _file(head: dict, body: bytes) -> bytes:
    import json

    text = json.dumps(dict(head, device="sigma"), sort_keys=True).encode()
    return MAGIC + len(text).to_bytes(4, "big") + text + body


def test_the_state_file_reads_format_1_and_bounds_what_it_reads() -> None:
    """Format 1 (parts without their inflated length) is still read; a part claiming more
    than deflate gives, a zip bomb, a header nested too deep or a file too long is refused
    in one line before anything large is allocated."""
    import zlib

    from camlab88.emulator.machine import state_file

    part = zlib.compress(b"abc" * 1000, 1)
    head, blobs = state_file.unpack(_file({"format_version": 1, "blobs": [["p", len(part)]]},
                                          part), "sigma")
    assert blobs == {"p": b"abc" * 1000}
    bomb = zlib.compress(b"\0" * (8 << 20), 9)
    for entry, why in ((["p", len(bomb), 10], "longer than it says"),
                       (["p", len(bomb), 1 << 40], "claims"),
                       (["p", 3, 10**6], "claims")):
        data = _file({"format_version": 2, "blobs": [entry]},
                     bomb if entry[1] == len(bomb) else b"abc")
        with pytest.raises(MachineStateError, match=why) as exc:
            state_file.unpack(data, "sigma")
        assert "\n" not in str(exc.value)
    deep = _file({"format_version": 2, "blobs": [], "x": 0}, b"")
    n = int.from_bytes(deep[len(MAGIC):len(MAGIC) + 4], "big")
    text = deep[len(MAGIC) + 4:len(MAGIC) + 4 + n].replace(b'"x": 0', b'"x": ' + b"[" * 100000
                                                           + b"]" * 100000)
    with pytest.raises(MachineStateError, match="nested deeper than 64"):
        state_file.unpack(MAGIC + len(text).to_bytes(4, "big") + text, "sigma")
    with pytest.raises(MachineStateError, match="at most"):
        state_file.unpack(MAGIC + b"\0" * (state_file.MAX_FILE + 1), "sigma")
