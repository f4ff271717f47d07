"""Regenerate every file in examples/ with the project's own code.

    python examples/make_examples.py            # rewrite examples/ in place
    python examples/make_examples.py --out DIR  # write them somewhere else (the tests do)

Sigma streams are formed by protocols.sigma's drivers in the three real host styles; the
KAS and CA scripts are written here as text (they are what an animator would type); the CA
log, the snooker checkpoint and session are made by running the programs on them. Every
file comes out byte-identical on every run (tests/test_examples.py checks that the
shipped ones are up to date).
"""

from __future__ import annotations

import argparse
import base64
import contextlib
import io
import json
import math
import os
import sys
from collections.abc import Callable
from pathlib import Path

from camlab88.base.atomicfile import write_atomic
from camlab88.protocols.sigma.drivers import PgplotGoc, RalGks
from camlab88.protocols.sigma.encoder import Encoder
from camlab88.protocols.sigma.orders import CR, GRAPHICS_FLAG, LF

HERE = Path(__file__).resolve().parent


# ---------------------------------------------------------------- Sigma streams
def pgplot_goc() -> bytes:
    """A PGPLOT /GOC graph: a box with ticks, a damped oscillation, its maxima as dots."""
    g = PgplotGoc()
    g.init()
    g.erase()
    g.colour(1)
    g.frame(96, 64, 704, 448, xticks=9, yticks=7)
    curve = [(96 + 2 * i, 256 + round(170 * math.exp(-i / 160) * math.cos(i / 12)))
             for i in range(305)]
    g.polyline(curve)
    for i in range(0, 305, 75):  # every other extremum (period 2 pi * 12 = 75.4 points)
        g.dot(*curve[i])
    return g.finish()


GKS_COLOURS = [(0, 0, 0), (1, 1, 1), (1, 0, 0), (0, 1, 0), (0, 0, 1), (1, 1, 0), (1, 0, 1),
               (0, 1, 1), (0.5, 0.5, 0.5), (1, 0.5, 0), (0.5, 0, 1), (0, 0.5, 0.2),
               (0.3, 0.3, 0.6), (0.9, 0.7, 0.6), (0.2, 0.6, 0.9), (0.7, 0.7, 0.7)]


