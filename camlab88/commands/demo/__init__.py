"""``camlab88 demo``: the main job — the emulated devices running the thesis's programs.

The acts (camlab88.commands.demo.acts.ACTS, one registry entry each) play one after another
on the harness: in a window if there is a display (Space: next act; Esc or close: quit),
else headless, writing every frame as PNG and one animated GIF per act.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from camlab88.commands.demo.acts import ACTS, FPS, Act
from camlab88.control_flags import add_control_options
from camlab88.replay_policy import DROP, KEEP, SCRATCH

__all__ = ["ACTS", "Act", "register"]
COMMAND = "camlab88 demo"
KEYS = "Space: next act; Esc or close: quit"
ACT_NAMES = tuple(a.name for a in ACTS)  # the --only choices; the help lists them
ACT_LIST = "; ".join(f"{i}. {a.name}: {a.about}" for i, a in enumerate(ACTS, 1))

DESCRIPTION = f"""\
Play the demo: the emulated devices running the thesis's programs, at 25 frames a second of \
device time. The acts: {ACT_LIST}. With a display it opens one window for every act (Space: \
next act, Esc: quit; F1 lists the controls, F11 shows the act's device in the inspector); with \
none, or --headless, it writes every frame as PNG and one animated GIF per act into --out."""


HELP = "play the demo session (all acts)"


def add_arguments(p: argparse.ArgumentParser) -> None:
    shown = [
        (p.add_argument("--headless", action="store_true", help="no window, write files"),
         KEEP),
        (p.add_argument("--out", default="camlab88-demo", type=Path,
                        help="output directory when headless (default ./camlab88-demo)"),
         SCRATCH),
        (p.add_argument("--scale", default=1, type=int, help="window scale"), KEEP),
        (p.add_argument("--screenshot", type=Path,
                        help="play unpaced, save the last screen of the last act and exit"),
         SCRATCH),
        (p.add_argument("--fast", action="store_true",
                        help="do not pace to the wall clock: flat out (--speed X wins)"), KEEP),
        (p.add_argument("--record", type=Path, metavar="FILE",
                        help="record the whole demo, every act, as one session (replay it "
                             "with 'camlab88 replay FILE --check')"), DROP)]
    for action, kind in shown:
        action.replay, action.run_only = kind, True
    add_control_options(p)
    p.add_argument("--only", action="append", choices=ACT_NAMES, metavar="ACT",
                   help=f"play only this act (repeatable): {', '.join(ACT_NAMES)}"
                   ).replay = KEEP  # which acts play: what the program does, not run-only


def run(args: argparse.Namespace) -> int:
    acts = [a for a in ACTS if not args.only or a.name in args.only]
    return play_acts(acts, args)


def play_acts(acts: list[Act], args: argparse.Namespace) -> int:
    """The acts one after another in one run: one window (Space: next act), or headless
    into PNGs and a GIF per act; the controls (--speed, --video, --inspect, --inspect-out,
    F-keys) as on every program, the inspector following each act's device."""
    from camlab88.commands.demo.acts import Stage
    from camlab88.control_flags import controls_from_args
    from camlab88.emulator.harness import Plugin, RunOptions, run
    from camlab88.emulator.harness.stream import ActSequence, ActWriters, FrameStream
    from camlab88.runopts import check_output

    headless = _headless(args)
    if headless:  # the one output rule, before the work: --out is made one level, never more
        from camlab88.runopts import check_output_dir

        check_output_dir(COMMAND, args.out, "write the demo's frames to")
    controls = controls_from_args(args, COMMAND, headless)
    hold = not headless and args.screenshot is None
    streams = []
    for i, act in enumerate(acts, 1):
        stage = Stage()
        streams.append(FrameStream(act.play(stage), act.size, FPS, act.title, KEYS,
                                   hold and i == len(acts), stage))

    def announce(i: int) -> None:
        print(f"{COMMAND}: act {i + 1}/{len(acts)}: {acts[i].title}", file=sys.stderr,
              flush=True)

    target = ActSequence(streams, COMMAND, KEYS, announce)
    if args.record is not None:
        check_output(COMMAND, args.record, "record to")
    opts = RunOptions(headless=headless, paced=not args.fast, scale=args.scale,
                      screenshot=args.screenshot, command=COMMAND, controls=controls,
                      record=args.record, argv=list(getattr(args, "_argv", [])))
    plugins: list[Plugin] = []
    if headless:
        args.out.mkdir(exist_ok=True)
        plugins.append(ActWriters(args.out, [(a.name, a.title) for a in acts], FPS, COMMAND))
    run(target, opts, plugins)
    return 0


def _headless(args: argparse.Namespace) -> bool:
    """The display rule; a replay plays as recorded (its own --headless decides the
    window: Replay.adjust)."""
    from camlab88.emulator.harness import choose_headless, replay

    active = replay.active()
    if active is not None:
        return bool(active.rec.headless)
    return choose_headless(COMMAND, args.headless,
                           f"writing every frame as PNG and a GIF per act into {args.out}")
