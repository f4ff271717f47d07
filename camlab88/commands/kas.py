"""``camlab88 kas ...``: the keyframe animation suite of thesis chapter 3.

The model programs (in-betweener, superimposer, plotter, exporter, schedule, editor model on
a script) and the device fronts: ``kas edit``, ``kas path`` and ``kas view`` run the programs
of ``apps.kas.front`` against an emulated Sigma T5684 over a 9600-baud line, in a window or
headless from an event script (the wiring to the emulator, window and tablet lives here).
"""

from __future__ import annotations

import argparse
import re
import sys
from pathlib import Path


def register(subparsers: argparse._SubParsersAction) -> None:
    kas = subparsers.add_parser("kas", help="KAS, the keyframe animation suite (chapter 3)",
                                description="KAS: keyframe editor model, in-betweener, "
                                "superimposer, viewer schedule and hard copy (thesis ch. 3). "
                                "File names may be library names (see 'kas library').")
    sub = kas.add_subparsers(dest="kas_command", metavar="KAS_COMMAND")
    sub.required = True

    ib = sub.add_parser("inbetween", help="in-between keyframes into a sequence",
                        description="Frames from keyframe A to B (both included) along a "
                        "sample path, placed by a timing (tick marks or a curve); with more "
                        "than two keyframes a spline goes through them all.")
    ib.add_argument("keys", nargs="+", metavar="KEY", help="two or more keyframe files")
    ib.add_argument("--path", help="sample path file (two keyframes only)")
    ib.add_argument("--timing", help="timing file (ticks or curve) or a built-in curve name: "
                    "linear, ease-in, ease-out, ease-in-out, overshoot")
    ib.add_argument("--frames", type=int, help="frames per pair of keyframes, both included")
    ib.add_argument("--missing", default="copy-nearest",
                    choices=("copy-nearest", "grow", "stay"),
                    help="what chains missing from a keyframe do (default copy-nearest)")
    ib.add_argument("--fit", default="stretch", choices=("stretch", "similarity"),
                    help="how the path is fitted to each point pair (default stretch)")
    ib.add_argument("--method", default="catmull-rom",
                    choices=("linear", "overhauser", "catmull-rom", "kochanek-bartels"),
                    help="spline through three or more keyframes (default catmull-rom)")
    ib.add_argument("--tension", type=float, default=0.0)
    ib.add_argument("--continuity", type=float, default=0.0)
    ib.add_argument("--bias", type=float, default=0.0)
    ib.add_argument("--keep-redundant", action="store_true",
                    help="keep collinear points instead of dropping them")
    ib.add_argument("--fps", type=float, default=25.0)
    ib.add_argument("--out", required=True, help="sequence file to write")
    ib.set_defaults(handler=_inbetween)

    sp = sub.add_parser("superimpose", help="superimpose sequences with start offsets",
                        description="Combine sequences; SEQ@N starts N frames late (its first "
                        "frame is held until then); a sequence that ends early holds its "
                        "last frame. The same sequence may be given several times.")
    sp.add_argument("seqs", nargs="+", metavar="SEQ[@OFFSET]")
    sp.add_argument("--out", required=True)
    sp.set_defaults(handler=_superimpose)

    pl = sub.add_parser("plot", help="plot every frame (HP-GL, SVG, PDF) with registration "
                        "marks", description="Each frame at the given size (default the "
                        "twelve-field, 12 x 8.75 inches) with registration marks; HP-GL uses "
                        "pen N for colour N; PDF is one multi-page sequence.pdf.")
    pl.add_argument("seq")
    pl.add_argument("--hpgl", metavar="DIR")
    pl.add_argument("--svg", metavar="DIR")
    pl.add_argument("--pdf", metavar="DIR")
    pl.add_argument("--width", type=float, default=12.0, help="inches (default 12)")
    pl.add_argument("--height", type=float, default=8.75, help="inches (default 8.75)")
    pl.add_argument("--margin", type=float, default=1.0, help="inches round the field")
    pl.set_defaults(handler=_plot)

    ex = sub.add_parser("export", help="export a sequence as GIF, MP4 or PNGs",
                        description="Render every frame and write OUT.gif, OUT.mp4 or "
                        "OUT_NNNN.png, with a progress bar. By default each frame is drawn by "
                        "the emulated Sigma T5684 (768 x 512, 16 colours, its own vectors); "
                        "--renderer raster uses the software rasteriser at any --width.")
    ex.add_argument("seq")
    ex.add_argument("out")
    ex.add_argument("--renderer", choices=("sigma", "raster"), default="sigma")
    ex.add_argument("--width", type=int, default=768, help="raster renderer only")
    ex.add_argument("--background", choices=("black", "white"), default="black")
    ex.set_defaults(handler=_export)

    sc = sub.add_parser("schedule", help="which frames the real-time viewer shows and drops",
                        description="Given each frame's size in characters on the line, "
                        "compute the real-time line test of §3.1.4: the frame due now is "
                        "sent after each swap; frames passed over are dropped.")
    sc.add_argument("sizes", help="comma-separated characters per frame, or @FILE with one "
                    "number a line")
    sc.add_argument("--fps", type=float, default=25.0)
    sc.add_argument("--baud", type=float, default=9600)
    sc.add_argument("--bits-per-char", type=float, default=10.0, help="10 for 8N1")
    sc.set_defaults(handler=_schedule)

    sh = sub.add_parser("edit-script", help="run the keyframe editor model on an event script",
                        description="Headless: feed the editor model the events of SCRIPT "
                        "(move/down/up X Y, key K, menu ITEM, type TEXT) and save the keyframe.")
    sh.add_argument("script")
    sh.add_argument("--start", help="keyframe to start from (default empty)")
    sh.add_argument("--over", help="previous keyframe to draw over (§2.3 guide)")
    sh.add_argument("--seed", type=int, default=0)
    sh.add_argument("--out", required=True)
    sh.set_defaults(handler=_edit_script)

    ps = sub.add_parser("path-script", help="draw a sample path and tick marks from a script",
                        description="Headless in-betweener set-up: keyframes A and B are "
                        "shown, the SCRIPT's stylus stroke draws the path, 't' then touches "
                        "place tick marks; writes the path and the tick timing.")
    ps.add_argument("first")
    ps.add_argument("second")
    ps.add_argument("script")
    ps.add_argument("--path-out", required=True)
    ps.add_argument("--timing-out", required=True)
    ps.set_defaults(handler=_path_script)

    _register_fronts(sub)

    dm = sub.add_parser("demo", help="build 'a line taking a walk' from the library")
    dm.add_argument("--out", required=True, help="sequence file to write")
    dm.set_defaults(handler=_demo)

    lb = sub.add_parser("library", help="list (or add to) the libraries of keyframes, paths "
                        "and timings", description="Lists the user library ($CAMLAB88_KAS_"
                        "LIBRARY, default ~/.local/share/camlab88/kas) and the shipped one. "
                        "--save FILE NAME checks FILE and copies it into the user library; "
                        "library names can then be given wherever a file is asked for.")
    lb.add_argument("--save", nargs=2, metavar=("FILE", "NAME"))
    lb.set_defaults(handler=_library)


