"""Pointer input for a program window: the configured tablet, or the mouse (the host-input
adapter beside the emulated tablet; used by the KAS fronts on the Sigma).

Everything a tablet sends is noted on a tablet tape (``camlab88.protocols.tablets.tape``) at
the poll it was read: a session recorder (``record=True``) takes it through ``take_tape()``,
a save state through ``take_state_tape()``.  In a replay
(``camlab88.emulator.harness.replay.active()``) the tape recorded in the session is read
instead and the ``--tablet`` device is never opened.  While a load runs a saved session
again the session polls a ``stand_in`` fed from the state's tape; then this run's tablet
carries on from where the stand-in left the pointer (``carry_on_from``).
"""

from __future__ import annotations

from camlab88.emulator.tablet_input.taped import TapeKeeper


class TabletInput(TapeKeeper):
    """Pointer input for a program window: the configured tablet, or the mouse.

    ``source`` is a SOURCE string or None (mouse only).  With ``emulated:P`` the window's mouse
    drives the emulated tablet, whose bytes come back through its pty and the protocol parser
    -- the same path a real tablet takes.  Programs call :meth:`poll` once per frame with the
    window's mouse samples and get :class:`camlab88.protocols.tablets.input_layer.PointerEvent`s in
    their working coordinates.
    """

    def __init__(self, source: str | None, area=None, notify=None, record: bool = False) -> None:
        from camlab88.protocols.tablets.input_layer import TWELVE_FIELD, InputLayer
        from camlab88.protocols.tablets.sources import parse_source

        self._emu = None
        self.tape = None
        self._emulated = False
        self._has_device = source is not None
        self._replaying = False
        self._kept: list[list] | None = None  # a replay's tape entries, for a save state
        self.protocol: str | None = None  # what a state's tablet input must match
        self.area = area = area or TWELVE_FIELD
        if source is None:
            self.layer = InputLayer(area, None, notify=notify)
            return
        spec = parse_source(source)
        self.protocol = spec.protocol or spec.kind  # (a HID tablet describes itself)
        self._emulated = spec.kind == "emulated"
        from camlab88.emulator.tablet_input.taped import recorded_tape

        recorded = recorded_tape()
        if recorded is not None:
            self.tape, self._replaying, self._kept = recorded, True, []
            self.layer = _replay_layer(recorded, area, notify)
            return
        self.layer = self._live_layer(spec, source, area, notify, record)

    def _live_layer(self, spec, source: str, area, notify, record: bool):
        from camlab88.protocols.tablets.calibration import load_calibration
        from camlab88.protocols.tablets.input_layer import InputLayer
        from camlab88.protocols.tablets.tape import RecordingSource, TapeRecorder

        calibration = load_calibration(spec.device_key)
        if spec.kind == "emulated":
            opened, reopen = self._open_emulated(spec)
        else:
            opened, reopen = _open_real(spec, source, notify)
        # always on tape: a save state keeps it (and with --record, the recording)
        tape = self.tape = TapeRecorder(("state", "record") if record else ("state",))
        tape.note("calibration", None if calibration is None else {
            "device": calibration.device, **calibration.to_json()})
        opened = RecordingSource(opened, tape) if opened is not None else None

        def reopen_recorded():
            return RecordingSource(reopen(), tape)

        return InputLayer(area, opened, reopen=reopen_recorded, calibration=calibration,
                          notify=notify)

    def _open_emulated(self, spec):
        """The emulated tablet on a pty, read back through its protocol parser like a real one."""
        from camlab88.emulator.tablet import EmulatedTablet
        from camlab88.protocols.tablets.serial_source import SerialSource
        from camlab88.protocols.tablets.sources import SourceLost, parse_source

        options = {k: v for k, v in spec.options.items() if k != "drive"}
        self._emu = EmulatedTablet(spec.protocol, options)
        self._emu.assume_initialised()  # read with init=0: set up as our start-up would
        query = "".join(f"&{k}={v}" for k, v in options.items())  # tilt=1, flair=1, ...
        url = f"serial:{self._emu.slave_path}?protocol={spec.protocol}&init=0{query}"
        opened = SerialSource(parse_source(url))
        opened.name = spec.text

        def reopen():
            raise SourceLost("the emulated tablet does not come back")

        return opened, reopen

    def poll(self, mouse=()) -> list:
        try:
            if self._emulated and self.layer.active == "tablet":
                if self._emu is not None:
                    from camlab88.emulator.tablet import pointer_to_tablet

                    for m in mouse:
                        self._emu.send(pointer_to_tablet(m.x, m.y, m.view_size,
                                                         self._emu.model, m.buttons))
                    if not mouse:
                        self._emu.repeat()  # a streaming tablet reports a still pen too
                return self.layer.poll((), timeout=0.0)
            return self.layer.poll(mouse)
        finally:
            self._end_poll()

    @property
    def live(self) -> bool:
        """A tablet read as it happens (not the mouse, not a replay's tape)."""
        return self._has_device and not self._replaying

    @property
    def emulated(self) -> bool:
        return self._emulated

    def stand_in(self, entries: list | None, emulated: bool) -> TabletInput:
        """What the session polls while a load runs it again: the state's tape ``entries``
        decoded through the protocol parser as a replay decodes a recording's (``emulated``:
        the saved session's tablet was the emulated one, driven by the window's mouse; this
        run's emulated tablet then follows the mouse, saying nothing, so it is where the
        saved one was), or the mouse alone (``entries`` None: the saved session had no
        tablet). TapeError if the tape's calibration is not this run's."""
        from camlab88.protocols.tablets.tape import Tape, TapeError

        other = TabletInput(None, self.area)
        if entries is None:
            return other
        tape = Tape(entries, where="state.tablet.tape")
        calibration = self.layer.calibration
        saved = tape.calibration()
        mine = None if calibration is None else (tuple(calibration.top_left),
                                                 tuple(calibration.bottom_right))
        if (saved[1:] if saved else None) != mine:
            raise TapeError("state.tablet.tape: saved with another calibration of the "
                            "tablet than this run's (camlab88 tablet calibrate)")
        other.tape, other._replaying, other._has_device = tape, True, True
        other.protocol, other._emulated = self.protocol, emulated
        other.layer = _replay_layer(tape, self.area, None)
        other._tape_end = entries[-1][0] if entries else -1
        if emulated and self._emu is not None:
            other._emu = self._emu
            self._emu.muted = True
        return other

    def carry_on_from(self, other: TabletInput) -> None:
        """After a load: go on from where the stand-in ``other`` left the pointer, counting
        polls from its (a recording's tape entries go on from there); this run's tablet
        then says what it sends again. ValueError if the state's tape holds polls the
        session never reached."""
        if self._emu is not None:
            self._emu.muted = False
        self.layer.carry_on_from(other.layer)
        self._count_polls_on_from(other)
        if self._replaying and self.layer.source is None and self.tape.opens_now():
            # a recording begun from the state: its tablet was open from the start, so it
            # comes in here as it was, not as one back after a loss
            self.layer.source = self.layer.reopen()

    def close(self) -> None:
        self.layer.close()
        if self._emu is not None:
            self._emu.close()


def _replay_layer(tape, area, notify):
    """The input layer fed from the tape: reopened (inline, every poll) exactly at the polls
    where the recorded session got its tablet (back)."""
    from camlab88.protocols.tablets.calibration import Calibration
    from camlab88.protocols.tablets.input_layer import InputLayer
    from camlab88.protocols.tablets.sources import SourceLost
    from camlab88.protocols.tablets.tape import TapeSource, decoder_for

    cal = tape.calibration()
    calibration = None if cal is None else Calibration(*cal)

    def reopen():
        opened = tape.opens_now()
        if opened is None:
            raise SourceLost("not on the tape at this poll")
        return TapeSource(tape, opened, decoder_for)

    initial = reopen() if tape.opens_now() is not None else None
    return InputLayer(area, initial, reopen=reopen, calibration=calibration, retry_every=1,
                      notify=notify, spawn=lambda job: job())


def _open_real(spec, source: str, notify):
    """A real tablet, or None (the mouse until it appears) when it is not there yet."""
    from camlab88.protocols.tablets.sources import SourceLost, open_source

    def reopen():
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
