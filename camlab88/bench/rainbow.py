"""``camlab88.Rainbow``: an emulated Cambridge Rainbow and a pad-library client on it, for
testing pad-library programs. Device time moves in 20 ms frames when ``run`` shows them."""

from __future__ import annotations

from camlab88.bench.machine_bench import MachineBench
from camlab88.emulator.machine import RainbowMachine
from camlab88.protocols.rainbow import KeyEvent, MouseEvent, RainbowClient, TabletEvent


class Rainbow(MachineBench):
    """A Rainbow workstation (docs/api.md, docs/rainbow.md).

    ``client`` is the pad library (protocols.rainbow.RainbowClient): create pads, map them,
    draw, set the LUT. ``strict_memory`` gives the relic's 512x256 video memory. With
    ``trace`` (the default) every command is kept in ``.trace``; ``strict`` raises
    ``camlab88.ProtocolError`` at the first refused command.
    """

    def __init__(self, *, strict_memory: bool = False, trace: bool = True,
                 strict: bool = False) -> None:
        super().__init__(RainbowMachine(strict_memory), trace, strict)

    @property
    def client(self) -> RainbowClient:
        """The pad-library client: every call is one frame of the command stream."""
        return self.machine.client

    def send(self, data: bytes) -> None:
        """Raw command-stream bytes (as a program on a socket would send them)."""
        self.machine.host.write(bytes(data))

    def run(self, seconds: float | None = None) -> int:
        """Show frames for ``seconds`` of device time (50 a second); None: one frame.
        Returns the number of frames shown."""
        if seconds is not None and seconds < 0:
            raise ValueError(f"cannot run backwards ({seconds} s)")
        return self.machine.tick(0.02 if seconds is None else seconds)

    @property
    def now(self) -> float:
        """Device time in seconds (20 ms a frame)."""
        return self.machine.now

    # ------------------------------------------------------------------ input
    def mouse(self, x: int, y: int, buttons: int = 0, button: int = 0,
              pressed: bool = False) -> None:
        """The mouse at screen (x, y) (y down); ``buttons`` LEFT=1 | MIDDLE=2 | RIGHT=4."""
        self.machine.post(MouseEvent(0, x, y, buttons, button, pressed))

    def key(self, key: str, char: str = "", pressed: bool = True) -> None:
        """A key on the keyboard (``key`` a name such as "a" or "return")."""
        self.machine.post(KeyEvent(0, key, char, pressed))

    def tablet(self, x: int, y: int, pressure: int = 0, buttons: int = 0,
               proximity: bool = True) -> None:
        """The tablet stylus at screen (x, y)."""
        self.machine.post(TabletEvent(0, x, y, pressure, buttons, proximity))