def _fail(cmd: str, exc: Exception) -> int:
    print(f"camlab88 kas {cmd}: {exc}", file=sys.stderr)
    return 2


def _progress(label: str):
    """A text progress bar on a terminal; nothing when stderr is a file or pipe."""
    if not sys.stderr.isatty():
        return None

    def show(i: int, n: int) -> None:
        width = 30
        done = width * i // max(n, 1)
        sys.stderr.write(f"\r{label} [{'#' * done}{'.' * (width - done)}] {i}/{n}")
        if i >= n:
            sys.stderr.write("\n")
        sys.stderr.flush()
    return show


def _timing(name: str | None):
    from apps.kas import files, library, timing

    if name is None:
        return None
    path = library.resolve(name)
    if not path.exists() and name in timing.BUILTIN:
        return timing.curve(name)
    return files.load_timing(path)


def _inbetween(args: argparse.Namespace) -> int:
    from apps.kas import files, library
    from apps.kas.inbetween import inbetween, inbetween_keys

    try:
        keys = [files.load_drawing_or_frame(library.resolve(k)) for k in args.keys]
        if len(keys) < 2:
            raise ValueError("give at least two keyframes")
        tm = _timing(args.timing)
        if len(keys) == 2:
            path = files.load_path(library.resolve(args.path)) if args.path else None
            seq = inbetween(keys[0], keys[1], args.frames, path, tm, args.missing, args.fit,
                            not args.keep_redundant, args.fps)
        else:
            if args.path:
                raise ValueError("--path works between two keyframes; split the sequence")
            if args.frames is None and (tm is None or tm.kind != "ticks"):
                raise ValueError("--frames is needed")
            seq = inbetween_keys(keys, args.frames, args.method, tm, args.missing,
                                 args.tension, args.continuity, args.bias,
                                 not args.keep_redundant, args.fps)
        files.save_sequence(args.out, seq)
    except (OSError, ValueError) as exc:
        return _fail("inbetween", exc)
    print(f"{args.out}: {len(seq)} frames, {sum(f.n_points for f in seq.frames)} points")
    return 0


