"""The demo's acts: a registry, one entry an act, in the order they play (``ACTS``: name,
title, size, the function of this module yielding its frames, the line ``demo --help``
shows). Each act's function yields (h, w, 3) uint8 frames at 25 a second of device time,
made by a program talking to an emulated device."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, NamedTuple

if TYPE_CHECKING:
    from collections.abc import Callable, Iterator

FPS = 25


def lockstep(run: Callable[[Callable[[Any], None]], object]) -> Iterator[Any]:
    from camlab88.base.lockstep import lockstep as frames

    return frames(run)


class Stage:
    """The device an act's frames come from, for the inspector: ``machine`` (a Sigma or
    Rainbow machine); ``time`` the act's device time."""

    def __init__(self) -> None:
        self.machine: Any = None
        self.shown = 0

    def time(self) -> Any:
        from fractions import Fraction

        return Fraction(self.shown, FPS)


class Act(NamedTuple):  # a NamedTuple, not a dataclass: every command builds this parser
    name: str
    title: str
    size: tuple[int, int]   # device pixels (w, h)
    frames: str             # the function of this module yielding the act's frames
    about: str              # one line for --help

    def play(self, stage: Stage | None = None) -> Iterator[Any]:
        """The act's frames; ``stage`` gets the device they come from."""
        stage = stage if stage is not None else Stage()
        for frame in globals()[self.frames](stage):
            stage.shown += 1
            yield frame


ACTS: tuple[Act, ...] = (
    Act("sigma", "Sigma T5684 on a 9600-baud line", (768, 512), "sigma_frames",
        "a host session over the line: vectors, dash masks, ellipses, fill, LUT animation, "
        "double buffering (§3.1.4)"),
    Act("kas", "KAS keyframe editor and line test on the T5684", (768, 512), "kas_frames",
        "KAS's editor drawing a stroke, then a line test of 'a line taking a walk'"),
    Act("paint", "KAS painting on the T5688", (768, 512), "paint_frames",
        "the demo walk auto-painted from its middle frame, replayed double-buffered at 9600 "
        "baud (§3.3)"),
    Act("snooker", "snooker motion development on the Rainbow", (768, 576), "snooker_frames",
        "a break simulated and replayed at 25 frames a second"),
    Act("snooker_camera", "snooker camera angles on the Rainbow", (768, 576),
        "snooker_camera_frames",
        "the thesis's example camera script (§6.3.1) over its shot, in the visualiser (§6.3.2)"),
    Act("film", "from motion development to rendered film", (768, 512), "film_frames",
        "a break simulated, a camera script interpreted, 36 frames rendered in true colour "
        "(§6.4)"),
    Act("ca", "the programmable cellular automaton on the Rainbow", (768, 576), "ca_frames",
        "Life's Gosper gun in auto mode, panned and zoomed by scripted mouse input"),
    Act("shelf", "Appendix I's shelf unit on the Rainbow", (768, 576), "shelf_frames",
        "four translucent pads slide apart and together; only arcs move, the LUT keeps the "
        "translucence"),
)


def sigma_frames(stage: Stage) -> Iterator[Any]:
    """The Sigma showcase: the screen after each 1/25 s of line time at 9600 baud."""
    from fractions import Fraction  # imported here: every command builds the demo's parser

    from camlab88.emulator.harness.sigma_batch import periods
    from camlab88.emulator.machine import SigmaMachine
    from camlab88.protocols.link import LineSettings
    from camlab88.protocols.sigma.demo import sigma_demo_stream

    machine = stage.machine = SigmaMachine("t5684", LineSettings(baud=9600), xonxoff=False)
    machine.host.write(sigma_demo_stream())
    for _k in periods(machine, Fraction(1, FPS)):
        yield machine.frame()


def kas_frames(stage: Stage) -> Iterator[Any]:
    """KAS on the T5684: the host's chunks written to a 9600-baud line at their times."""
    from fractions import Fraction

    from camlab88.apps.kas.program import demo_session
    from camlab88.emulator.harness.sigma_batch import periods
    from camlab88.emulator.machine import SigmaMachine
    from camlab88.protocols.link import LineSettings

    machine = stage.machine = SigmaMachine("t5684", LineSettings(baud=9600))
    for t, data in demo_session().chunks:  # the host's writes, each at its line time
        machine.outside.write(data, at=t)
    for _k in periods(machine, Fraction(1, FPS)):
        yield machine.frame()


