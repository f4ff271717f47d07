"""``camlab88.Sigma``: an emulated Sigma T5684/T5688 on its serial line, for testing host
programs. Time is virtual: nothing happens until ``run`` advances it."""

from __future__ import annotations

from camlab88.bench.machine_bench import MachineBench
from camlab88.emulator.machine import SigmaMachine
from camlab88.protocols.link import LineSettings, to_time


class Sigma(MachineBench):
    """A Sigma terminal at the end of a serial line (docs/api.md).

    ``model`` "t5684" (768x512, 16 colours) or "t5688" (256 colours, 1536x1024 area);
    ``baud`` the line speed (8N1). With ``trace`` (the default) every decoded order is kept
    in ``.trace``; ``strict`` raises ``camlab88.ProtocolError`` at the first unknown,
    malformed or out-of-range order.
    """

    def __init__(self, model: str = "t5684", baud: int = 9600, *, trace: bool = True,
                 strict: bool = False) -> None:
        super().__init__(SigmaMachine(model, LineSettings(baud=baud)), trace, strict)

    # ------------------------------------------------------------------ the line
    def send(self, data: bytes | str) -> float:
        """Host -> terminal: queue bytes on the line now (a str is sent as Latin-1).
        Returns the virtual time (s) at which the last byte will have arrived."""
        if isinstance(data, str):
            data = data.encode("latin-1")
        return self.machine.host.write(bytes(data))

    def write(self, data: bytes) -> int:
        """The Sigma as a port: a host program that writes to any object with ``write``
        (a serial port, a file) writes to the line this way. Returns ``len(data)``."""
        self.send(data)
        return len(data)

    def run(self, seconds: float | None = None) -> None:
        """Advance virtual time by ``seconds``, or (None) until the line is idle: every byte
        sent either way has arrived and the terminal has taken what it was sent."""
        m = self.machine
        if seconds is None:
            m.run_until(m.idle_time())
            m.tick()  # one more tick: the terminal takes the last bytes
        elif seconds < 0:
            raise ValueError(f"cannot run backwards ({seconds} s)")
        else:
            m.run_until(m.now + to_time(seconds))

    @property
    def now(self) -> float:
        """Virtual seconds since power-on."""
        return float(self.machine.now)

    # ------------------------------------------------------------------ local input
    def key(self, char: str) -> None:
        """A key struck on the terminal's keyboard: a character, or a key's name
        (``"up"``, ``"f2"``: camlab88.protocols.sigma.keyboard); ends a cursor read, else
        goes up the line."""
        self.machine.press(char)

    def cursor(self, x: int, y: int) -> None:
        """Move the crosshair with the joystick to drawing-area (x, y) (device units, y up)."""
        self.machine.cursor(x, y)

    def tablet(self, x: int, y: int, pressed: bool = False) -> None:
        """The stylus at screen (x, y) (device units, y up); a press ends a cursor read."""
        self.machine.tablet(x, y, pressed)

    # ------------------------------------------------------------------ state
    @property
    def stats(self) -> dict[str, int]:
        """Bytes and orders decoded; unknown, malformed and impossible orders skipped."""
        return dict(self.machine.stats)