def _superimpose(args: argparse.Namespace) -> int:
    from apps.kas import files, library
    from apps.kas.superimpose import superimpose

    try:
        parts = []
        cache: dict[str, object] = {}
        for spec in args.seqs:
            # SEQ@N: only a last '@' followed by a whole number is an offset, so file
            # names may contain '@' ('a@b.kas', 'take@2.kas@5')
            m = re.fullmatch(r"(.+)@([+-]?\d+)", spec)
            name, offset = (m[1], int(m[2])) if m else (spec, 0)
            if name not in cache:
                cache[name] = files.load_sequence(library.resolve(name))
            parts.append((cache[name], offset))
        seq = superimpose(parts)
        files.save_sequence(args.out, seq)
    except (OSError, ValueError) as exc:
        return _fail("superimpose", exc)
    print(f"{args.out}: {len(seq)} frames")
    return 0


def _plot(args: argparse.Namespace) -> int:
    from apps.kas import files, library, plot

    targets = [(f, d) for f, d in (("hpgl", args.hpgl), ("svg", args.svg), ("pdf", args.pdf))
               if d]
    if not targets:
        return _fail("plot", ValueError("give --hpgl DIR, --svg DIR and/or --pdf DIR"))
    try:
        if min(args.width, args.height) <= 0 or args.margin < 0:
            raise ValueError("sizes must be positive")
        seq = files.load_sequence(library.resolve(args.seq))
        size = plot.PlotSize(args.width, args.height, args.margin)
        for fmt, d in targets:
            written = plot.plot_sequence(seq, d, fmt, size, _progress(f"plot {fmt}"))
            print(f"{fmt}: {len(written)} file(s) in {d}")
    except (OSError, ValueError) as exc:
        return _fail("plot", exc)
    return 0


def _export(args: argparse.Namespace) -> int:
    from apps.kas import files, library
    from apps.kas.export import export

    try:
        seq = files.load_sequence(library.resolve(args.seq))
        if args.renderer == "sigma":
            if args.width != 768:
                print("kas export: the Sigma renderer draws 768 x 512; --width applies to "
                      "--renderer raster", file=sys.stderr)
            out = _export_sigma(seq, args.out, args.background, _progress("export"))
        else:
            out = export(seq, args.out, args.width, args.background, _progress("export"))
    except (OSError, ValueError) as exc:
        return _fail("export", exc)
    print(f"wrote {out} ({args.renderer} renderer)")
    return 0


