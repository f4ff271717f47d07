"""``camlab88 figures [N]``: the thesis's screen figures as shipped session recordings.

Without a number: the list, each with the thesis's caption (shortened) and whether its
recording ships. With one (``camlab88 figures 6.5``): the recording ``examples/figures/
fig-6.5.session`` replayed, in a window, or headless (``--headless``, or no display) to its
last screen written as a PNG (``fig-6.5.png``, or ``--screenshot PNG``). The recordings are
made by ``examples/figures/make_figures.py``; docs/figures.md is the gallery.
"""

from __future__ import annotations

import argparse
from pathlib import Path

from camlab88.commandspec import add_command
from camlab88.runopts import fail

COMMAND = "camlab88 figures"
FIGURES_DIR = Path(__file__).resolve().parents[3] / "examples" / "figures"

# The thesis's screen figures and their captions (shortened where long).
CAPTIONS: dict[str, str] = {
    "3.1": "KAS screen layout",
    "3.2": "KAS in edit mode: dull lines unaltered, bright ones moved, purple ones where they were",
    "3.6": "a sample path stretched and reflected to fit between each pair of points",
    "3.7": "the four working areas used during image painting, at quarter size",
    "3.8": "a simple example of painting an outline image",
    "6.1": "the situation ready for the start of a game of snooker",
    "6.5": "screen layout as the snooker program is running: the orange menu",
    "6.6": "setting the velocity of a ball",
    "6.7": "images produced during camera definition",
    "6.8": "demonstration of anti-aliasing",
    "6.9": "shaded image of a snooker table: multiple highlights and shadows under the balls",
    "7.1": "examples of patterns from the Game of Life",
    "7.2": "the evolution of a glider over five generations",
    "7.3": "screen layout during editing, with the menu of editing methods",
    "7.4": "Gosper glider guns from the Game of Life",
    "7.5": "cellular automaton screen images at zoom 16 (with grid) and zoom 8 (without)",
    "7.9": "a cellular automaton simulating a Turing machine recognising primes (testing 25)",
}


def register(subparsers: argparse._SubParsersAction) -> None:
    add_command(subparsers, __name__, figures)


def recording(number: str) -> Path:
    return FIGURES_DIR / f"fig-{number}.session"


def figures(args: argparse.Namespace) -> int:
    if args.number is None:
        return _list()
    if args.number not in CAPTIONS:
        return fail(COMMAND, f"no screen figure {args.number!r} (figures: "
                             f"{', '.join(CAPTIONS)})")
    path = recording(args.number)
    if not path.is_file():
        return fail(COMMAND, f"figure {args.number} has no recording yet ({path} is missing)")
    return _replay(args, path)


def _list() -> int:
    for number, caption in CAPTIONS.items():
        mark = "" if recording(number).is_file() else "   (not recorded yet)"
        print(f"fig {number:<4} {caption}{mark}")
    print(f"\n`{COMMAND} N` replays one (recordings in {FIGURES_DIR})")
    return 0


def _replay(args: argparse.Namespace, path: Path) -> int:
    from camlab88.emulator.harness import choose_headless
    from camlab88.emulator.harness.replay import Replay
    from camlab88.protocols.session import SessionFileError, read
    from camlab88.session_replay import rerun

    try:
        rec = read(path)
    except SessionFileError as exc:
        return fail(COMMAND, exc)
    headless = choose_headless(COMMAND, args.headless, "writing the figure's last screen")
    shot = args.screenshot or (Path(f"fig-{args.number}.png") if headless else None)
    ctx = Replay(rec, headless=headless, period=False, check=False, frames=None,
                 screenshot=None if shot is None else shot.resolve())
    status, said = rerun(ctx)
    if ctx.runs == 0 or status != 0:
        return fail(COMMAND, f"{path}: the replay ended with exit status {status}: "
                    f"{said.strip()}", 1)
    if shot is not None:
        print(f"{COMMAND}: figure {args.number} ({CAPTIONS[args.number]}) -> {shot}")
    return 0
