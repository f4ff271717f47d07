"""``camlab88 figures [N]``: the thesis's screen figures as shipped session recordings.

Without a number: the list, each with its section, the thesis's caption (shortened), its
verdict and whether its recording ships. With one (``camlab88 figures 6.5``): the recording
``examples/figures/fig-6.5.session`` replayed, in a window, or headless (``--headless``, or no
display) to its last screen written as a PNG (``fig-6.5.png``, or ``--screenshot PNG``), then
the thesis's section and whole caption, and where and why ours differs. The recordings are
made by ``examples/figures/make_figures.py``; the figures' captions, sections and what
differs live in camlab88/figure_catalogue.toml; docs/figures.md is the gallery.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from camlab88.figure_catalogue import by_number
from camlab88.figure_catalogue import figures as catalogue
from camlab88.runopts import fail

COMMAND = "camlab88 figures"
FIGURES_DIR = Path(__file__).resolve().parents[3] / "examples" / "figures"


DESCRIPTION = """\
The thesis's screen figures as session recordings (examples/figures). With no number, the \
list with captions; with one, that figure replayed in a window, or headless to a PNG of its \
last screen."""


HELP = "the thesis's screen figures, replayed from shipped recordings"


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("number", nargs="?", help="a figure number, e.g. 6.5")
    p.add_argument("--headless", action="store_true", help="no window: write the PNG")
    p.add_argument("--screenshot", type=Path, metavar="PNG",
                   help="save the last screen here (default fig-N.png when headless)")
    p.add_argument("--html", type=Path, metavar="DIR",
                   help="build the web gallery in DIR: each figure's session as a "
                        "self-contained replay page (fig-N.html: number, section, caption, what "
                        "differs), and index.html; opens offline (docs/replay-web.md)")


def recording(number: str) -> Path:
    return FIGURES_DIR / f"fig-{number}.session"


def run(args: argparse.Namespace) -> int:
    if args.html is not None:
        return _gallery(args)
    if args.number is None:
        return _list()
    known = by_number()
    if args.number not in known:
        return fail(COMMAND, f"no screen figure {args.number!r} (figures: "
                             f"{', '.join(known)})")
    path = recording(args.number)
    if not path.is_file():
        return fail(COMMAND, f"figure {args.number} has no recording yet ({path} is missing)")
    return _replay(args, path)


def _list() -> int:
    for fig in catalogue():
        mark = "" if recording(fig.number).is_file() else "   (not recorded yet)"
        differs = "" if fig.verdict == "agrees" else f"   [{fig.verdict}]"
        print(f"fig {fig.number:<4} {fig.section_label:<11} {fig.short}{differs}{mark}")
    print(f"\n`{COMMAND} N` replays one (recordings in {FIGURES_DIR})")
    return 0


def _replay(args: argparse.Namespace, path: Path) -> int:
    from camlab88.emulator.harness import choose_headless
    from camlab88.emulator.harness.control_options import Controls
    from camlab88.emulator.harness.replay import Replay
    from camlab88.protocols.session import SessionFileError, read
    from camlab88.session_replay import rerun

    try:
        rec = read(path, traffic=False)  # a replay: the traffic is not kept
    except SessionFileError as exc:
        return fail(COMMAND, exc)
    headless = choose_headless(COMMAND, args.headless, "writing the figure's last screen")
    shot = args.screenshot or (Path(f"fig-{args.number}.png") if headless else None)
    # A figure recorded with --inspect (Appendix I's pad structure) is shown with the
    # inspector's panel beside the screen: a replay otherwise takes only its own controls.
    controls = Controls(inspect=True) if "--inspect" in rec.argv else None
    ctx = Replay(rec, headless=headless, period=False, check=False, frames=None,
                 screenshot=None if shot is None else shot.resolve(), controls=controls)
    status, said = rerun(ctx)
    if ctx.fault is not None:  # read again as it played, the recording failed its checks
        return fail(COMMAND, ctx.fault)
    if ctx.runs == 0 or status != 0:
        return fail(COMMAND, f"{path}: the replay ended with exit status {status}: "
                    f"{said.strip()}", 1)
    fig = by_number()[args.number]
    if shot is not None:
        print(f"{COMMAND}: figure {args.number} ({fig.short}) -> {shot}")
    print(f"thesis {fig.section_label}, figure {fig.number}: {fig.caption}")
    if fig.differs:
        print(f"{fig.verdict}: {fig.differs}")
    return 0


def _gallery(args: argparse.Namespace) -> int:
    """``--html DIR``: every figure's replay page and index.html (camlab88.replay_page)."""
    from camlab88.figure_catalogue import by_number
    from camlab88.replay_page.gallery import build

    known = by_number()
    if args.number is not None and args.number not in known:
        return fail(COMMAND, f"no screen figure {args.number!r} (figures: {', '.join(known)})")
    chosen = list(known.values()) if args.number is None else [known[args.number]]
    out = args.html
    from camlab88.runopts import check_output_dir

    check_output_dir(COMMAND, out, "write the gallery to")  # the one output rule: DIR one level
    try:
        entries = build(out, chosen, recording)
    except OSError as exc:
        return fail(COMMAND, f"cannot write the gallery to {out}: {exc.strerror or exc}")
    made = [en for en in entries if en.page is not None]
    failed = [en for en in entries if en.page is None and en.why != "not recorded yet"]
    size = sum(p.stat().st_size for p in out.iterdir() if p.is_file())
    print(f"{COMMAND}: gallery {out / 'index.html'} ({len(made)} figure pages, "
          f"{size / 1e6:.1f} MB in {out})", file=sys.stderr)
    for en in failed:
        print(f"{COMMAND}: figure {en.figure.number}: {en.why}", file=sys.stderr)
    return 1 if failed else 0
