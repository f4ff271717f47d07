"""One fuzz target per decoder or parser: bytes in, the format's own error or a result out.

Each target feeds the bytes to the same reader the command line uses (through
``camlab88.base.textinput`` for text formats, as the file readers do). A target passes when the
reader returns or raises the format's documented error (a ValueError subclass naming the
input); any other exception — a traceback for the user — is a finding. docs/reliability.md
lists what each format promises.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

CORPUS = Path(__file__).parent / "corpus"
NAME = "<fuzz>"


@dataclass(frozen=True)
class Target:
    name: str  # also the corpus directory's name
    run: Callable[[bytes], object]
    errors: tuple[type[BaseException], ...] = (ValueError,)

    @property
    def corpus(self) -> Path:
        return CORPUS / self.name

    def seeds(self) -> list[bytes]:
        return [p.read_bytes() for p in sorted(self.corpus.glob("*")) if p.is_file()]

    def check(self, data: bytes) -> None:
        """Run one input; an expected error is swallowed, anything else propagates."""
        try:
            self.run(data)
        except self.errors:
            pass


def _text(data: bytes) -> str:
    from camlab88.base.textinput import decode_utf8

    return decode_utf8(data, NAME, bom=True)


def _scene(data: bytes) -> object:
    from camlab88.base.textinput import loads_json
    from camlab88.emulator.rainbow.scene import SceneError, build_scene

    return build_scene(loads_json(_text(data), NAME, SceneError), None, NAME)


def _rainbow_error() -> type[BaseException]:
    from camlab88.emulator.rainbow.errors import RainbowError  # the command line reports these too

    return RainbowError


def _rainbow_recording(data: bytes) -> object:
    from camlab88.protocols.rainbow.recording import Recording

    return _via_file(data, Recording.load)


def _via_file(data: bytes, reader: Callable[[str], object], suffix: str = "") -> object:
    """For readers that only take a path: one scratch file per process, rewritten."""
    import os
    import tempfile

    path = _SCRATCH.get(suffix)
    if path is None:
        folder = "/dev/shm" if os.path.isdir("/dev/shm") else None
        fd, path = tempfile.mkstemp(prefix="camlab88-fuzz-", suffix=suffix, dir=folder)
        os.close(fd)
        _SCRATCH[suffix] = path
    with open(path, "wb") as fh:
        fh.write(data)
    return reader(path)


_SCRATCH: dict[str, str] = {}


def _link(data: bytes) -> object:
    from camlab88.protocols.link.recording import parse_recording

    return parse_recording(_text(data), NAME)


def _sigma_stream(data: bytes) -> object:
    term = _terminal()
    term.power_on()
    term.feed(data)
    return term.stats


_TERMINALS: list = []


def _terminal():  # emulator.sigma.Terminal
    if not _TERMINALS:
        from camlab88.emulator.sigma import Terminal

        _TERMINALS.append(Terminal("T5684"))
    return _TERMINALS[0]


def _sigma_state(data: bytes) -> object:
    from camlab88.emulator.sigma import state

    return state.load(_terminal(), data)


def _kas(kind: str) -> Callable[[bytes], object]:
    def run(data: bytes) -> object:
        from camlab88.apps.kas import files

        return getattr(files, f"parse_{kind}")(_text(data), NAME)
    return run


def _snooker_session(data: bytes) -> object:
    from camlab88.apps.snooker.session import Session, SessionError
    from camlab88.base.textinput import loads_json

    return Session.from_json(loads_json(_text(data), NAME, SessionError))


def _snooker_checkpoint(data: bytes) -> object:
    from camlab88.apps.snooker import checkpoint

    return _via_file(data, checkpoint.read, ".cp")


def _ca_pattern(suffix: str) -> Callable[[bytes], object]:
    def run(data: bytes) -> object:
        from camlab88.apps.ca.patterns import read_pattern

        return _via_file(data, read_pattern, suffix)
    return run


def _sigma_events(data: bytes) -> object:
    from camlab88.protocols.sigma.input_script import parse

    return parse(_text(data), NAME)


def _ca_rules(data: bytes) -> object:
    from camlab88.apps.ca.rules import parse_rules

    return parse_rules(_text(data), NAME)


def _ca_log(data: bytes) -> object:
    from camlab88.apps.ca.log import parse_log

    return parse_log(_text(data), NAME)


def _ca_checkpoint(data: bytes) -> object:
    from camlab88.apps.ca.log import parse_checkpoint

    return parse_checkpoint(_text(data), NAME)


def _hid(data: bytes) -> object:
    from camlab88.protocols.tablets.hid_descriptor import parse_descriptor

    return parse_descriptor(data, NAME)


def _tablet(protocol: str) -> Callable[[bytes], object]:
    def run(data: bytes) -> object:
        from camlab88.protocols.tablets.registry import make_parser

        parser = make_parser(protocol)
        return parser.feed(data) + parser.flush()
    return run


def _rainbow_stream(data: bytes) -> object:
    from camlab88.protocols.rainbow.stream import Decoder

    return Decoder().feed(data)


def _ccl(data: bytes) -> object:
    from camlab88.apps.snooker.camera.ccl import read_script
    from camlab88.apps.snooker.camera.parser import parse

    return _via_file(data, lambda path: parse(read_script(path)), ".ccl")


def _views(data: bytes) -> object:
    from camlab88.apps.snooker.camera.views import read_views

    return _via_file(data, read_views, ".views")


def _lights(data: bytes) -> object:
    from camlab88.apps.snooker.render.lights import read_lights

    return _via_file(data, read_lights, ".lights")


def _rainbow_script(data: bytes) -> object:
    from camlab88.protocols.rainbow.script import load

    return _via_file(data, load, ".events")


def _kas_script(data: bytes) -> object:
    from camlab88.apps.kas.program.script import load_timed_script

    return _via_file(data, load_timed_script, ".script")


def _kas_paint_ops() -> type[BaseException]:
    from camlab88.apps.kas.paint.opsfile import OpsFileError

    return OpsFileError


def _kas_ops(data: bytes) -> object:
    from camlab88.apps.kas.paint import opsfile

    return _via_file(data, opsfile.load, ".ops")


def _session_error() -> type[BaseException]:
    from camlab88.protocols.session.format import SessionFileError

    return SessionFileError


def _session(data: bytes) -> object:
    """Both ways a recording is read: whole, and streamed as a replay reads it (the two
    must agree on what they refuse, and the replay's second reading give the events,
    outside input and hashes the whole read holds)."""
    from camlab88.protocols.session.format import SessionFileError, read

    def both(path: str) -> object:
        try:
            whole = read(path)
        except SessionFileError as exc:
            try:
                read(path, traffic=False)
            except SessionFileError:
                raise exc from None
            raise AssertionError("the streamed read took what the whole read refused") from None
        streamed = read(path, traffic=False)
        again = list(streamed.timeline())
        for kind, held in (("event", whole.events), ("hash", whole.hashes),
                           ("wire", [w for w in whole.wire if w[1] in "+-"])):
            if [v for k, v in again if k == kind] != held:
                raise AssertionError(f"the replay's reading differs from the whole in {kind}s")
        return whole, streamed

    return _via_file(data, both, ".session")


def _tape_errors() -> tuple[type[BaseException], ...]:
    from camlab88.protocols.tablets.sources import SourceLost
    from camlab88.protocols.tablets.tape import TapeError

    return TapeError, SourceLost  # a "lost" entry replays as the device going away


def _tape(data: bytes) -> object:
    """A session's T record replayed as ``replay`` does: the entries checked, each opening's
    decoder rebuilt and fed the recorded bytes poll by poll."""
    from camlab88.protocols.tablets.tape import Tape, TapeSource, decoder_for, parse_chunk

    tape = Tape.from_chunks([data], NAME)
    source = None
    events = []
    for poll in sorted({entry[0] for entry in parse_chunk(data, NAME)}):
        tape.poll = poll
        opened = tape.opens_now()
        if opened is not None:
            source = TapeSource(tape, opened, decoder_for)
        if source is not None:
            events += source.read()
    return tape.calibration(), events


def _actors_error() -> type[BaseException]:
    from camlab88.apps.actors.model import ActorFileError

    return ActorFileError


def _actors(data: bytes) -> object:
    from camlab88.apps.actors.model import read_actors

    return _via_file(data, read_actors, ".actors")


_PROGRAMS: list = []


def _machine_state(data: bytes) -> object:
    from camlab88.emulator.machine import SigmaMachine

    return SigmaMachine("t5684").load_state(data)


def _program_state(data: bytes) -> object:
    """A CA program's declared state file: unpacked, its values checked against the
    program's schema and by the program (built, not put in place); refusals are
    ValueErrors (MachineStateError, StateValueError, the checkpoint reader's LogError)."""
    from camlab88.base.plainstate import decode
    from camlab88.emulator.machine.state_file import unpack

    if not _PROGRAMS:
        from camlab88.apps.ca.program.program import CAProgram, Options
        from camlab88.emulator.machine import RainbowMachine

        _PROGRAMS.append(CAProgram(RainbowMachine().client, Options(pattern="glider")))
    program = _PROGRAMS[0]
    head, parts = unpack(data, "program")
    values = decode(program.STATE_SCHEMA, head.get("values"), parts)
    return program.check_state_values(values)


def _cli_load_state(data: bytes) -> object:
    """An opened state (fuzz.states) packed again and given to the program it names through
    the real command line's ``--load-state``; any outcome but a clean run or a one-line
    refusal naming the file is a finding."""
    from fuzz import states

    path = _via_file(states.close_state(data), lambda p: p, ".c88state")
    program = states.program_of(data)
    code, err = states.load_state(program, Path(path), 60.0)
    found = states.verdict(Path(path), code, err)
    if found is not None:
        raise AssertionError(f"{program}: {found}")
    return code


TARGETS: dict[str, Target] = {t.name: t for t in (
    Target("rainbow-scene", _scene, (ValueError, _rainbow_error())),
    Target("rainbow-recording", _rainbow_recording),
    Target("rainbow-stream", _rainbow_stream),
    Target("link-recording", _link),
    Target("sigma-stream", _sigma_stream),
    Target("sigma-state", _sigma_state),
    *(Target(f"kas-{kind}", _kas(kind)) for kind in ("keyframe", "sequence", "path", "timing")),
    Target("snooker-session", _snooker_session),
    Target("snooker-checkpoint", _snooker_checkpoint),
    Target("ca-rules", _ca_rules),
    Target("ca-native", _ca_pattern(".pat")),
    *(Target(f"ca-{suffix}", _ca_pattern(f".{suffix}"))
      for suffix in ("rle", "cells", "mc", "lif", "life")),
    Target("ca-log", _ca_log),
    Target("ca-checkpoint", _ca_checkpoint),
    Target("hid-descriptor", _hid),
    Target("tablet-wacom4", _tablet("wacom4")),
    Target("tablet-summa", _tablet("summa-mm")),
    *(Target(f"tablet-{name}", _tablet(name)) for name in ("bitpad1", "bitpad2", "calcomp")),
    Target("snooker-ccl", _ccl),
    Target("snooker-views", _views),
    Target("render-lights", _lights),
    Target("rainbow-script", _rainbow_script),
    Target("kas-script", _kas_script),
    Target("sigma-events", _sigma_events),
    # the two below accept only their format's own error (every refusal names file:line:col)
    Target("kas-paint-ops", _kas_ops, (_kas_paint_ops(),)),
    Target("session-recording", _session, (_session_error(),)),
    Target("tablet-tape", _tape, _tape_errors()),
    Target("ca-actors", _actors, (_actors_error(),)),
    Target("machine-state", _machine_state),
    Target("program-state", _program_state),
    # a command's outcome, not a reader's error: nothing escaping main() is expected
    Target("cli-load-state", _cli_load_state, ()),
)}