# ---------------------------------------------------------------------- device fronts
def _register_fronts(sub: argparse._SubParsersAction) -> None:
    ed = sub.add_parser("edit", help="the keyframe editor on the emulated Sigma T5684",
                        description="Edit keyframe FILE (created if missing) on an emulated "
                        "Sigma T5684 over a 9600-baud line: the stylus is the tablet (--tablet "
                        "SOURCE) or the mouse, keys are typed on the terminal. F2 saves. "
                        "--script runs a timed event script (see docs/kas.md); --headless "
                        "needs one.")
    ed.add_argument("file")
    _front_options(ed)
    ed.add_argument("--over", help="previous keyframe to draw over (§2.3 guide)")
    ed.add_argument("--seed", type=int, default=0, help="de-regularise random seed")
    ed.set_defaults(handler=_edit)

    pa = sub.add_parser("path", help="draw a sample path and tick marks on the Sigma",
                        description="Keyframes A and B shown superimposed; the stylus draws "
                        "the sample path, 't' then touches place tick marks; F2 (or the end "
                        "of a headless script) saves the path to --out and the ticks to "
                        "--ticks.")
    pa.add_argument("first")
    pa.add_argument("second")
    pa.add_argument("--out", required=True, help="sample path file to write")
    pa.add_argument("--ticks", help="tick timing file to write (default: OUT with _ticks)")
    pa.add_argument("--previous", help="the previous pair's path, shown for continuity "
                    "(default: the path last saved for a pair ending at FIRST, if any)")
    pa.add_argument("--no-library", action="store_true", help="do not keep the path in the "
                    "user library (nor look up the previous pair's)")
    _front_options(pa)
    pa.set_defaults(handler=_path)

    vw = sub.add_parser("view", help="the line test: play a sequence on the emulated Sigma",
                        description="Play SEQ on an emulated Sigma T5684 over the line, double "
                        "buffered in two 2-bit buffers (four colours). --realtime (default) "
                        "keeps period-line time and drops the frames the line cannot carry; "
                        "--every shows every frame however long it takes.")
    vw.add_argument("seq")
    g = vw.add_mutually_exclusive_group()
    g.add_argument("--realtime", dest="mode", action="store_const", const="realtime")
    g.add_argument("--every", dest="mode", action="store_const", const="every")
    vw.set_defaults(mode="realtime")
    vw.add_argument("--baud", type=int, default=9600)
    vw.add_argument("--fps", type=float, help="default: the sequence's")
    vw.add_argument("--swap", choices=("lut", "mask"), default="lut",
                    help="buffer switch: rewrite the LUT (default) or the display mask")
    vw.add_argument("--background", choices=("black", "white"), default="black")
    vw.add_argument("--headless", action="store_true", help="no window")
    vw.add_argument("--frames", type=Path, help="write the screen of every period as PNG here")
    vw.add_argument("--screenshot", type=Path, help="save the last screen as PNG")
    vw.add_argument("--scale", type=int, default=1)
    vw.set_defaults(handler=_view)


def _front_options(p: argparse.ArgumentParser) -> None:
    p.add_argument("--script", type=Path, help="timed event script (headless driving)")
    p.add_argument("--tablet", metavar="SOURCE", help="tablet source (see 'camlab88 tablet'); "
                   "default: the mouse")
    p.add_argument("--headless", action="store_true", help="no window (needs --script)")
    p.add_argument("--screenshot", type=Path, help="save the screen as PNG once the script "
                   "(or the start-up screen) has been drawn, then exit")
    p.add_argument("--background", choices=("black", "white"), default="black")
    p.add_argument("--baud", type=int, default=9600)
    p.add_argument("--scale", type=int, default=1)


