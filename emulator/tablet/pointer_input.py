"""Pointer input for a program window: the configured tablet, or the mouse (the host-input
adapter beside the emulated tablet; used by the KAS fronts on the Sigma)."""

from __future__ import annotations


class TabletInput:
    """Pointer input for a program window: the configured tablet, or the mouse.

    ``source`` is a SOURCE string or None (mouse only).  With ``emulated:P`` the window's mouse
    drives the emulated tablet, whose bytes come back through its pty and the protocol parser
    -- the same path a real tablet takes.  Programs call :meth:`poll` once per frame with the
    window's mouse samples and get :class:`protocols.tablets.input_layer.PointerEvent`s in
    their working coordinates.
    """

    def __init__(self, source: str | None, area=None, notify=None) -> None:
        from protocols.tablets.calibration import load_calibration
        from protocols.tablets.input_layer import TWELVE_FIELD, InputLayer
        from protocols.tablets.sources import parse_source

        self._emu = None
        area = area or TWELVE_FIELD
        if source is None:
            self.layer = InputLayer(area, None, notify=notify)
            return
        spec = parse_source(source)
        calibration = load_calibration(spec.device_key)
        if spec.kind == "emulated":
            opened, reopen = self._open_emulated(spec)
        else:
            opened, reopen = _open_real(spec, source, notify)
        self.layer = InputLayer(area, opened, reopen=reopen, calibration=calibration,
                                notify=notify)

    def _open_emulated(self, spec):  # noqa: ANN001, ANN202
        """The emulated tablet on a pty, read back through its protocol parser like a real one."""
        from emulator.tablet import EmulatedTablet
        from protocols.tablets.serial_source import SerialSource
        from protocols.tablets.sources import SourceLost, parse_source

        options = {k: v for k, v in spec.options.items() if k != "drive"}
        self._emu = EmulatedTablet(spec.protocol, options)
        self._emu.assume_initialised()  # read with init=0: set up as our start-up would
        query = "".join(f"&{k}={v}" for k, v in options.items())  # tilt=1, flair=1, ...
        url = f"serial:{self._emu.slave_path}?protocol={spec.protocol}&init=0{query}"
        opened = SerialSource(parse_source(url))
        opened.name = spec.text

        def reopen():  # noqa: ANN202
            raise SourceLost("the emulated tablet does not come back")

        return opened, reopen

    def poll(self, mouse=()) -> list:
        if self._emu is not None and self.layer.active == "tablet":
            from emulator.tablet import pointer_to_tablet

            for m in mouse:
                self._emu.send(pointer_to_tablet(m.x, m.y, m.view_size, self._emu.model,
                                                 m.buttons))
            if not mouse:
                self._emu.repeat()  # a streaming tablet reports a still pen too
            return self.layer.poll((), timeout=0.0)
        return self.layer.poll(mouse)

    def close(self) -> None:
        self.layer.close()
        if self._emu is not None:
            self._emu.close()


def _open_real(spec, source: str, notify):  # noqa: ANN001, ANN202
    """A real tablet, or None (the mouse until it appears) when it is not there yet."""
    from protocols.tablets.sources import SourceLost, open_source

    def reopen():  # noqa: ANN202
        return open_source(spec)

    try:
        opened = open_source(spec)
    except SourceLost as exc:
        opened = None
        if notify:
            notify(f"{source}: {exc}; using the mouse until it appears")
    for note in getattr(opened, "size_notes", ()):
        if notify:
            notify(note)
    return opened, reopen
