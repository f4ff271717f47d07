"""Make the thesis's screen figures as session recordings: ``examples/figures/fig-N.session``.

Each figure is its program driven the way the figure's caption describes, by scripted input
through the harness (the same code a person's mouse and keyboard drive), ending on the
figure's picture. The input scripts are written to ``examples/figures/scripts/`` (kept in
the repository, so a person can read and edit them), then each program is run with
``--headless --events SCRIPT --record fig-N.session`` in a scratch directory, so the recording
holds plain file names and its inputs by content.

    python examples/figures/make_figures.py            # every figure
    python examples/figures/make_figures.py 7.2 6.5    # some
    python examples/figures/make_figures.py --docs     # docs/figures.md's table, from
                                                       # camlab88/figure_catalogue.toml

``camlab88 figures`` lists them, ``camlab88 figures 7.2`` replays one; tests/test_figures.py
replays every one with ``--check``.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import tempfile
from collections.abc import Callable
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parents[1]
SCRIPTS = HERE / "scripts"
sys.path.insert(0, str(ROOT))


# -- the CA program: scripts found by driving the program in process ------------------------
class _CA:
    """The CA program on an in-process Rainbow, keeping every line of input it is given, so
    menu positions that depend on the program's state are read off the running program."""

    def __init__(self, pattern: str, rules: str = "life") -> None:
        from camlab88.apps.ca.program import script_events
        from camlab88.apps.ca.program.program import CAProgram, Options
        from camlab88.emulator.machine import RainbowMachine

        self._se = script_events
        self.machine = RainbowMachine()
        self.program = CAProgram(self.machine.client, Options(pattern=pattern, rules=rules))
        self.mouse = script_events.MouseState()
        self.lines: list[str] = []

    def run(self, text: str) -> None:
        steps = self._se.parse(text, "<figure>", self.mouse)
        self._se.play(steps, self.machine.post, self.program.frame,
                      lambda: self.program.finished)
        self.lines.append(text.rstrip("\n"))

    def choose(self, item: str, x: int = 300, y: int = 300) -> None:
        from camlab88.apps.ca.program.demo import choose

        self.run(choose(item, x, y))

    def leave_editing(self) -> None:
        from camlab88.apps.ca.program.demo import leave_editing

        self.run(leave_editing())

    def auto_then_step(self, frames: int) -> None:
        """Out of editing, ``frames`` frames in auto mode (a generation a frame), then back
        to step mode, where the screen holds still for the figure."""
        self.leave_editing()
        self.choose("Auto mode")
        self.run(f"frames {frames}")
        self.choose("Step mode")

    def pick(self, item: str) -> None:
        from camlab88.protocols.rainbow.ui.menu import ROW_H

        menu = self.program.choice
        assert menu is not None, f"no choice menu is open for {item!r}"
        i = menu.items.index(item)
        x, y = menu.x + 10, menu.y + menu.scroll + i * ROW_H + ROW_H // 2
        self.run(f"move {x} {y}\nclick right {x} {y}\nframes 1")

    def type(self, text: str) -> None:
        self.run(f"type {text}\nkey return\nframes 1")

    def click_cell(self, cx: int, cy: int) -> None:
        v = self.program.view
        sx, sy = v.screen_of_cell(cx, cy)
        z = v.zoom or 1
        self.run(f"move {sx + z // 2} {sy + z // 2}\nclick right {sx + z // 2} {sy + z // 2}\n"
                 "frames 1")

    def script(self, comment: str) -> str:
        return "".join(f"# {c}\n" for c in comment.splitlines()) + "\n".join(self.lines) + "\n"


def _centre(ca: _CA) -> tuple[int, int]:
    x, y = ca.program.view.top_left_cell()
    return x + 23, y + 18  # zoom 16 shows 47 x 36 cells


def fig_7_1() -> str:
    ca = _CA("boat")
    ca.leave_editing()  # single step mode: nothing moves until the right button is clicked
    x0, y0 = ca.program.view.top_left_cell()
    for name, cx, cy in (("ship", 10, 4), ("beacon", 18, 4), ("catherine_wheel", 27, 3),
                         ("traffic_lights", 4, 20), ("tumbler", 17, 22)):
        ca.choose("Load pattern")
        ca.type(name)
        ca.click_cell(x0 + cx, y0 + cy)
        ca.pick("identity")
        ca.run("key escape\nframes 1")
    ca.run("frames 3")
    return ca.script("Figure 7.1: the boat (loaded at the start), then the ship, the beacon, "
                     "the Catherine wheel,\ntraffic lights and the tumbler placed by Load "
                     "pattern.")


