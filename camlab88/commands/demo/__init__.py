"""``camlab88 demo``: the main job — the emulated devices running the thesis's programs.

The acts (camlab88.commands.demo.acts.ACTS, one registry entry each) play one after another
on the harness: in a window if there is a display (Space: next act; Esc or close: quit),
else headless, writing every frame as PNG and one animated GIF per act.
"""

from __future__ import annotations

import argparse
import sys

from camlab88.commands.demo.acts import ACTS, FPS, Act
from camlab88.commandspec import add_command, keys_of

__all__ = ["ACTS", "Act", "register"]
COMMAND = "camlab88 demo"
KEYS = keys_of(__name__)
ACT_NAMES = tuple(a.name for a in ACTS)  # the --only choices; the help lists them
ACT_LIST = "; ".join(f"{i}. {a.name}: {a.about}" for i, a in enumerate(ACTS, 1))


def register(subparsers: argparse._SubParsersAction) -> None:
    add_command(subparsers, __name__, demo)


def demo(args: argparse.Namespace) -> int:
    acts = [a for a in ACTS if not args.only or a.name in args.only]
    return play_acts(acts, args)


def play_acts(acts: list[Act], args: argparse.Namespace) -> int:
    """The acts one after another in one run: one window (Space: next act), or headless
    into PNGs and a GIF per act; the controls (--speed, --video, --inspect, --inspect-out,
    F-keys) as on every program, the inspector following each act's device."""
    from camlab88.commands.demo.acts import Stage
    from camlab88.control_flags import controls_from_args
    from camlab88.emulator.harness import Plugin, RunOptions, choose_headless, run
    from camlab88.emulator.harness.stream import ActSequence, ActWriters, FrameStream

    headless = choose_headless(COMMAND, args.headless,
                               f"writing every frame as PNG and a GIF per act into {args.out}")
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
    opts = RunOptions(headless=headless, paced=not args.fast, scale=args.scale,
                      screenshot=args.screenshot, command=COMMAND, controls=controls,
                      argv=list(getattr(args, "_argv", [])))
    plugins: list[Plugin] = []
    if headless:
        args.out.mkdir(parents=True, exist_ok=True)
        plugins.append(ActWriters(args.out, [(a.name, a.title) for a in acts], FPS, COMMAND))
    run(target, opts, plugins)
    return 0
