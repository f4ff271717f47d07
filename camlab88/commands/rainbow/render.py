"""``camlab88 rainbow render SCENE.json --out PNG``: one frame of a scene file."""

from __future__ import annotations

import argparse
from pathlib import Path

from camlab88.commands.rainbow import add_relic_memory_options
from camlab88.runopts import check_output, check_output_dir, fail

COMMAND = "camlab88 rainbow render"

DESCRIPTION = """\
Compile SCENE.json's pad graph to band structure and render one 768x576 frame."""


HELP = "render a scene file (JSON pad graph) to a PNG"


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("scene", metavar="SCENE.json")
    p.add_argument("--out", required=True, metavar="PNG", help="where to write the frame")
    p.add_argument("--bands", metavar="FILE", help="also write the band structure as text")
    p.add_argument("--reference", action="store_true",
                   help="render with the per-pixel reference compositor instead")
    add_relic_memory_options(p)
    p.add_argument("--inspect-out", type=Path, metavar="DIR",
                   help="also write the inspector's panel (bands over the screen, video "
                        "memory, pad graph) as DIR/frame_00000.png")


def run(args: argparse.Namespace) -> int:
    from camlab88.emulator.machine import RainbowError, RainbowMachine, SceneError

    # the one output rule (docs/exit_status.md), before the work: status 2
    check_output(COMMAND, Path(args.out), "write", (".png",))
    if args.bands:
        check_output(COMMAND, Path(args.bands), "write the bands to")
    if args.inspect_out is not None:
        check_output_dir(COMMAND, Path(args.inspect_out), "write the inspector's frames to")
    machine = RainbowMachine(strict_memory=args.strict)
    try:
        machine.load_scene(args.scene)
    except (SceneError, RainbowError) as exc:
        return fail(COMMAND, exc)
    try:  # compiling (or the reference walk) refuses graphs with too many paths
        frame = machine.reference() if args.reference else machine.frame()
        text = machine.bands_text() if args.bands else None
    except RainbowError as exc:
        return fail(COMMAND, f"{args.scene}: {exc}")
    status = _write(args, frame, text)
    if status == 0 and args.inspect_out is not None:
        return _inspect(args, machine.device, frame)
    return status


def _inspect(args: argparse.Namespace, device, frame) -> int:
    from camlab88.base.png import frame_path, write_frame
    from camlab88.emulator.inspect import PANEL_WIDTH
    from camlab88.emulator.inspect.rainbow import RainbowPanel

    path = frame_path(args.inspect_out, 0)
    try:
        write_frame(RainbowPanel(device, PANEL_WIDTH)(frame), args.inspect_out, 0)
    except OSError as exc:
        return fail(COMMAND, exc)
    print(f"wrote {path}")
    return 0


def _write(args: argparse.Namespace, frame, text: str | None) -> int:
    from camlab88.base.atomicfile import write_atomic
    from camlab88.base.png import write_png

    try:
        write_png(frame, args.out)
        print(f"wrote {args.out}")
        if text is not None:
            write_atomic(args.bands, text.encode())
            print(f"wrote {args.bands}")
    except OSError as exc:
        return fail(COMMAND, exc)  # an output that cannot be written: 2, as everywhere
    return 0