def _edit(args: argparse.Namespace) -> int:
    from apps.kas import files, library
    from apps.kas.editor import Editor
    from apps.kas.front import EditorFront

    target = Path(args.file)
    try:
        start = files.load_keyframe(target) if target.exists() else None
        over = files.load_drawing_or_frame(library.resolve(args.over)) if args.over else None
        saved: list[int] = []

        def save(drawing) -> None:  # noqa: ANN001
            files.save_keyframe(target, drawing)
            saved.append(len(drawing.chains))
            front.editor.message = f"saved {target.name}"

        front = EditorFront(Editor(start, over, args.seed), args.background, save)
        session = _run_front(front, args, "kas edit")
    except (OSError, ValueError) as exc:
        return _fail("edit", exc)
    ed = front.editor
    if not saved:
        state = "NOT saved (F2 saves)" if ed.dirty else "nothing to save"
    elif ed.dirty:
        state = f"saved {target} earlier, but the last edits are NOT saved"
    else:
        state = f"saved {target}"
    print(f"kas edit: {len(ed.drawing.chains)} chains, {ed.drawing.n_points} points; {state}; "
          f"{session.line.stats['host_to_device_bytes']} characters to the Sigma")
    return 0


def _path(args: argparse.Namespace) -> int:
    from apps.kas import files, library
    from apps.kas.front import PathFront
    from apps.kas.path_editor import PathEditor

    out = Path(args.out)
    ticks = Path(args.ticks) if args.ticks else out.with_name(f"{out.stem}_ticks{out.suffix}")
    try:
        prev_file = library.resolve(args.previous) if args.previous else None
        if prev_file is None and not args.no_library:
            prev_file = library.previous_pair_path(args.first)
            if prev_file is not None:
                print(f"kas path: showing the previous pair's path {prev_file}")
        prev = files.load_path(prev_file) if prev_file is not None else None
        model = PathEditor(files.load_drawing_or_frame(library.resolve(args.first)),
                           files.load_drawing_or_frame(library.resolve(args.second)), prev)

        def save(path, timing) -> None:  # noqa: ANN001
            files.save_path(out, path)
            if len(timing.values):
                files.save_timing(ticks, timing)
            if not args.no_library:
                p_name, t_name = library.pair_names(args.first, args.second)
                files.save_path(library.user_file(p_name), path)
                if len(timing.values):
                    files.save_timing(library.user_file(t_name), timing)

        front = PathFront(model, args.background, save)
        _run_front(front, args, "kas path")
        path = model.sample_path()
        if args.script is not None:
            if path is None:
                raise ValueError(f"{args.script}: the script draws no path")
            save(path, model.timing())
    except (OSError, ValueError) as exc:
        return _fail("path", exc)
    if path is not None:
        print(f"kas path: {len(path.points)} path points, {len(model.ticks)} ticks -> {out}"
              + (f", {ticks}" if model.ticks else ""))
    return 0


def _run_front(front, args: argparse.Namespace, title: str):  # noqa: ANN001, ANN202
    """Run a front on an emulated T5684 over the line: from a script and/or a window."""
    from apps.kas.front.script import Session, parse_timed_script
    from emulator.sigma import Terminal
    from protocols.link import LineSettings

    events = []
    if args.script is not None:
        events = parse_timed_script(args.script.read_text(encoding="utf-8"), str(args.script))
    if args.headless and args.script is None:
        raise ValueError("--headless needs --script")
    term = Terminal("t5684")
    settings = LineSettings(baud=args.baud)
    if not args.headless and not _display():
        raise ValueError("no display for a window: give --headless and --script")
    if args.headless:
        session = Session(front, term, settings)
        session.run_script(events)
        if args.screenshot is not None:
            from camlab88.commands.sigma import write_png_atomic

            write_png_atomic(term.frame(), args.screenshot)
            print(f"{title}: screenshot {args.screenshot}")
        return session
    return _windowed(front, term, settings, events, args, title)