def ral_gks(high_res: bool) -> bytes:
    """A RAL GKS picture: a colour table, a spiral in each line type, a cell array."""
    g = RalGks(high_res=high_res)
    g.open(GKS_COLOURS)
    g.clear()
    s = 2 if high_res else 1
    for lt in range(1, 5):
        g.linetype(lt)
        g.colour(lt + 1)
        cx, cy = (150 + 170 * (lt - 1)) * s, 330 * s
        g.polyline([(cx + round(s * (8 + t) * math.cos(t / 4)),
                     cy + round(s * (8 + t) * math.sin(t / 4))) for t in range(0, 70)])
    g.linetype(1)
    for row in range(40):  # a cell array: 16 colours in diagonal bands
        g.cell_row(160 * s, (60 + row) * s, [(row // 4 + col // 8) % 16 for col in range(448)])
    g.message("RAL GKS")
    stream = g.finish()
    if high_res:  # shown whole at half size: the reconstructed KQ4 view order (README)
        stream += GRAPHICS_FLAG + Encoder().view(4) + b"BH"
    return stream


def crystals_cameron() -> bytes:
    """CAMERON's SIGMA device style (CRYSTALS, facts/sigma.md S6): FC before every polyline
    and polygon, HI colours, firmware ellipses (JO ratio, JM/JN size), polygons filled from
    a seed with JK, text in 6-character BA fields -- a molecule-like drawing of atoms and
    bonds. CAMERON sends the fill seed without the +100 excess (facts S6: probably a bug),
    so the terminal finds it 100 units down and left of where CAMERON meant."""
    e = Encoder()
    out = bytearray(bytes((CR, LF)) + GRAPHICS_FLAG + e.erase())
    atoms = [(250, 300, 2), (400, 360, 3), (550, 300, 2), (400, 200, 5), (250, 150, 6)]
    for (x0, y0, _), (x1, y1, _) in zip(atoms, atoms[1:]):
        out += e.line_solid() + e.colour(1) + e.move(x0, y0) + e.draw(x1, y1)
    for x, y, colour in atoms:
        out += e.colour(colour) + e.move(x, y) + e.ellipse(28, 1.0, solid=True)
        out += e.colour(1) + e.move(x, y) + e.ellipse(34, 1.0)
    ring = [(600, 120), (720, 120), (720, 240), (600, 240), (600, 120)]  # a polygon, filled
    out += e.line_solid() + e.colour(4) + e.polyline(ring)
    seed_x, seed_y = 710, 230  # meant; arrives as (610, 130), still inside the square
    out += e.pen_up() + e.pair(seed_x - 100, seed_y - 100) + e.fill(4)
    for k, label in enumerate(("C1", "N2", "C3", "O4", "S5")):
        x, y, _ = atoms[k]
        out += e.move(x + 40, y + 30) + e.colour(7) + e.text(f"{label:<6}")
    out += e.alpha_mode()
    return bytes(out)


# ---------------------------------------------------------------- Rainbow scene
def rainbow_scene() -> str:
    """Pads and clusters: a grey background, a 4-bit gradient pad mapped twice, a 3-bit
    ring pad in front, all through one LUT (docs/rainbow.md, "Scene files")."""
    size = 96
    grad = bytes((x + y) * 15 // (2 * size - 2) for y in range(size) for x in range(size))
    ring = bytes(7 if 30 <= math.hypot(x - 47.5, y - 47.5) < 44 else 0
                 for y in range(size) for x in range(size))
    # The LUT index is page * 256 + the pixel's planes: the gradient's values sit in planes
    # 1-4 (page 1), the ring's 7 in planes 5-7 (page 2, its 0 pixels the background colour).
    lut = [[0, "#202830"]]
    lut += [[256 + (i << 1), f"#{16 * i:02x}40{255 - 16 * i:02x}"] for i in range(16)]
    lut += [[512, "#202830"], [512 + (7 << 5), "#f0d020"]]
    scene = {
        "lut": lut,
        "nodes": {
            "back": {"type": "pad", "width": 768, "height": 576, "depth": 1, "fill": 0},
            "gradient": {"type": "pad", "width": size, "height": size, "depth": 4,
                         "plane": 1, "lut_page": 1,
                         "pixels": base64.b64encode(grad).decode("ascii")},
            "ring": {"type": "pad", "width": size, "height": size, "depth": 3, "plane": 5,
                     "lut_page": 2, "pixels": base64.b64encode(ring).decode("ascii")},
            "group": {"type": "cluster", "width": 400, "height": 200},
        },
        "arcs": [
            {"parent": "screen", "child": "back"},
            {"parent": "screen", "child": "group", "x": 184, "y": 188, "priority": 1},
            {"parent": "group", "child": "gradient", "x": 20, "y": 50},
            {"parent": "group", "child": "gradient", "x": 280, "y": 50},
            {"parent": "group", "child": "ring", "x": 150, "y": 50, "priority": 1},
        ],
    }
    return json.dumps(scene, indent=1) + "\n"


# ---------------------------------------------------------------- KAS scripts
KAS_KEYFRAME_SCRIPT = """\
# A KAS editor event script (docs/kas.md "Event scripts"): `camlab88 kas edit-script
# examples/kas/house.script --out house_a.kas` feeds these events to the keyframe editor.
# Units: inches of the twelve-field, (0, 0) its centre.
# --- a white house: walls and roof as one chain, touched corner by corner
key 1
down -2 -2
up -2 -2
down 2 -2
up 2 -2
down 2 1
up 2 1
down 0 2.5
up 0 2.5
down -2 1
up -2 1
down -2 -2
up -2 -2
key space
# --- a yellow door in a new section
key n
key 5
down -0.5 -2
up -0.5 -2
down -0.5 -0.5
up -0.5 -0.5
down 0.5 -0.5
up 0.5 -0.5
down 0.5 -2
up 0.5 -2
key space
"""

KAS_MOVE_SCRIPT = """\
# The next keyframe, made from the first by edit-mode commands: `camlab88 kas edit-script
# examples/kas/move.script --start house_a.kas --out house_b.kas`.
menu edit
# l: move the line-chain under the square cursor (the walls), touch from, touch to
key l
down 0 0
up 0 0
down 4 1
up 4 1
# ]: the next chain (the door), moved by the same vector
key ]
key l
down 0 0
up 0 0
down 4 1
up 4 1
"""

KAS_PATH_SCRIPT = """\
# A KAS in-betweener set-up script (docs/kas.md "In-betweening"): `camlab88 kas path-script
# house_a.kas house_b.kas examples/kas/arc.script --path-out arc.kas --timing-out
# arc_ticks.kas` (keyframes from house.script and move.script).
# One stylus stroke draws the sample path (an arc), then `t` and a touch per tick mark.
down -4 0
down -3 1.2
down -1.5 1.9
down 0 2.1
down 1.5 1.9
down 3 1.2
down 4 0
up 4 0
key t
down -3.6 0.6
up -3.6 0.6
down -2.5 1.5
up -2.5 1.5
down -0.8 2
up -0.8 2
down 1.5 1.9
up 1.5 1.9
down 3.4 0.9
up 3.4 0.9
"""


# ---------------------------------------------------------------- CA script
CA_EVENTS = """\
# Scripted mouse input for `camlab88 ca program --headless --events FILE` (the Rainbow
# script language, protocols/rainbow/script.py). The grid shows 16-pixel cells at zoom 16.
frames 5
# The program starts in edit mode: the right button sets cells (a blinker beside the glider).
click right 300 300
click right 316 300
click right 332 300
frames 2
# The edit menu's centre item, "Leave editing" (middle button pressed and released in place).
press middle 400 300
release middle 400 300
frames 2
# Step mode: every right click computes the next generation.
click right 300 300
frames 2
click right 300 300
frames 2
click right 300 300
frames 2
click right 300 300
frames 2
# The left button held pans the view (recorded with --record-pans).
drag left 300 300 340 320
frames 3
"""


# Hand-written: the chessmen of docs/ca_actors.md and the camera of the README's glider-gun film.
CHESS_ACTORS = """\
# Chessmen for the cellular automaton's cell types (thesis 8.1). Units are cells: a cell is a
# 1 x 1 square of the floor; z is up. Life uses state 1 (pawns); the maze runner uses
# 1 (walls: pawns), 2 (head: the knight) and 3 (tail: rooks); 4 is a king for your own rules.
rules life

actor 1 pawn
  colour 236 226 200
  material ambient 0.3 diffuse 0.8 specular 0.5 shininess 30
  lathe 0.36 0  0.36 0.06  0.3 0.1  0.2 0.14  0.13 0.3  0.11 0.46  0.2 0.5  0.2 0.54  0.09 0.58
  sphere 0.15 at 0 0 0.54
  bob 0.04 24
end

actor 2 knight
  colour 60 44 40
  material ambient 0.3 diffuse 0.7 specular 0.8 shininess 60
  lathe 0.38 0  0.38 0.07  0.3 0.11  0.22 0.16  0.2 0.3
  extrude -0.16 -0.12  0.2 -0.12  0.2 0.12  -0.16 0.12 height 0.45 at 0 0 0.3
  box 0.16 0.42 0.14 at 0 0.14 0.6
  sphere 0.06 at 0 -0.1 0.74
  turn 360 48
end

actor 3 rook
  colour 200 60 50
  material ambient 0.3 diffuse 0.8 specular 0.4 shininess 20
  lathe 0.38 0  0.38 0.08  0.3 0.12  0.24 0.16  0.2 0.6  0.27 0.64  0.27 0.74
  box 0.1 0.1 0.1 at 0.19 0 0.74
  box 0.1 0.1 0.1 at -0.19 0 0.74
  box 0.1 0.1 0.1 at 0 0.19 0.74
  box 0.1 0.1 0.1 at 0 -0.19 0.74
end

actor 4 king
  colour 230 190 60
  material ambient 0.3 diffuse 0.7 specular 0.9 shininess 80
  lathe 0.4 0  0.4 0.08  0.3 0.13  0.22 0.2  0.14 0.7  0.24 0.76  0.2 0.8  0.26 0.96  0.1 1
  box 0.06 0.06 0.26 at 0 0 1
  box 0.2 0.06 0.06 at 0 0 1.1
  turn 90 96
end
"""

GUN_CAMERA = """\
The glider gun as chessmen (docs/ca_film.md). Event numbers are generations, coordinates
are cells (x along the columns, y down the rows, z up) from the top-left corner of the
pattern, and everything before this first colon is a comment:
FROM 1 UNTIL END; OBSERVER MOVING FROM (6, 29, 9) TO (28, 31, 8);
  VIEWPOINT MOVING FROM (17, 8, 0) TO (22, 12, 0); FOCAL LENGTH OF 26
"""


# ---------------------------------------------------------------- running the programs
def _cli(argv: list[str]) -> None:
    """Run a camlab88 command in this process, its report kept off the terminal."""
    from camlab88.cli import main

    with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(io.StringIO()):
        status = main(argv)
    if status != 0:
        raise SystemExit(f"make_examples: camlab88 {' '.join(argv)} failed ({status})")


def ca_log(out: Path) -> None:
    """The Log of a CA session driven by the event script (thesis section 7.3.1)."""
    log = out / "ca" / "session.log"
    log.unlink(missing_ok=True)  # a fresh log, not a continued one
    _cli(["ca", "program", "--headless", "--pattern", "glider", "--events",
          str(out / "ca" / "session.events"), "--log", str(log), "--record-pans"])


def ca_actors_session(out: Path) -> None:
    """The actor editor's demonstration, recorded (plain file names, as a user records):
    ``camlab88 replay examples/ca/actors_edit.session --check`` replays it."""
    home = Path.cwd()
    os.chdir(out / "ca")
    try:
        Path("pawn.actors").unlink(missing_ok=True)
        _cli(["ca", "actors", "pawn.actors", "--rules", "maze", "--headless", "--events",
              "actors_edit.events", "--record", "actors_edit.session"])
        Path("pawn.actors").unlink()  # the saved file is the session's, not an example
    finally:
        os.chdir(home)


def snooker_files(out: Path) -> None:
    """A new game saved before the break (a session) and the break played out
    (a §6.2.2 checkpoint)."""
    from camlab88.apps.snooker.session import Session

    Session.new_game().save(out / "snooker" / "opening.json")
    _cli(["snooker", "simulate", "--break", "5", "--out", str(out / "snooker" / "break.cp")])


# Hand-written: the walking figure of docs/ca_actors.md (§8.1's "a human figure").
WALKER_ACTORS = """\
# A walking human figure built from parts (thesis 8.1: "each cell as an animated object in
# its own right (a human figure for example) ... each actor undergoing its own independent
# motion"), for the maze runner's rules: the runner's head (2) is the walker, its tail (3) a
# footprint tile, the walls (1) low hedges. Units are cells; z is up. Legs and arms swing
# about the hip and the shoulder (`swing PIVOT_Z DEGREES PERIOD PHASE`), left and right half
# a period apart; `phase individual` gives every walker its own clock (from where and when
# it was born), so two runners do not walk in step. Its front is its own -y (feet and nose
# point that way); `face glide` turns it to face the way it walks.
rules maze

actor 1 hedge
  colour 60 120 50
  material ambient 0.3 diffuse 0.8 specular 0.1 shininess 8
  box 0.9 0.9 0.3
end

actor 2 walker
  colour 220 180 140
  material ambient 0.3 diffuse 0.8 specular 0.3 shininess 20
  box 0.12 0.14 0.42 at -0.09 0 0 swing 0.44 30 16 0
  box 0.12 0.14 0.42 at 0.09 0 0 swing 0.44 30 16 0.5
  extrude -0.06 -0.17 0.06 -0.17 0.06 0.07 -0.06 0.07 height 0.06 at -0.09 0 0 swing 0.44 30 16 0
  extrude -0.06 -0.17 0.06 -0.17 0.06 0.07 -0.06 0.07 height 0.06 at 0.09 0 0 swing 0.44 30 16 0.5
  box 0.34 0.2 0.36 at 0 0 0.42
  box 0.08 0.1 0.34 at -0.23 0 0.44 swing 0.78 25 16 0.5
  box 0.08 0.1 0.34 at 0.23 0 0.44 swing 0.78 25 16 0
  sphere 0.12 at 0 0 0.8
  sphere 0.035 at 0 -0.11 0.88
  phase individual
  face glide
end
"""


TEXT_FILES: dict[str, Callable[[], str]] = {
    "rainbow/scene.json": rainbow_scene,
    "kas/house.script": lambda: KAS_KEYFRAME_SCRIPT,
    "kas/move.script": lambda: KAS_MOVE_SCRIPT,
    "kas/arc.script": lambda: KAS_PATH_SCRIPT,
    "ca/session.events": lambda: CA_EVENTS,
    "ca/actors_edit.events": lambda: _actors_events(),
    "ca/chess.actors": lambda: CHESS_ACTORS,
    "ca/walker.actors": lambda: WALKER_ACTORS,
    "ca/gun.ccl": lambda: GUN_CAMERA,
}
STREAMS: dict[str, Callable[[], bytes]] = {
    "sigma/pgplot_goc.sig": pgplot_goc,
    "sigma/ral_gks_t5684.sig": lambda: ral_gks(False),
    "sigma/ral_gks_t5688.sig": lambda: ral_gks(True),
    "sigma/crystals_cameron.sig": crystals_cameron,
}
MADE = ["ca/session.log", "snooker/opening.json", "snooker/break.cp",
        "ca/actors_edit.session"]


def _actors_events() -> str:
    from camlab88.apps.actors.editor.demo import demo_events

    return demo_events()


def make(out: Path) -> list[Path]:
    """Write every example under ``out``; returns the files written."""
    for sub in ("sigma", "rainbow", "kas", "ca", "snooker"):
        (out / sub).mkdir(parents=True, exist_ok=True)
    for name, text in TEXT_FILES.items():
        write_atomic(out / name, text())
    for name, stream in STREAMS.items():
        write_atomic(out / name, stream())
    ca_log(out)
    ca_actors_session(out)
    snooker_files(out)
    return [out / n for n in (*TEXT_FILES, *STREAMS, *MADE)]


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--out", type=Path, default=HERE, help="directory (default: examples/)")
    args = ap.parse_args(argv)
    os.environ.setdefault("SDL_VIDEODRIVER", "dummy")  # the CA program runs headless
    written = make(args.out)
    print(f"wrote {len(written)} files under {args.out}:")
    for p in written:
        print(f"  {p.relative_to(args.out)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
