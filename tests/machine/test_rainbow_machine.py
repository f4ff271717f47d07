"""The Rainbow machine as every Rainbow program's one assembly: recording as an option, the
frame shown, a replay on a fresh machine, a program run's saved Rainbow (session_state)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from camlab88.emulator.machine import MachineStateError, RainbowMachine
from camlab88.protocols.rainbow import KeyEvent, MouseEvent, RainbowRefused


def _draw(m: RainbowMachine) -> int:
    c = m.client
    pad = c.create_pad(64, 32, 4)
    c.map(0, pad, 10, 10)
    c.set_lut(0, [(0, 0, 0), (200, 30, 30)])
    c.clear(pad, 1)
    c.wait_frame()
    return pad


def test_recording_is_a_machine_option_and_holds_calls_replies_and_input() -> None:
    assert RainbowMachine().recording is None
    m = RainbowMachine(record=True)
    _draw(m)
    m.post(KeyEvent(0, "a", "a", True))
    kinds = [d for d, _ in m.recording.entries]
    assert kinds[:2] == [">", "<"] and kinds[-1] == "i" and kinds.count(">") == 5
    again = RainbowMachine()
    result = again.replay(m.recording)
    assert result.mismatches == [] and result.commands == 5 and result.events == 1
    assert np.array_equal(again.frame(), m.frame())


def test_shown_is_the_last_frame_waited_for_and_on_frame_is_told_it() -> None:
    seen = []
    m = RainbowMachine(on_frame=seen.append)
    assert m.shown().shape == (576, 768, 3)  # before any frame: the screen as it stands
    _draw(m)
    assert len(seen) == 1 and seen[0] is m.shown() and m.frame_count == 1
    assert tuple(m.shown()[20, 20]) == (200, 30, 30) and m.compiles >= 1


def test_a_client_call_is_a_whole_frame_whatever_the_byte_stream_holds() -> None:
    m = RainbowMachine()
    m.host.write(b"\x01")  # half a frame on the stream port
    assert m.client.create_pad(8, 8, 1) == 1  # answered on its own
    with pytest.raises(RainbowRefused, match="at byte 0"):
        m.client.destroy(99)


def test_a_saved_program_run_continues_on_another_machine() -> None:
    m = RainbowMachine()
    pad = _draw(m)
    m.post(MouseEvent(0, 5, 6, 0))
    other = RainbowMachine()
    other.check_session_state(m.session_state())()
    assert np.array_equal(other.frame(), m.frame())
    assert other.client.create_pad(8, 8, 1) == pad + 1  # the client's ids carry on
    assert other.client.poll_events() == m.client.poll_events()


def test_a_damaged_session_state_changes_nothing() -> None:
    from camlab88.emulator.machine.state_file import pack, unpack

    m = RainbowMachine()
    _draw(m)
    head, blobs = unpack(m.session_state(), "rainbow-session")
    head["client"] = [1, -2, 3]
    other = RainbowMachine()
    before = other.frame().copy()
    with pytest.raises(MachineStateError, match="client ids"):
        other.check_session_state(pack("rainbow-session", head, blobs))
    assert np.array_equal(other.frame(), before)


def test_a_scene_file_is_built_on_the_machine_and_its_errors_come_from_it(tmp_path) -> None:
    """``rainbow render`` reaches the device through the machine: a scene's pad graph built
    on it, the band-structure frame agreeing with the per-pixel reference, the bands as
    text, and a bad file refused with the machine's SceneError naming it."""
    from camlab88.emulator.machine import SceneError

    scene = Path(__file__).resolve().parents[1] / "data" / "rainbow" / "golden_scene.json"
    machine = RainbowMachine()
    blank = machine.frame().copy()
    machine.load_scene(scene)
    frame = machine.frame()
    assert not np.array_equal(frame, blank)
    assert np.array_equal(frame, machine.reference())
    assert machine.bands_text().strip()
    bad = tmp_path / "bad.json"
    bad.write_text('{"nodes": [')
    with pytest.raises(SceneError, match="bad.json"):
        RainbowMachine().load_scene(bad)
