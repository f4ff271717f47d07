"""Write the seed corpus: valid files of every format, made by the project's own writers (or
copied from its library and test data), so the fuzzers start from inputs that go deep.
``python fuzz/make_corpus.py`` rewrites fuzz/corpus/; the result is committed."""

from __future__ import annotations

import shutil
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from fuzz.targets import CORPUS  # noqa: E402

CA_LIB = ROOT / "apps" / "ca" / "library"
KAS_LIB = ROOT / "apps" / "kas" / "library"
DATA = ROOT / "tests" / "data"


def _put(target: str, name: str, data: bytes | str) -> None:
    folder = CORPUS / target
    folder.mkdir(parents=True, exist_ok=True)
    (folder / name).write_bytes(data.encode() if isinstance(data, str) else data)


def _copy(target: str, *paths: Path) -> None:
    for p in paths:
        _put(target, p.name, p.read_bytes())


def _rainbow() -> None:
    from camlab88.emulator.machine import RainbowMachine
    from camlab88.protocols.rainbow.stream import encode

    _put("rainbow-scene", "small.json", '{"lut": [[0, "#000000"], [1, "#ff0000"]], "nodes": '
         '{"c": {"type": "cluster", "width": 64, "height": 32}, "p": {"type": "pad", "width": '
         '16, "height": 8, "depth": 1, "fill": 1}}, "arcs": [{"parent": "screen", "child": "c", '
         '"x": 5, "y": 6}, {"parent": "c", "child": "p", "priority": 1}]}')
    rb = RainbowMachine(record=True)
    c = rb.client
    pad = c.create_pad(32, 16, 4)
    c.map(0, pad, 10, 20)
    c.set_lut(0, ["#000000", "#00ff00"])
    c.rect(pad, 0, 0, 8, 8, 1)
    c.text(pad, 1, 1, "hi", 1)
    c.wait_frame()
    (CORPUS / "rainbow-recording").mkdir(parents=True, exist_ok=True)
    rb.recording.save(CORPUS / "rainbow-recording" / "session.rec")
    frames = b"".join(d for kind, d in rb.recording.entries if kind == ">")
    _put("rainbow-stream", "session.bin", frames)
    _put("rainbow-stream", "hello.bin", encode("hello"))