def _windowed(front, term, settings, events, args, title: str):  # noqa: ANN001, ANN202
    from apps.kas.front.keyboard import KEY_BYTES
    from apps.kas.front.script import Session
    from camlab88.commands.tablet import TabletInput
    from emulator.host_input import KeyDown, PointerButton, PointerMove, Quit
    from emulator.window import Window
    from protocols.link import Throttle
    from protocols.tablets.input_layer import MouseSample

    notices: list[str] = []
    tablet = TabletInput(args.tablet, area=_tablet_area(), notify=notices.append)
    session = Session(front, term, settings, pointer=tablet)
    window = Window(f"camlab88 {title} - Sigma T5684", (768, 512), scale=args.scale)
    throttle = Throttle(1.0)
    buttons = 0
    i = 0
    ticks = 0
    try:
        while True:
            mouse, keys = [], []
            if i < len(events):
                mouse, keys, i = session.due(events, i)
            for ev in window.poll():
                if isinstance(ev, Quit):
                    if front.may_close():
                        return session
                    continue
                if isinstance(ev, KeyDown):
                    if ev.key in KEY_BYTES:
                        keys.append(ev.key)
                    elif len(ev.char) == 1 and 0x20 <= ord(ev.char) <= 0x7E:
                        keys.append(ev.char)
                elif isinstance(ev, PointerMove | PointerButton):
                    if isinstance(ev, PointerButton) and ev.button == 1:
                        buttons = 1 if ev.pressed else 0
                    elif isinstance(ev, PointerMove):
                        buttons = 1 if 1 in ev.buttons else 0
                    mouse.append(MouseSample(ev.x, ev.y, buttons, (768, 512)))
            session.step(mouse, keys)
            while notices:
                print(f"{title}: {notices.pop(0)}", file=sys.stderr)
            ticks += 1
            if ticks % 4 == 0:
                window.show(term.frame())
            if args.screenshot is not None and i >= len(events) and not session.busy():
                window.show(term.frame())
                window.screenshot(args.screenshot)
                print(f"{title}: screenshot {args.screenshot}")
                return session
            if args.screenshot is None:
                throttle.pace(session.clock.exact)
    finally:
        tablet.close()
        window.close()


def _display() -> bool:
    import os

    return bool(os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY")
                or os.environ.get("SDL_VIDEODRIVER"))


class _Quit(Exception):
    """The window was closed."""


def _tablet_area():  # noqa: ANN202
    from apps.kas.front.layout import TABLET_AREA

    return TABLET_AREA


def _view(args: argparse.Namespace) -> int:
    from apps.kas import files, library
    from apps.kas.front.viewer import LineTest
    from camlab88.commands.sigma import write_png_atomic
    from emulator.sigma import Terminal

    headless = args.headless or not _display()
    try:
        seq = files.load_sequence(library.resolve(args.seq))
        test = LineTest(seq, args.swap, args.background)
        term = Terminal("t5684")
        window = None
        if not headless:
            from emulator.window import Window

            window = Window("camlab88 kas view - Sigma T5684", (768, 512), scale=args.scale)
        fps = args.fps or seq.fps

        def period(k: int, t) -> None:  # noqa: ANN001
            if args.frames is not None:
                write_png_atomic(t.frame(), args.frames / f"frame_{k:05d}.png")
            if window is not None:
                window.show(t.frame())
                if any(type(ev).__name__ == "Quit" for ev in window.poll()):
                    raise _Quit
                if args.screenshot is None:
                    window.wait_frame(fps)

        try:
            try:
                rep = test.run(args.mode, args.baud, args.fps, term, period)
            except _Quit:
                print("kas view: window closed")
                return 0
            if args.screenshot is not None:
                if window is not None:
                    window.show(term.frame())
                    window.screenshot(args.screenshot)
                else:
                    write_png_atomic(term.frame(), args.screenshot)
        finally:
            if window is not None:
                window.close()
    except (OSError, ValueError) as exc:
        return _fail("view", exc)
    print(rep.summary())
    print("shown:", " ".join(map(str, rep.shown_frames)))
    print("dropped:", " ".join(map(str, rep.dropped)) or "-")
    return 0


def _export_sigma(seq, out: str, background: str, progress) -> Path:  # noqa: ANN001
    """Each frame drawn on a fresh emulated T5684 (16 colours, the terminal's own vectors)."""
    from apps.kas.export import export
    from apps.kas.front.viewer import still_bytes
    from emulator.sigma import Terminal

    def on_sigma(frame):  # noqa: ANN001, ANN202
        term = Terminal("t5684")
        term.feed(still_bytes(frame, background))
        return term.frame()

    return export(seq, out, progress=progress, render_frame=on_sigma)