def _side_by_side(caption: str, pattern: str, rules: str, copies: int, apart: int,
                  size: tuple[int, int]) -> str:
    """The script of ``copies`` of ``pattern`` in a row, ``apart`` cells between reference
    points, each advanced one generation more than the one on its left by "Advance area"
    (section 7.3.2: the rules apply only inside a rectangle, the way the thesis puts two guns
    out of phase): generations 0, 1, ... from left to right on one screen. ``size``: the
    pattern's cells."""
    ca = _CA(pattern, rules)  # loaded with its reference point at the view's centre cell
    ca.leave_editing()  # single step mode: nothing moves until the right button is clicked
    (gx, gy), = {(x, y) for (_, x, y) in ca.program.session._loaded}
    xs = [gx + apart * (k - copies // 2) for k in range(copies)]
    ca.choose("Load pattern")
    ca.type(pattern)
    first = True
    for x in xs:
        if x == gx:
            continue
        ca.click_cell(x, gy)
        if first:
            ca.pick("identity")  # the orientation is asked once, for the first copy
            first = False
    ca.run("key escape\nframes 1")
    w, h = size
    for k in range(1, copies):  # copies k.. one generation on
        ca.choose("Advance area")
        ca.pick("Advance a rectangle")
        ca.click_cell(xs[k] - 2, gy - 2)
        ca.click_cell(xs[-1] + w + 1, gy + h + 1)
        ca.run("click right 600 500\nframes 2")
    ca.choose("Advance area")
    ca.pick("Advance everywhere")
    ca.run("frames 2")
    return ca.script(caption)


def fig_7_2() -> str:
    return _side_by_side("Figure 7.2: a glider over five generations side by side: five "
                         "gliders loaded in a row, then\nAdvance area steps the 2nd to 5th one "
                         "generation, the 3rd to 5th another, ...: generations\n0 to 4 from "
                         "left to right, the fifth the first moved one cell diagonally.",
                         "glider", "life", 5, 8, (3, 3))


def fig_7_7() -> str:
    return _side_by_side("Figure 7.7: the 'movement' of a maze runner over four generations, "
                         "side by side: four copies\nof a runner (head red, tail blue) beside a "
                         "wall (green) that turns a corner, the 2nd to 4th\nadvanced one "
                         "generation, the 3rd and 4th another, the 4th a third: generations 0 "
                         "to 3.", "maze_corner", "maze", 4, 10, (7, 7))


def fig_7_3() -> str:
    ca = _CA("glider")
    ca.run("frames 2\npress middle 380 300\nframes 2")
    return ca.script("Figure 7.3: the editing screen, the middle button held: the menu from "
                     "which the editing method\nis chosen.")


def _after_auto(caption: str, frames: int, *pattern_and_rules: str) -> str:
    """The CA's screen after ``frames`` generations in auto mode, held in step mode."""
    ca = _CA(*pattern_and_rules)
    ca.auto_then_step(frames)
    ca.run("frames 2")
    return ca.script(caption)


def fig_7_4() -> str:
    """Section 7.3.2: "a monochrome display depicting two Gosper glider guns": a second gun
    loaded below and left of the first (out of its gliders' way), zoom 8, Alter display's
    Monochrome, then auto mode until each gun has sent several gliders on their way."""
    ca = _CA("gosper_gun")
    ca.leave_editing()
    ca.choose("Zoom 8")
    (gx, gy), = {(x, y) for (_, x, y) in ca.program.session._loaded}
    ca.choose("Load pattern")
    ca.type("gosper_gun")
    ca.click_cell(gx - GUN_APART[0], gy + GUN_APART[1])
    ca.pick("identity")
    ca.run("key escape\nframes 1")
    ca.choose("Centralise viewport")  # the two guns in the middle, room for their gliders
    ca.choose("Alter display")
    ca.pick("Monochrome")
    ca.choose("Auto mode")
    ca.run("frames 150")
    ca.choose("Step mode")
    ca.run("frames 2")
    return ca.script("Figure 7.4: two Gosper glider guns on a monochrome display: a second gun "
                     "loaded below and left\nof the first, zoom 8, Centralise viewport, Alter "
                     "display: Monochrome, then auto mode,\na generation a frame.")


GUN_APART = (24, 22)  # cells: the second gun clear of the first gun's stream of gliders


def fig_7_5() -> str:
    ca = _CA("gosper_gun")
    ca.auto_then_step(60)
    ca.choose("Alter display")
    ca.pick("Grid off")
    ca.choose("Zoom 8")
    ca.run("frames 2")
    return ca.script("Figure 7.5: zoom 16 with the grid (the gun firing), then the grid off "
                     "and zoom 8.")


FIG_7_9_GENERATION = 12  # the copy on the third row, the divisor 3, the head at the left end


def fig_7_9() -> str:
    """Section 7.4.2's moment: the number copied to the third row, 3 written between the
    copies, the head back at the left end "ready to begin the main part" (generation 12)."""
    ca = _CA("primes_25", "turing_primes")
    ca.auto_then_step(FIG_7_9_GENERATION - 1)  # the click into step mode shows one more
    ca.run("frames 2")
    assert ca.program.session.generation == FIG_7_9_GENERATION, ca.program.session.generation
    return ca.script("Figure 7.9: the three-tape Turing machine testing 25, at the figure's "
                     "moment: the number on the\ntop row, its copy on the third, the divisor "
                     "3 between them and the head back at the left\nend (generation 12); the "
                     "failure cross on the head's row, left of the machine, is invisible.")


# -- the snooker motion program: fixed scripts on its screen's coordinates ------------------
def fig_6_1() -> str:
    return "# Figure 6.1: the table ready for the start of a game.\nframes 10\n"


def fig_6_5() -> str:
    return ("# Figure 6.5: the cue ball selected, the middle button held: the orange menu.\n"
            "frames 5\nmove 175 325\nwait 2\npress middle\nwait 4\n")


def fig_6_6() -> str:
    return ("# Figure 6.6: setting the cue ball's velocity with the mouse arrow (the orange "
            "menu's\n# 'Change ball's velocity', then the rubber band held).\n"
            "frames 5\nmove 175 325\nwait 2\npress middle\nwait 2\nglide 175 400 25\nwait 2\n"
            "release middle\nwait 2\npress middle\nmove 250 318\nwait 1\nmove 330 310\n"
            "wait 1\nmove 440 300\nwait 3\n")


def fig_I_2() -> str:
    return ("# Appendix I, figure 2: a sample screen and its pad structure: the snooker program's "
            "screen\n# (table pad, double-buffered ball pads, cursor pad, message areas) with "
            "the green menu\n# open, and the inspector's pad graph from the screen down "
            "beside it (--inspect).\n"
            "frames 5\nmove 600 200\nwait 2\npress middle\nwait 4\n")


# -- KAS on the Sigma: the editor's script language (screen inches, centre origin, y up) ----
_DRAW = """move -4 -2
down -4 -2
down -3.8 -1.9
down -3.6 -1.7
down -3.4 -1.8
down -3.2 -1.5
up -3.2 -1.5
down -2.5 -1.5
up -2.5 -1.5
key space
menu pen2
down -4 1
up -4 1
down -3 2
up -3 2
down -2 1
up -2 1
down -2 1.5
up -2 1.5
key space
key n
key 3
key r
down 1 1
up 1 1
down 3 2.5
up 3 2.5
key 4
key c
down 2 -1.5
up 2 -1.5
down 2.8 -1.5
up 2.8 -1.5
key 5
down -1 -3
up -1 -3
down 0 -3.5
up 0 -3.5
key space
"""


def fig_3_1() -> str:
    return ("# Figure 3.1: KAS's screen layout (black background): the menu row along the top,\n"
            "# a freehand chain, a straight-line chain in red, a rectangle, a circle and a line.\n"
            + _DRAW)


def fig_3_2() -> str:
    return ("# Figure 3.2: KAS in edit mode: the drawing of figure 3.1, then edit mode, a point\n"
            "# squared and triangled, and two points moved: moved lines bright, their old\n"
            "# positions purple, the rest dull.\n" + _DRAW
            + "menu edit\nkey g\nmove 0 0\ndown -4 -2\nup -4 -2\nkey tab\ndown -3.4 -1.8\n"
            "up -3.4 -1.8\nkey tab\nkey m\ndown 0 0\nup 0 0\ndown 0.2 0.3\nup 0.2 0.3\n"
            "key ]\nkey tab\nkey ]\nkey ]\nkey tab\nkey l\ndown 0 0\nup 0 0\n"
            "down 0.5 -0.25\nup 0.5 -0.25\n")


def _face_sequence() -> dict[str, bytes]:
    """A face in a hat as a one-frame KAS sequence: head, two eyes, a smile, and a hat (crown
    and brim) whose brim crosses the head -- the drawing of figure 3.8's kind."""
    import math

    def circle(cx: float, cy: float, r: float, n: int) -> list[tuple[float, float]]:
        return [(cx + r * math.cos(2 * math.pi * k / n), cy + r * math.sin(2 * math.pi * k / n))
                for k in range(n + 1)]

    chains = [(1, circle(0, -0.5, 2.0, 40)), (3, circle(-0.7, 0, 0.3, 16)),
              (3, circle(0.7, 0, 0.3, 16)),
              (2, [(-1.0, -1.2), (-0.5, -1.6), (0.0, -1.75), (0.5, -1.6), (1.0, -1.2)]),
              (1, [(-1.2, 1.0), (-1.0, 3.0), (1.0, 3.0), (1.2, 1.0)]),
              (1, [(2.2, 1.0), (-2.2, 1.0)])]
    out = ["KAS sequence 1", "fps 25", "frames 1", "frame 0", f"chains {len(chains)}"]
    for pen, pts in chains:
        out.append(f"chain section=1 points={len(pts)}")
        out += [f"{x:.3f} {y:.3f} {pen}" for x, y in pts]
    return {"face.kas": ("\n".join([*out, "end"]) + "\n").encode()}


_PAINT = """colour 10
select 0 -2.5
fill
clear
colour 1
select -0.7 -0.3
fill
clear
select 0.7 -0.3
fill
clear
colour 2
select 0 -1.75
fill
clear
colour 4
select 0 3.0
select -2.1 1.0
fill
clear
"""


def fig_3_8() -> str:
    return ("# Figure 3.8: painting an outline image: the head, the eyes, the smile and the hat\n"
            "# each selected (the chain nearest the point) and filled, in that order.\n"
            + _PAINT)


def fig_3_7() -> str:
    return ("# Figure 3.7: the four working areas at quarter size (the painting of figure 3.8,\n"
            "# then the preview: painting bottom right, mixing top right, the double buffers\n"
            "# on the left).\n" + _PAINT + "show preview\n")


def _pink_shot() -> dict[str, bytes]:
    """The thesis example's shot and its views (§6.3.1's script), frames 1-70: the
    visualiser ends on the last command's view, behind the pink looking at the pocket."""
    from camlab88.apps.snooker.camera import ccl, motion
    from camlab88.apps.snooker.visualiser.demo import EXAMPLE_SCRIPT, example_shot

    with tempfile.TemporaryDirectory() as tmp:
        cp = Path(tmp) / "pink_shot.cp"
        example_shot().checkpoint().write(cp)
        views = ccl.compile_script(EXAMPLE_SCRIPT, motion.load(cp)).views()[:70]
        text = "# the thesis example camera script (section 6.3.1) over its shot, frames 1-70\n"
        text += "".join(v.to_line() + "\n" for v in views)
        return {"pink_shot.cp": cp.read_bytes(), "example.views": text.encode()}


def _pair() -> dict[str, bytes]:
    """Figure 3.6's keyframes: a flag (pole and pennant) on the right, and the same flag
    moved up and left with its pennant turned to face the other way, so each pair of
    corresponding points is a different distance and direction apart."""
    from camlab88.apps.kas import files
    from camlab88.apps.kas.model import Chain, Drawing

    def flag(x: float, y: float, s: float) -> Drawing:
        return Drawing([Chain.from_points([(x, y), (x, y + 2.0)], 1),
                        Chain.from_points([(x, y + 2.0), (x + 1.2 * s, y + 1.6),
                                           (x, y + 1.2)], 2)])

    return {"flag_a.kas": files.keyframe_text(flag(2.5, -3.0, 1.0)).encode(),
            "flag_b.kas": files.keyframe_text(flag(-2.5, 0.5, -1.0)).encode()}


def fig_3_6() -> str:
    return ("# Figure 3.6: the in-betweener's set-up: both keyframes superimposed (the flag,\n"
            "# then moved with its pennant turned), one sample path drawn in one stroke from the\n"
            "# foot of the pole to its new place (an arch), then t and five tick marks. The one\n"
            "# path is stretched and reflected to fit between each pair of points.\n"
            "down 2.5 -3\ndown 2.2 -1.6\ndown 1.4 -0.5\ndown 0.3 0.3\ndown -1 0.7\n"
            "down -2 0.7\ndown -2.5 0.5\nup -2.5 0.5\nkey t\n"
            "down 2.3 -1.9\nup 2.3 -1.9\ndown 1.6 -0.7\nup 1.6 -0.7\ndown 0.3 0.3\n"
            "up 0.3 0.3\ndown -1 0.7\nup -1 0.7\ndown -2 0.7\nup -2 0.7\n")


def _antialias() -> dict[str, bytes]:
    """Figure 6.8: the anti-aliasing demonstration as Sigma orders, made by the renderer's
    own coverage kernel (apps/snooker/render/antialias_figure.py)."""
    from camlab88.apps.snooker.render.antialias_figure import screen

    return {"antialias.sigma": screen()}


# Figure 6.9's view: the baulk colours and the cue ball close up, the blue and the pack
# beyond, so each ball's four shadows and highlights (the canopy's four bulbs) show.
TABLE_VIEW = "1 -1.9 -0.5 0.45 -0.9 0.0 0.0 50"
TABLE_BAUD = 115200  # the picture is the same at any speed; 9600 would be 156 s of line


def _shaded_table() -> dict[str, bytes]:
    """Figure 6.9: the opening position rendered by the period renderer (§6.4) as the Sigma
    orders it sends the T5688, setup and one frame."""
    from camlab88.apps.snooker.camera.views import parse_views
    from camlab88.apps.snooker.render.palette import fixed_palette
    from camlab88.apps.snooker.render.scene import Scene
    from camlab88.apps.snooker.render.sigma_host import SigmaHost
    from camlab88.apps.snooker.session import Session

    scene = Scene.from_checkpoint(Session.new_game().checkpoint())
    host = SigmaHost(scene, fixed_palette(scene), "period")
    frame = host.frame(parse_views(TABLE_VIEW + "\n")[0])
    return {"table.sigma": host.setup() + frame.data}


def _seconds(name: str, data: bytes, baud: int) -> list[str]:
    """``--seconds``: the stream's line time (10 bits a byte) and a little more."""
    return ["--in", name, "--baud", str(baud), "--seconds",
            str(int(len(data) * 10 / baud) + 2)]


KAS = ["kas", "edit", "figure.kas", "--headless"]
CA = ["ca", "program", "--headless"]
SNOOKER = ["snooker", "play", "--headless"]
PAINT = ["kas", "paint", "face.kas", "--headless"]
PATH = ["kas", "path", "flag_a.kas", "flag_b.kas", "--out", "flag_path.kas", "--no-library",
        "--headless"]
VISUALISE = ["snooker", "visualise", "pink_shot.cp", "example.views", "--headless"]
SIGMA = ["sigma", "run", "--model", "t5688", "--headless"]  # + _seconds(): a stream's length
INPUTS: dict[str, Callable[[], dict[str, bytes]]] = {
    "3.6": _pair, "3.7": _face_sequence, "3.8": _face_sequence, "6.7": _pink_shot,
    "6.8": _antialias, "6.9": _shaded_table}
BAUD = {"6.8": 9600, "6.9": TABLE_BAUD}
FIGURES: dict[str, tuple[list[str], Callable[[], str] | None]] = {
    "3.6": (PATH, fig_3_6),
    "3.7": (PAINT, fig_3_7),
    "3.8": (PAINT, fig_3_8),
    "6.7": (VISUALISE, None),
    "6.8": (SIGMA, None),
    "6.9": (SIGMA, None),
    "3.1": (KAS, fig_3_1),
    "3.2": (KAS, fig_3_2),
    "6.1": (SNOOKER, fig_6_1),
    "6.5": (SNOOKER, fig_6_5),
    "6.6": (SNOOKER, fig_6_6),
    "I.2": ([*SNOOKER, "--inspect"], fig_I_2),
    "7.1": ([*CA, "--pattern", "boat"], fig_7_1),
    "7.2": ([*CA, "--pattern", "glider"], fig_7_2),
    "7.3": ([*CA, "--pattern", "glider"], fig_7_3),
    "7.4": ([*CA, "--pattern", "gosper_gun"], fig_7_4),
    "7.5": ([*CA, "--pattern", "gosper_gun"], fig_7_5),
    "7.7": ([*CA, "--rules", "maze", "--pattern", "maze_corner"], fig_7_7),
    "7.9": ([*CA, "--rules", "turing_primes", "--pattern", "primes_25"], fig_7_9),
}


def _script_args(number: str, argv: list[str], tmp: Path) -> list[str]:
    """Write the figure's input script (kept in scripts/) and return its option."""
    script = FIGURES[number][1]
    if script is None:
        return []
    kas = argv[0] == "kas"
    path = SCRIPTS / f"fig-{number}.{'script' if kas else 'events'}"
    SCRIPTS.mkdir(parents=True, exist_ok=True)
    path.write_text(script(), encoding="utf-8")
    shutil.copy(path, tmp / path.name)
    return ["--script" if kas else "--events", path.name]


def make(number: str) -> Path:
    argv = FIGURES[number][0]
    out = HERE / f"fig-{number}.session"
    with tempfile.TemporaryDirectory() as scratch:
        tmp = Path(scratch)
        for name, data in INPUTS.get(number, dict)().items():
            (tmp / name).write_bytes(data)
            if argv is SIGMA:
                argv = [*argv, *_seconds(name, data, BAUD[number])]
        env = {**os.environ, "PYTHONPATH": str(ROOT)}
        for k in ("DISPLAY", "WAYLAND_DISPLAY", "SDL_VIDEODRIVER"):
            env.pop(k, None)
        cmd = [sys.executable, "-m", "camlab88", *argv, *_script_args(number, argv, tmp),
               "--record", out.name]
        subprocess.run(cmd, cwd=tmp, env=env, check=True)
        shutil.copy(tmp / out.name, out)
        # the gallery's picture: the recording's last screen, as `camlab88 figures N` shows it
        subprocess.run([sys.executable, "-m", "camlab88", "figures", number, "--headless",
                        "--screenshot", str(IMAGES / f"fig-{number}.png")], cwd=tmp, env=env,
                       check=True)
    return out


DOCS = ROOT / "docs" / "figures.md"
IMAGES = ROOT / "docs" / "images" / "figures"
TABLE_START, TABLE_END = "<!-- table: make_figures.py --docs -->", "<!-- end of table -->"


def write_docs() -> None:
    """Put the catalogue's table between docs/figures.md's markers."""
    from camlab88.base.atomicfile import write_atomic
    from camlab88.figure_catalogue import markdown_table

    text = DOCS.read_text(encoding="utf-8")
    head, rest = text.split(TABLE_START, 1)
    tail = rest.split(TABLE_END, 1)[1]
    write_atomic(DOCS, f"{head}{TABLE_START}\n{markdown_table()}{TABLE_END}{tail}")


def main(argv: list[str]) -> int:
    if argv == ["--docs"]:
        write_docs()
        print(f"{DOCS.relative_to(ROOT)}: the table written from the catalogue")
        return 0
    wanted = argv or list(FIGURES)
    unknown = [n for n in wanted if n not in FIGURES]
    if unknown:
        print(f"make_figures: no figure {', '.join(unknown)} (figures: {', '.join(FIGURES)})",
              file=sys.stderr)
        return 2
    for n in wanted:
        out = make(n)
        print(f"{out.relative_to(ROOT)}: {out.stat().st_size} bytes")
    return 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