def snooker_frames(stage: Stage) -> Iterator[Any]:
    """The snooker program's replay on the Rainbow: a break simulated and shown (ball pads
    double-buffered over the table pad by LUT transparency)."""
    from camlab88.apps.snooker.program.demo import play_break
    from camlab88.emulator.machine import RainbowMachine

    def run(show: Callable[[Any], None]) -> None:
        stage.machine = RainbowMachine(on_frame=show)
        play_break(stage.machine.client, 4.0)

    yield from lockstep(run)


def ca_frames(stage: Stage) -> Iterator[Any]:
    """The cellular automaton on the Rainbow: the Gosper gun in auto mode, panned and zoomed,
    driven by the program's own scripted mouse events."""
    from camlab88.apps.ca.program.demo import demo_events
    from camlab88.apps.ca.program.program import CAProgram, Options
    from camlab88.apps.ca.program.script_events import parse, play
    from camlab88.emulator.machine import RainbowMachine

    machine = stage.machine = RainbowMachine()
    program = CAProgram(machine.client, Options(rules="life", pattern="gosper_gun"))

    def run(show: Callable[[Any], None]) -> None:
        def frame() -> None:
            program.frame()
            show(machine.shown())

        play(parse(demo_events(60), "<ca demo>"), machine.post, frame,
             lambda: program.finished)

    yield from lockstep(run)


def shelf_frames(stage: Stage) -> Iterator[Any]:
    """Appendix I's shelf unit: four pads slide apart and back (4 s); only arcs move."""
    from camlab88.emulator.machine import RainbowMachine
    from camlab88.protocols.rainbow.shelf import ShelfDemo

    machine = stage.machine = RainbowMachine()
    demo = ShelfDemo(machine.client)
    for _ in range(100):  # one slide apart and together again, at 25 frames a second
        demo.step()
        demo.step()  # the Rainbow's 50 Hz frames, two a demo frame
        yield machine.shown().copy()


def paint_frames(stage: Stage) -> Iterator[Any]:
    """The demo walk (with its rising sun) auto-painted from three operations done on its
    middle frame, every fourth frame painted and replayed double-buffered on a T5688 at 9600
    baud; one picture per 1/25 s of line time."""
    from fractions import Fraction

    from camlab88.apps.kas import demo
    from camlab88.apps.kas.paint.ops import Op, OpsFile
    from camlab88.apps.kas.paint.program import PaintProgram
    from camlab88.apps.kas.paint.replay import ReplayHost
    from camlab88.emulator.harness.sigma_batch import periods
    from camlab88.emulator.machine import SigmaMachine
    from camlab88.protocols.link import LineSettings

    seq = demo.build()
    mid = len(seq.frames) // 2
    sun = tuple(seq.frames[mid - 1].chains[2].centre())
    ops = OpsFile(ops=[Op("fill", 3, chains=(2,)), Op("fill", 5, chains=(1,)),
                       Op("region", 27, at=sun)], painted=mid)
    machine = stage.machine = SigmaMachine("t5688", LineSettings(baud=9600), xonxoff=False)
    host = ReplayHost(PaintProgram(seq, ops), machine.host, range(1, len(seq.frames) + 1, 4))
    for _ in periods(machine, Fraction(1, FPS)):
        yield machine.frame()
        host.step()  # the next frame once the line has delivered the last


def snooker_camera_frames(stage: Stage) -> Iterator[Any]:
    """The thesis's example camera script over its shot, in the visualiser on the Rainbow."""
    from camlab88.apps.snooker.visualiser.demo import play_example
    from camlab88.emulator.machine import RainbowMachine

    machine = stage.machine = RainbowMachine()

    def run(show: Callable[[Any], None]) -> None:
        play_example(machine.client, lambda _f: show(machine.shown()))

    yield from lockstep(run)


def film_frames(stage: Stage) -> Iterator[Any]:
    """A break from the motion program through a camera script to rendered frames."""
    from camlab88.apps.snooker.film.demo import film_frames as frames

    yield from frames()

