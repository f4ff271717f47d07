"""The emulated tablet device: events in, the real protocol's bytes out through a pty.

Any program can open ``slave_path`` with pyserial as if it were the tablet's serial port; the
tablet answers the host's queries (Wacom ``~#``/``~C``/``~R``, Summagraphics ``a``/``z?``,
CalComp ``ESC%VS``) and honours stream/prompt/stop commands the way its encoder models them.
"""

from __future__ import annotations

import threading
import time
from collections.abc import Mapping
from dataclasses import replace

from camlab88.protocols.link.pty import PtyPort
from camlab88.protocols.tablets import wacom4
from camlab88.protocols.tablets.base import ProtocolError
from camlab88.protocols.tablets.events import TabletEvent, TabletModel
from camlab88.protocols.tablets.registry import make_encoder, resolve


class EmulatedTablet:
    def __init__(
        self,
        protocol: str = "summa-mm",
        options: Mapping[str, str] | None = None,
        port: PtyPort | None = None,
    ) -> None:
        spec, merged = resolve(protocol, options)
        self.protocol = spec.name
        self.line = spec.line
        self.encoder = make_encoder(protocol, options)
        self.port = port if port is not None else PtyPort()
        self._host = b""  # unfinished host command bytes
        self.commands: list[bytes] = []  # every command the host sent, for inspection
        self.sent_events = 0
        self.refused = 0  # events the protocol cannot express (see _encode)
        self.last_refusal = ""
        self.last: TabletEvent | None = None
        # follows what it is sent but writes nothing (a loaded session run again: what it
        # sent then is on the state's tape)
        self.muted = False
        self._lock = threading.Lock()  # the window loop sends while a thread answers the host
        self._thread: threading.Thread | None = None
        self._stop = threading.Event()
        startup = self.encoder.startup()
        if startup:
            self.port.write(startup)

    @property
    def model(self) -> TabletModel:
        """The tablet as currently set up (host commands such as Summagraphics ``b`` change
        where its origin is)."""
        return self.encoder.model

    def assume_initialised(self) -> None:
        """Put the tablet in the state our start-up sequence leaves it in, without the host
        sending it (for a reader opened with ``init=0``); the replies are discarded."""
        data = b"".join(step.data for step in self.line.init)
        if self.protocol == "wacom4":  # then the model's setup string, as after ``~#``
            data += wacom4.parse_model_reply(self.encoder.identity).setup_string
        with self._lock:
            commands, _ = self.encoder.split_commands(data)
            for command in commands:
                self.encoder.answer(command)

    @property
    def slave_path(self) -> str:
        return self.port.slave_path

    @property
    def streaming(self) -> bool:
        return bool(getattr(self.encoder, "streaming", True))

    def send(self, event: TabletEvent) -> bytes:
        """Report one pointer state (if the tablet is streaming or was prompted)."""
        self.service()
        with self._lock:
            return self._send_locked(event)

    def repeat(self) -> bytes:
        """Stream mode: a tablet keeps reporting while the pen is in proximity, even held
        still (the host's silence detection relies on it)."""
        last = self.last
        if last is None or not last.proximity:
            return b""
        return self.send(last)

    def _send_locked(self, event: TabletEvent) -> bytes:
        if self.port.closed:
            return b""
        self.last = event
        prompted = getattr(self.encoder, "prompted", 0)
        if not self.streaming and not prompted:
            return b""
        if prompted:
            self.encoder.prompted = prompted - 1
        data = self._encode(event)
        if data and not self.muted:
            self.port.write(data)
            self.sent_events += 1
        return data

    def _encode(self, event: TabletEvent) -> bytes:
        """Encode, never raising: a running device must not fall over on a mouse chord.

        Formats that carry one button at a time (Summagraphics codes, Bit Pad digits) report
        the lowest button held; a stylus whose format reads button 2 as "eraser" (Wacom IV)
        gets the middle mouse button as its barrel button; anything else the format cannot
        say is refused and counted."""
        attempts = [event]
        lowest = event.buttons & -event.buttons
        if lowest and lowest != event.buttons:
            attempts.append(replace(event, buttons=lowest))
        if event.buttons & 4 and event.tool == "pen":
            attempts.append(replace(event, buttons=event.buttons & ~4 | 2))
        reason = ""
        for attempt in attempts:
            try:
                return self.encoder.encode(attempt)
            except ProtocolError as exc:
                reason = str(exc)
        self.refused += 1
        self.last_refusal = reason
        return b""

    def service(self, timeout: float = 0.0) -> list[bytes]:
        """Read and answer host commands; returns the commands handled."""
        if timeout:
            time.sleep(timeout)  # poll, so the lock is never held while waiting
        with self._lock:
            if self.port.closed:
                return []
            return self._service_locked()

    def _service_locked(self) -> list[bytes]:
        data = self.port.read(4096, 0.0)
        if not data:
            return []
        commands, self._host = self.encoder.split_commands(self._host + data)
        for command in commands:
            self.commands.append(command)
            reply = self.encoder.answer(command)
            if reply:
                self.port.write(reply)
        return commands

    def serve_in_background(self, period: float = 0.01) -> None:
        """Answer host commands from a thread (while a host on this process waits for them)."""
        if self._thread is not None:
            return

        def loop() -> None:
            while not self._stop.is_set():
                self.service(period)

        self._thread = threading.Thread(target=loop, name="emulated-tablet", daemon=True)
        self._thread.start()

    def close(self) -> None:
        """Unplug: the program on the other end sees the port hang up."""
        self._stop.set()
        if self._thread is not None:
            self._thread.join(timeout=2.0)
            self._thread = None
        with self._lock:
            self.port.close()

    def __enter__(self) -> EmulatedTablet:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()
