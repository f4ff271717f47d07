"""``camlab88 kas export SEQ OUT``: a sequence as GIF, MP4 or PNGs."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from camlab88.commands.kas import add_background_options
from camlab88.runopts import check_output, fail, progress

COMMAND = "camlab88 kas export"

DESCRIPTION = """\
Render every frame and write OUT.gif, OUT.mp4 or OUT_NNNN.png, with a progress bar. By \
default each frame is drawn by the emulated Sigma T5684 (768 x 512, 16 colours, its own \
vectors); --renderer raster uses the software rasteriser at any --width."""


HELP = "export a sequence as GIF, MP4 or PNGs"


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("seq")
    p.add_argument("out")
    p.add_argument("--renderer", default="sigma", choices=["sigma", "raster"])
    p.add_argument("--width", default=768, type=int, help="raster renderer only")
    add_background_options(p)


def run(args: argparse.Namespace) -> int:
    from camlab88.apps.kas import files, library
    from camlab88.apps.kas.export import export as write

    # the one output rule (docs/exit_status.md), and a full disk, before rendering: status 2
    check_output(COMMAND, Path(args.out), "export to", (".gif", ".mp4", ".png"))
    try:  # the input: missing or malformed, it could not start (status 2)
        seq = files.load_sequence(library.resolve(args.seq))
    except (OSError, ValueError) as exc:
        return fail(COMMAND, exc)
    try:
        if args.renderer == "sigma":
            if args.width != 768:
                print("kas export: the Sigma renderer draws 768 x 512; --width applies to "
                      "--renderer raster", file=sys.stderr)
            out = write(seq, args.out, progress=progress("export"),
                        render_frame=_on_sigma(args.background))
        else:
            out = write(seq, args.out, args.width, args.background, progress("export"))
    except ValueError as exc:
        return fail(COMMAND, exc)
    except OSError as exc:  # a write fault during the export: the work failed (status 1)
        return fail(COMMAND, exc, 1)
    print(f"wrote {_written(out, len(seq))} ({args.renderer} renderer)")
    return 0


def _written(out: Path, n: int) -> str:
    """What was written: one file, or the first..last of the numbered PNGs."""
    if out.suffix.lower() != ".png" or n == 1:
        return str(out)
    last = out.with_name(out.name.replace("_0001.png", f"_{n:04d}.png"))
    return f"{n} frames, {out} .. {last.name}"


def _on_sigma(background: str):
    """Each frame drawn on a fresh emulated T5684 (16 colours, the terminal's own vectors)."""
    from camlab88.apps.kas.program.viewer import still_bytes
    from camlab88.emulator.harness.sigma_batch import still

    def on_sigma(frame):
        return still(still_bytes(frame, background), "t5684").frame()
    return on_sigma
