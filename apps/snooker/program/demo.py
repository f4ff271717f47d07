"""A short snooker demo for the Rainbow: a break-off simulated, then replayed at 25 frames/s."""

from __future__ import annotations

from camlab88.apps.snooker.layout import break_off_direction
from camlab88.apps.snooker.program.program import Program
from camlab88.apps.snooker.session import Session
from camlab88.apps.snooker.table import CUE
from camlab88.protocols.rainbow.client import RainbowClient


def break_session(speed_m_s: float = 7.0) -> Session:
    s = Session.new_game()
    ux, uy = break_off_direction(s.table, s.balls)
    s.set_velocity(CUE, ux * speed_m_s, uy * speed_m_s)
    s.simulate_to_rest()
    return s


def play_break(client: RainbowClient, seconds: float = 4.0, speed_m_s: float = 7.0) -> int:
    """Replay the first `seconds` of a break at 25 frames/s; returns time frames shown."""
    s = break_session(speed_m_s)
    frames = s.timeline.time_frames[: max(1, round(seconds * s.table.frame_rate))]
    program = Program(client, s)
    program.play_positions([f.balls.pos for f in frames], [f.balls.on_table for f in frames])
    return len(frames)