def _schedule(args: argparse.Namespace) -> int:
    from apps.kas import viewer_schedule as vs

    try:
        text = args.sizes
        if text.startswith("@"):
            text = ",".join(Path(text[1:]).read_text().split())
        sizes = [int(s) for s in text.split(",") if s.strip()]
        if any(s < 0 for s in sizes):
            raise ValueError("sizes must not be negative")
        sched = vs.realtime(sizes, args.fps, args.baud, args.bits_per_char)
    except (OSError, ValueError) as exc:
        return _fail("schedule", exc)
    print(f"{len(sched.shown)} shown, {len(sched.dropped)} dropped, {sched.end:.3f} s")
    print("shown:", " ".join(map(str, sched.shown_frames)))
    print("dropped:", " ".join(map(str, sched.dropped)))
    return 0


def _edit_script(args: argparse.Namespace) -> int:
    from apps.kas import files, library
    from apps.kas.editor import Editor
    from apps.kas.events import parse_script

    try:
        start = files.load_keyframe(library.resolve(args.start)) if args.start else None
        over = files.load_drawing_or_frame(library.resolve(args.over)) if args.over else None
        events = parse_script(Path(args.script).read_text(encoding="utf-8"), args.script)
        ed = Editor(start, over, args.seed)
        ed.run(events)
        files.save_keyframe(args.out, ed.drawing)
    except (OSError, ValueError) as exc:
        return _fail("edit-script", exc)
    print(f"{args.out}: {len(ed.drawing.chains)} chains, {ed.drawing.n_points} points"
          + (f"; {ed.message}" if ed.message else ""))
    return 0


def _path_script(args: argparse.Namespace) -> int:
    from apps.kas import files, library
    from apps.kas.events import parse_script
    from apps.kas.path_editor import PathEditor

    try:
        pe = PathEditor(files.load_drawing_or_frame(library.resolve(args.first)),
                        files.load_drawing_or_frame(library.resolve(args.second)))
        pe.run(parse_script(Path(args.script).read_text(encoding="utf-8"), args.script))
        path = pe.sample_path()
        if path is None:
            raise ValueError(f"{args.script}: the script draws no path")
        files.save_path(args.path_out, path)
        files.save_timing(args.timing_out, pe.timing())
    except (OSError, ValueError) as exc:
        return _fail("path-script", exc)
    print(f"path of {len(path.points)} points, {len(pe.ticks)} ticks "
          f"({len(pe.ticks) + 2} frames with the keyframes)")
    return 0


def _demo(args: argparse.Namespace) -> int:
    from apps.kas import demo, files

    try:
        seq = demo.build()
        files.save_sequence(args.out, seq)
    except (OSError, ValueError) as exc:
        return _fail("demo", exc)
    print(f"{args.out}: {len(seq)} frames")
    return 0


def _library(args: argparse.Namespace) -> int:
    from apps.kas import library

    if args.save:
        from apps.kas import files

        src, name = args.save
        loaders = {"keyframe": files.parse_keyframe, "sequence": files.parse_sequence,
                   "path": files.parse_path, "timing": files.parse_timing}
        try:
            text = Path(src).read_text(encoding="utf-8")
            first = text.split("\n", 1)[0].split()
            kind = first[1] if len(first) == 3 and first[0] == "KAS" else ""
            if kind not in loaders:
                raise files.KasFileError(src, 1, "not a KAS keyframe, sequence, path or "
                                         "timing file")
            loaders[kind](text, src)  # refuse a bad file before it enters the library
            dest = library.user_file(name)
            files.atomic_write(dest, text)
        except (OSError, ValueError, UnicodeDecodeError) as exc:
            return _fail("library", exc)
        print(f"kas library: {kind} {src} saved as {dest}")
        return 0
    print(f"user library: {library.user_dir()}")
    for name, kind, where in library.entries():
        print(f"{name:28} {kind:9} {where}")
    return 0
