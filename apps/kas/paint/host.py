"""The painting program as a host on its port (thesis §3.3): what the user's mouse and keys
do (the key map, clicks on chains and swatches), the script taken a command at a time when
the line has drained, and the replay's frames as the harness's ticks.  The harness target
(emulator.harness.sigma_host) runs the machine; these only write to the port."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from camlab88.apps.kas.paint.replay import ReplayHost
from camlab88.protocols.link.port import HostPort

KEYS = ("click: select chain / pick swatch; f fill, l colour lines, r region, t touch at the "
        "pointer, c clear; r/g/b (+shift) RGB steps; w painting, m mixing, p preview; , . "
        "frames; a auto-paint (saved at the end)")


class PaintHost:
    """The painting session on its port: window input at once, the next script command
    when the line has drained; ``done`` once the script has played and the line is quiet
    (with ``end``)."""

    def __init__(self, session, port: HostPort, commands: list, end: bool) -> None:
        self.session, self.port, self.commands, self.end = session, port, list(commands), end
        self.messages: list[str] = []
        self.at = (0, 0)  # the pointer, device pixels (y up)
        self.on_input: Callable[[Any], None] | None = None  # told each script command run
        self._send(session.start())

    def _send(self, data: bytes) -> None:
        if data:
            self.port.write(data)

    def _do(self, fn: Callable[[], bytes]) -> None:
        try:
            self._send(fn())
        except ValueError as exc:
            self.session.message = str(exc)
        if self.session.message:
            self.messages.append(self.session.message)
            self.session.message = ""

    # ------------------------------------------------------------ the user's hand
    def pointer(self, x: int, y: int) -> None:
        self.at = (x, y)

    def click(self) -> None:
        self._do(self._click)

    def key(self, key: str, shift: bool) -> None:
        self._do(lambda: self._key(key, shift))

    def _click(self) -> bytes:
        s = self.session
        k = s.swatch_at(*self.at)
        if k is not None:
            return s.pick(k)
        at = s.area_point(*self.at)
        return s.select_near(*at) if at else b""

    def _key(self, key: str, shift: bool) -> bytes:
        s = self.session
        at = s.area_point(*self.at)
        guns = {"r": "red", "g": "green", "b": "blue"}
        acts = {"f": s.fill, "l": s.colour_lines, "c": s.clear,
                "w": lambda: s.show("painting"), "m": lambda: s.show("mixing"),
                "p": lambda: s.show("preview"), "a": lambda: self._auto(),
                ",": lambda: s.goto(max(s.n - 1, 1)),
                ".": lambda: s.goto(min(s.n + 1, len(s.seq.frames)))}
        if key in guns and s.view != 1:
            return s.rgb(guns[key], -8 if shift else 8)
        if key in ("r", "t") and at:
            return s.region(*at) if key == "r" else s.touch(*at)
        return acts[key]() if key in acts else b""

    def _auto(self) -> bytes:
        fails = self.session.autopaint()
        self.session.message = f"auto-paint: {len(fails)} operation(s) could not apply"
        self.messages += [str(f) for f in fails]
        return b""

    # ------------------------------------------------------------ the harness's ticks
    def step(self) -> bool:
        from camlab88.apps.kas.paint import script

        if self.port.drained() and self.commands:
            cmd = self.commands.pop(0)
            if self.on_input is not None:
                self.on_input(cmd)
            self._do(lambda: script.run(self.session, cmd))
        return True

    def done(self) -> bool:
        return self.end and not self.commands and self.port.drained()

    def status(self) -> str:
        s = self.session
        return f"frame {s.n} of {len(s.seq.frames)}"


class ReplayFrames:
    """``kas paint --replay`` on the harness: one tick = one painted frame, drawn into the
    hidden buffer and then shown (the target runs the line until it is quiet, so a window
    plays at the speed of the 9600-baud line)."""

    def __init__(self, program, port: HostPort) -> None:
        self.host = ReplayHost(program, port)  # the set-up and the first frame
        self.port = port

    def step(self) -> bool:
        if self.host.finished and self.port.drained():
            return False
        self.host.step()
        return True

    def status(self) -> str:
        return f"frame {self.host.shown} of {len(self.host.frames)}"