def _link_and_sigma() -> None:
    from camlab88.emulator.sigma import Terminal, state
    from camlab88.protocols.link import LineSettings, Recorder, SerialLine
    from camlab88.protocols.sigma.demo import (
        sigma_animation_stream,
        sigma_demo_stream,
        sigma_picture_stream,
    )

    stream = sigma_demo_stream()
    # the whole demo, and its two halves on their own: the animation half is 664 LUT orders,
    # so a mutation of the whole demo mostly lands in those; the picture half (955 bytes)
    # holds every other kind of order and costs a seventh as much to run
    _put("sigma-stream", "demo.sig", stream)
    _put("sigma-stream", "picture.sig", sigma_picture_stream())
    _put("sigma-stream", "animation.sig", sigma_animation_stream())
    (CORPUS / "link-recording").mkdir(parents=True, exist_ok=True)
    rec = Recorder(CORPUS / "link-recording" / "demo.rec", LineSettings(), xonxoff=True)
    line = SerialLine(LineSettings(), recorder=rec)
    line.host.write(stream[:600])
    line.device.write(b"\x13\x11")
    line.close()
    term = Terminal("T5684")
    term.feed(stream[: len(stream) // 2])
    _put("sigma-state", "half.state", state.save(term, compress=True))


def _kas() -> None:
    from camlab88.apps.kas import files
    from camlab88.apps.kas.model import AnimSequence

    a = files.load_keyframe(KAS_LIB / "walk_a.kas")
    b = files.load_keyframe(KAS_LIB / "walk_b.kas")
    _copy("kas-keyframe", KAS_LIB / "walk_a.kas", KAS_LIB / "sun_a.kas")
    _put("kas-sequence", "two.kas", files.sequence_text(AnimSequence([a, b], 25.0)))
    _copy("kas-path", KAS_LIB / "walk_path.kas")
    _copy("kas-timing", KAS_LIB / "walk_ticks.kas")


def _snooker() -> None:
    import json

    from camlab88.apps.snooker.session import Session

    _put("snooker-session", "new.json", json.dumps(Session.new_game().to_json()))
    _copy("snooker-checkpoint", DATA / "snooker" / "thesis_example.cp")


def _ca() -> None:
    from camlab88.apps.ca import log
    from camlab88.apps.ca.engine import Engine
    from camlab88.apps.ca.patterns import format_mc, read_pattern
    from camlab88.apps.ca.rules import load_rules

    _copy("ca-rules", CA_LIB / "life.rules", CA_LIB / "maze.rules",
          DATA / "ca" / "figure_7_6.rules")
    _copy("ca-native", CA_LIB / "maze_demo.pat")
    _copy("ca-rle", CA_LIB / "gosper_gun.rle", CA_LIB / "acorn.rle",
          DATA / "ca" / "lifewiki_style.rle")
    _copy("ca-cells", CA_LIB / "glider.cells")
    _copy("ca-actors", ROOT / "examples" / "ca" / "chess.actors")
    _put("ca-actors", "every_kind.actors", "rules maze\nactor 2 head\n colour 9 8 7\n material "
         "ambient 0.1 diffuse 0.9 specular 0 shininess 1\n lathe 0.4 0 0.1 0.5 size 1 2 1\n"
         " box 0.2 0.2 0.2 at 0 0 0.5\n sphere size 0.2 0.1 0.3\n extrude 0 0 1 0 0 1 "
         "height 0.2 at -0.5 -0.5 0\n bob 0.1 12\n turn -90 30\nend\n")
    _copy("ca-lif", DATA / "ca" / "golly" / "acorn.lif", DATA / "ca" / "golly" / "breeder.lif")
    _copy("ca-life", DATA / "ca" / "golly" / "acorn_106.life")
    _copy("ca-mc", DATA / "ca" / "golly" / "broken-lines.mc")
    _put("ca-mc", "wireworld.mc", "[M2]\n#R WireWorld\n1 0 3 3 1\n2 0 1 0 0\n3 2 0 2 2\n")
    _put("ca-mc", "gun.mc", format_mc(read_pattern(CA_LIB / "gosper_gun.rle")))
    rules = load_rules(str(CA_LIB / "life.rules"))
    glider = read_pattern(CA_LIB / "glider.cells")
    events = [log.ev_rules(0, "life", rules.text), log.ev_edit(0, 5, 5, 1),
              log.ev_load(0, "glider", 10, 10, "rot90", glider), log.ev_advance(3, None)]
    _put("ca-log", "session.log", log.format_log(events, True, log.LogSettings("wrap", 7)))
    engine = Engine(rules)
    engine.set_cells(*glider.placed(20, 20))
    _put("ca-checkpoint", "glider.cp", log.format_checkpoint(engine))


def _tablets() -> None:
    from camlab88.protocols.tablets.events import TabletEvent
    from camlab88.protocols.tablets.hid_descriptor import parse_hex_text
    from camlab88.protocols.tablets.registry import make_encoder

    for name, proto in (("tablet-wacom4", "wacom4"), ("tablet-summa", "summa-mm"),
                        ("tablet-bitpad1", "bitpad1"), ("tablet-bitpad2", "bitpad2"),
                        ("tablet-calcomp", "calcomp")):
        enc = make_encoder(proto)
        events = [TabletEvent(100 * k, 50 * k, True, k % 2) for k in range(1, 6)]
        _put(name, "stroke.bin", enc.startup() + b"".join(enc.encode(e) for e in events))
    # the three Wacom pens, and the pen+touch screens (finger collections beside the pen's)
    selftests = DATA / "tablets" / "linux-hid-selftests"
    hexes = [*sorted(selftests.glob("wacom_*.hex"))[:3], *sorted(selftests.glob("[!w]*.hex"))]
    for h in hexes:
        _put("hid-descriptor", h.stem + ".bin", parse_hex_text(h.read_text(), str(h)))


def _scripts_and_views() -> None:
    """Camera scripts, view and lights files, Rainbow and KAS input scripts (shipped files)."""
    _copy("snooker-ccl", DATA / "snooker_camera" / "thesis_example.ccl")
    _copy("snooker-views", DATA / "snooker_render" / "break.views")
    _put("render-lights", "two_bulbs.lights", "# x y z (m) and intensity, or r g b\n"
         "-0.9 -0.45 1.5 0.9\n0.9 0.45 1.5 1.0 0.95 0.85\n")
    _copy("rainbow-script", DATA / "snooker_camera" / "typo.events", ROOT / "examples" / "ca" /
          "session.events")
    _copy("kas-script", ROOT / "examples" / "kas" / "arc.script")
    _put("sigma-events", "every_kind.events", "# a cursor read answered, then typing\n"
         "0.5 key A\nreply cursor 468 356\nnext key return\n1.25 type hello # kept\n"
         "next tablet 100 200 down\nnext tablet 100 200 up\n")


def _kas_paint() -> None:
    """Operations files written by opsfile: one as the program saves it after auto-paint
    (every frame's seeds recorded), one with a frame's own touch-up operations."""
    from camlab88.apps.kas import files
    from camlab88.apps.kas.inbetween import inbetween
    from camlab88.apps.kas.paint import opsfile
    from camlab88.apps.kas.paint.ops import Op, OpsFile
    from camlab88.apps.kas.paint.palette import Palette
    from camlab88.apps.kas.paint.session import PaintSession

    seq = inbetween(files.load_keyframe(KAS_LIB / "walk_a.kas"),
                    files.load_keyframe(KAS_LIB / "walk_b.kas"),
                    path=files.load_path(KAS_LIB / "walk_path.kas"), frames=4)
    ops = OpsFile(ops=[Op("fill", 3, chains=(2,)), Op("fill", 5, chains=(1,)),
                       Op("line", 8, chains=(1,))], painted=2)
    session = PaintSession(seq, ops)
    session.autopaint()
    _put("kas-paint-ops", "walk_autopainted.ops", opsfile.ops_text(session.ops))
    own = OpsFile(Palette([(0, 0, 0), (255, 0, 0), (0, 0, 255)]),
                  [Op("fill", 1, chains=(1,)), Op("region", 2, at=(0.5, -1.0))],
                  {1: [Op("touch", 2, at=(2.5, 2.5), frame=1)]}, 0.05, 1)
    _put("kas-paint-ops", "touch_up.ops", opsfile.ops_text(own))


# a tablet tape's entries of every kind (a session's T record; protocols.tablets.tape)
_SMALL_TAPE = (b'[[0,"calibration",null],[0,"open",{"kind":"serial","name":"emulated:summa-mm",'
               b'"protocol":"summa-mm","options":{},"model":{"name":"Summagraphics MM",'
               b'"max_x":6000,"max_y":6000,"lines_per_inch":500.0,"pressure_max":null,'
               b'"tilt_range":null,"origin":"upper-left","buttons":4},"replies":[],'
               b'"parmrk":true}],[1,"raw","f80000000000"],[2,"flush",null],[3,"idle",1],'
               b'[4,"lost","unplugged"]]')


def _tapes() -> None:
    """A tablet tape recorded by ``kas edit --tablet emulated:summa-mm --record`` (its T
    records' entries, tests/data/tablets) and a small one with every kind of entry."""
    _copy("tablet-tape", DATA / "tablets" / "summa_kas_edit.tape")
    _put("tablet-tape", "every_kind.tape", _SMALL_TAPE)


def _sessions() -> None:
    """Two recordings camlab88 made (tests/data/sessions, the small ones) and one written by
    protocols.session.format with every record type (input events too); the third made by
    camlab88, begun from a state, is _resumed_recording's."""
    from fractions import Fraction

    from camlab88.protocols.session.format import ScreenHash, SessionRecording, dumps

    _copy("session-recording", DATA / "sessions" / "sigma_run.session",
          DATA / "sessions" / "kas_edit.session")
    sha = "0123456789abcdef" * 4
    rec = SessionRecording(
        ["ca", "program", "--headless", "--events", "e.events"], 2, True,
        {"e.events": b"key space\nwait 1\n"},
        [(3, Fraction(3, 25), {"kind": "KeyDown", "key": "space"})],
        [(3, ">", b"\x1b[H hello"), (4, "<", b"\x11"), (4, "+", b"\x13"),
         (4, "T", _SMALL_TAPE)],
        [ScreenHash(2, 4, Fraction(4, 25), sha)], ScreenHash(3, 5, Fraction(1, 5), sha), 5)
    _put("session-recording", "every_record.session", dumps(rec))


# the resumed recording: sigma_run.session's run saved at 0.2 s, then recorded from there
RESUMED = "resumed_sigma_run.session"
RESUMED_RUN = ["sigma", "run", "--headless", "--in", "picture.sigma", "--seconds", "0.4"]


def _resumed_recording() -> None:
    """A recording begun from ``--load-state``: ``sigma run --load-state s.c88state --record``
    (its header's argv names the state; its file record carries the state by content, the
    replay's ``--load-state`` reads it through the same loader as a state on disk)."""
    import os

    from camlab88.protocols.session.format import read
    from fuzz.states import run_cli

    old = Path.cwd()
    with tempfile.TemporaryDirectory() as scratch:
        os.chdir(scratch)
        try:
            for name, data in read(DATA / "sessions" / "sigma_run.session").files.items():
                Path(name).write_bytes(data)
            for argv in ([*RESUMED_RUN, "--save-state", "s.c88state", "--at", "0.2"],
                         [*RESUMED_RUN, "--load-state", "s.c88state", "--record", "r.session"]):
                code, err = run_cli(argv, 300.0)
                if code != 0:
                    raise RuntimeError(f"{' '.join(argv)}: {err}")
            _put("session-recording", RESUMED, Path("r.session").read_bytes())
        finally:
            os.chdir(old)


def _states() -> None:
    """A Sigma machine with a stream half taken, and a CA program's whole state."""
    from camlab88.apps.ca.program.program import CAProgram, Options
    from camlab88.base.plainstate import encode
    from camlab88.emulator.machine import RainbowMachine, SigmaMachine
    from camlab88.emulator.machine.state_file import pack
    from camlab88.protocols.sigma.demo import sigma_animation_stream

    machine = SigmaMachine("t5684")
    machine.host.write(sigma_animation_stream()[:400])
    machine.run_until(0.2)
    _put("machine-state", "sigma_mid_stream.state", machine.save_state())
    program = CAProgram(RainbowMachine().client, Options(pattern="glider"))
    program.frame()
    parts: dict[str, bytes] = {}
    values = encode(program.STATE_SCHEMA, program.state_values(), parts)
    _put("program-state", "ca_glider.state", pack("program", {"values": values}, parts))


def _cli_states() -> None:
    """Real states saved by the commands in fuzz/states.py, opened: the cli-load-state
    seeds. They name each program's state version: make them again after a version bump,
    or the commands refuse them all at the version check and the fuzzing goes no deeper."""
    from fuzz import states

    with tempfile.TemporaryDirectory() as scratch:
        for name in states.PROGRAMS:  # opened: see fuzz/states.py
            data = states.save_state(name, Path(scratch) / f"{name}.c88state")
            _put("cli-load-state", f"{name}.opened", states.open_state(data))


def main() -> int:
    if CORPUS.exists():
        shutil.rmtree(CORPUS)
    for make in (_rainbow, _link_and_sigma, _kas, _snooker, _ca, _tablets, _scripts_and_views,
                 _kas_paint, _tapes, _sessions, _resumed_recording, _states, _cli_states):
        make()
    for folder in sorted(CORPUS.iterdir()):
        files = list(folder.iterdir())
        print(f"{folder.name:20s} {len(files)} files, {sum(f.stat().st_size for f in files)} bytes")
    return 0


if __name__ == "__main__":
    sys.exit(main())
