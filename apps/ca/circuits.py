"""Generator of the stylised electronic-circuit rules of section 7.4.3 (RECONSTRUCTED).

The thesis describes but does not print these rules.  Elements, as it lists them ("the
logic values 0 and 1 (both static and moving across the grid in various directions)"):

* logic values 0 and 1 moving east, south, west or north (``P(v, d)``): each generation a
  value passes a message to the cell ahead (which becomes it) and tells its four neighbours
  it is there and which value it carries;
* static logic values 0 and 1 (``S(v)``): a cell that stays put holding a level, like a wire
  tied high or low, and tells its four neighbours its value every generation.  A gate
  beside it counts it as one more input, but only moving values make a gate fire (a static
  level alone would make it fire every generation); a moving value running into it is
  absorbed and sets its level (so it also serves as a one-bit latch);
* mirrors (``M(d)``, turning a stream through a right angle or emitting a gate's output):
  a value arriving from any side, or a gate's output message, comes out heading ``d``
  one generation later;
* crossings (``X``): values pass straight through, both directions at once;
* eaters (``E``): absorb values;
* gates AND, OR, XOR, NAND, NOR (``G``): they count the values in the four abutting cells (a
  stream passing by, or heading into the gate, which absorbs it); when at least one is
  there the gate fires next generation, sending its result to the four cells three away;
  where a mirror stands there, the output leaves in the mirror's direction (the thesis's
  "enabling cell"); gates with several inputs count them (XOR = odd parity, so a 3-input
  XOR gives a full adder's sum).

Message area: bits 0-2 adjacent moving values, 3-5 adjacent moving ones, 6-7 gate output
(present, value), 8-15 arrivals (present, value per direction E, S, W, N), 16-18 adjacent
static values, 19-21 adjacent static ones, 22 and up the fixed element's code (each element
sends its code to itself).
"""

from __future__ import annotations

from itertools import product

DIRS = ("E", "S", "W", "N")
STEP = {"E": (1, 0), "S": (0, 1), "W": (-1, 0), "N": (0, -1)}
GATES = ("AND", "OR", "XOR", "NAND", "NOR")
STATIC_SHIFT = 16  # adjacent static values (3 bits), then adjacent static ones (3 bits)
CODE_SHIFT = 22
SPAWN, SPAWN_ONE = 64, 128
ANY_STATIC = "??????"


def _arrival_bits(d: str, v: int) -> int:
    k = DIRS.index(d)
    return (1 << (8 + 2 * k)) | (v << (9 + 2 * k))


def _gate_fn(kind: str, n: int, k: int) -> int:
    return {"AND": k == n, "OR": k > 0, "XOR": k % 2 == 1, "NAND": k != n,
            "NOR": k == 0}[kind]


class Forms:
    """Life-form numbers of every element state."""

    def __init__(self) -> None:
        self.numbers: dict[tuple, int] = {}
        for v in (0, 1):
            for d in DIRS:
                self._add(("P", v, d))
        for d in DIRS:
            self._add(("M", d))
            for v in (0, 1):
                self._add(("MH", d, v))
        self._add(("E",))
        for v in (0, 1):
            self._add(("S", v))
        for h, vv in product(self._holds("EW"), self._holds("SN")):
            self._add(("X", h, vv))
        for g in GATES:
            self._add(("G", g))
            for v in (0, 1):
                self._add(("GF", g, v))
        self.codes = {("M", d): 1 + i for i, d in enumerate(DIRS)}
        self.codes[("E",)] = 5
        self.codes[("X",)] = 6
        for i, g in enumerate(GATES):
            self.codes[("G", g)] = 7 + i
        for v in (0, 1):
            self.codes[("S", v)] = 12 + v

    @staticmethod
    def _holds(axis: str) -> list[tuple[int, str] | None]:
        return [None] + [(v, d) for d in axis for v in (0, 1)]

    def _add(self, key: tuple) -> None:
        self.numbers[key] = len(self.numbers) + 1

    def __getitem__(self, key: tuple) -> int:
        return self.numbers[key]


FORMS = Forms()


def _grid(entries: dict[tuple[int, int], str], reach: int = 1) -> list[str]:
    rows = []
    for dy in range(-reach, reach + 1):
        rows.append(" ".join(entries.get((dx, dy), ".") for dx in range(-reach, reach + 1)))
    return rows


def _particle_entries(held: list[tuple[int, str]], code: int | None) -> dict:
    """Message entries (additions) of the values in a cell, plus its element code."""
    sums: dict[tuple[int, int], int] = {}
    for v, d in held:
        for dd in DIRS:
            o = STEP[dd]
            sums[o] = sums.get(o, 0) + 1 + 8 * v + (_arrival_bits(d, v) if dd == d else 0)
    out = {o: f"+{s}" for o, s in sums.items()}
    if code is not None:
        out[(0, 0)] = f"|#X{code << CODE_SHIFT:X}"
    return out


COLOURS = {"P0": "60 60 FF", "P1": "FF FF 40", "M": "A0 A0 A0", "E": "80 40 40",
           "X": "C0 60 C0", "G": "40 C0 40", "S0": "20 30 90", "S1": "FF 90 00"}


def _static_entries(v: int, code: int) -> dict:
    """A static value: its level to the four neighbours, its code to itself."""
    out = {STEP[d]: f"+{(1 + 8 * v) << STATIC_SHIFT}" for d in DIRS}
    out[(0, 0)] = f"|#X{code << CODE_SHIFT:X}"
    return out


def rules_text() -> str:
    f = FORMS
    out = ["// Stylised electronic circuits (thesis section 7.4.3). RECONSTRUCTED: generated",
           "// by apps/ca/circuits.py; see docs/ca.md for the elements and their messages.", ""]
    for key, n in f.numbers.items():
        kind = key[0]
        if kind == "P":
            _, v, d = key
            ent = _particle_entries([(v, d)], None)
            colour = COLOURS[f"P{v}"]
        elif kind in ("M", "MH"):
            d = key[1]
            ent = _particle_entries([(key[2], d)] if kind == "MH" else [], f.codes[("M", d)])
            colour = COLOURS["P1" if kind == "MH" and key[2] else "M"]
        elif kind == "E":
            ent = {(0, 0): f"|#X{f.codes[('E',)] << CODE_SHIFT:X}"}
            colour = COLOURS["E"]
        elif kind == "S":
            ent = _static_entries(key[1], f.codes[key])
            colour = COLOURS[f"S{key[1]}"]
        elif kind == "X":
            held = [h for h in key[1:] if h is not None]
            ent = _particle_entries(held, f.codes[("X",)])
            colour = COLOURS["X"]
        else:
            g = key[1]
            ent = {(0, 0): f"|#X{f.codes[('G', g)] << CODE_SHIFT:X}"}
            if kind == "GF":
                spawn = SPAWN | (SPAWN_ONE if key[2] else 0)
                for o in ((3, 0), (-3, 0), (0, 3), (0, -3)):
                    ent[o] = f"|{spawn}"
            colour = COLOURS["G"]
        reach = 3 if kind == "GF" else 1
        out.append(f"{n} -{reach} {reach} -{reach} {reach} COLOUR {colour}  // {key}")
        out += _grid(ent, reach)
        out.append("")
    out.append("$")
    out += _interpretations()
    return "\n".join(out) + "\n"


def _pattern(code: int, arrivals: str, spawn: str, counts: str,
             static: str = ANY_STATIC) -> str:
    """#B pattern: code (bits 22+), static counts (6 bits), arrivals (8 bits, N..E high to
    low), spawn, moving counts."""
    head = bin(code)[2:] if code else ""
    return "#B" + head + static + arrivals + spawn + counts


def _arrival_field(which: dict[str, int | None]) -> str:
    """8-bit string, direction N (high) .. E (low); None = absent, 0/1 = value."""
    s = ""
    for d in reversed(DIRS):
        v = which.get(d)
        s += "00" if v is None else f"{v}1"
    return s


def _interpretations() -> list[str]:
    f = FORMS
    lines: list[str] = ["// empty cells: exactly one arriving value continues"]
    for d in DIRS:
        for v in (0, 1):
            lines.append(f"{_pattern(0, _arrival_field({d: v}), '??', '??????')} "
                         f"{f[('P', v, d)]}")
    for d in DIRS:
        code = f.codes[("M", d)]
        lines.append(f"// mirror {d}: one arrival or a gate's output comes out heading {d}")
        for a in DIRS:
            for v in (0, 1):
                lines.append(f"{_pattern(code, _arrival_field({a: v}), '??', '??????')} "
                             f"{f[('MH', d, v)]}")
        for v in (0, 1):
            lines.append(f"{_pattern(code, '00000000', f'{v}1', '??????')} {f[('MH', d, v)]}")
        lines.append(f"{_pattern(code, '????????', '??', '??????')} {f[('M', d)]}")
    lines.append("// eater")
    lines.append(f"{_pattern(f.codes[('E',)], '????????', '??', '??????')} {f[('E',)]}")
    lines += _static_lines()
    lines.append("// crossing: each axis holds the value arriving along it")
    code = f.codes[("X",)]
    for combo in product((None, 0, 1), repeat=4):
        which = dict(zip(DIRS, combo))
        horiz = [(v, d) for d, v in which.items() if d in "EW" and v is not None]
        vert = [(v, d) for d, v in which.items() if d in "SN" and v is not None]
        h = horiz[0] if len(horiz) == 1 else None  # head-on values annihilate
        vv = vert[0] if len(vert) == 1 else None
        lines.append(f"{_pattern(code, _arrival_field(which), '??', '??????')} "
                     f"{f[('X', h, vv)]}")
    for g in GATES:
        lines += _gate_lines(g)
    return lines


def _static_lines() -> list[str]:
    """A static value holds its level; one moving value arriving sets it (and is absorbed)."""
    f = FORMS
    lines = ["// static values: one arriving value sets the level, otherwise it is held"]
    for held in (0, 1):
        code = f.codes[("S", held)]
        for d in DIRS:
            for v in (0, 1):
                lines.append(f"{_pattern(code, _arrival_field({d: v}), '??', '??????')} "
                             f"{f[('S', v)]}")
        lines.append(f"{_pattern(code, '????????', '??', '??????')} {f[('S', held)]}")
    return lines


def _gate_lines(g: str) -> list[str]:
    """Fires when a moving value is beside it; static values beside it count as inputs."""
    f = FORMS
    code = f.codes[("G", g)]
    lines = [f"// gate {g}: n moving inputs (k of them 1) and ns static (ks of them 1)"]
    for n in range(1, 5):
        for k in range(0, n + 1):
            for ns in range(0, 5 - n):
                for ks in range(0, ns + 1):
                    v = int(_gate_fn(g, n + ns, k + ks))
                    pat = _pattern(code, "????????", "??", f"{k:03b}{n:03b}",
                                   f"{ks:03b}{ns:03b}")
                    lines.append(f"{pat} {f[('GF', g, v)]}")
    lines.append(f"{_pattern(code, '????????', '??', '??????')} {f[('G', g)]}")
    return lines


# -- the 4-bit ripple-carry adder -----------------------------------------------------------
# Each bit is a band of rows (a full adder from two half adders and an OR), shifted BAND_DX
# columns east and BAND_DY rows down from the one before; the carry leaves a band heading
# south through crossings over the next band's input streams and the previous sum stream.
# Streams move east; a value at column x at generation t has "phase" x - t.  Phase rules
# (checked by the tests): a gate's side inputs must share a phase p; its output leaves an
# east-side mirror at phase p + 1 and a north- or south-side mirror at p - 2; shifting a
# stream k rows with two mirrors costs k.

BAND_DX, BAND_DY = 40, 12
PERIOD = 8  # columns between successive values in a stream


def _band(cells: list, bx: int, by: int, last: bool) -> None:
    f = FORMS

    def put(x: int, y: int, key: tuple) -> None:
        cells.append((bx + x, by + y, f[key]))

    put(0, 0, ("G", "XOR"))  # p = a xor b ...
    put(0, 3, ("M", "E"))  # ... leaves south, into row 3
    put(6, 0, ("G", "AND"))  # g = a and b ...
    put(9, 0, ("M", "E"))  # ... leaves east along row 0
    put(12, -1, ("E",))
    put(12, 1, ("E",))
    put(12, 4, ("G", "XOR"))  # s = p xor c ...
    put(12, 7, ("M", "E"))  # ... leaves south, row 7: the sum output
    put(18, 4, ("G", "AND"))  # h = p and c ...
    put(21, 4, ("M", "E"))  # ... east along row 4
    put(24, 3, ("E",))
    put(24, 5, ("E",))
    put(14, 0, ("M", "S"))  # g turns down two rows to row 2
    put(14, 2, ("M", "E"))
    put(28, 3, ("G", "OR"))  # carry out = g or h ...
    put(28, 6, ("M", "E"))  # ... leaves south, row 6
    put(31, 2, ("E",))
    put(31, 4, ("E",))
    if not last:
        put(33, 6, ("M", "S"))  # the carry heads south to the next band
        put(33, 7, ("X", None, None))  # over this band's sum stream
        put(33, BAND_DY - 1, ("X", None, None))  # over the next band's a and b
        put(33, BAND_DY + 1, ("X", None, None))
        put(33, BAND_DY + 5, ("M", "E"))  # and east into the next band's carry row


def adder_layout(pairs: list[tuple[int, int]], carry_in: int = 0
                 ) -> tuple[list, dict[str, tuple[int, int]]]:
    """Cells of the adder with input streams for ``pairs``; and the output probe points.

    The carry into bit 0 is a static value held beside bit 0's two carry gates (the moving
    p stream makes them fire; the static level is their second input), so the adder shows
    both kinds of logic value: ``carry_in`` = 1 adds one to every sum."""
    f = FORMS
    cells: list = [(12, 5, f[("S", carry_in)]), (18, 5, f[("S", carry_in)])]
    phase0 = -10
    for i in range(4):
        _band(cells, i * BAND_DX, i * BAND_DY, last=i == 3)
        phase = phase0 - i * BAND_DY
        for j, (a, b) in enumerate(pairs):
            x = phase - j * PERIOD
            cells.append((x, i * BAND_DY - 1, f[("P", (a >> i) & 1, "E")]))
            cells.append((x, i * BAND_DY + 1, f[("P", (b >> i) & 1, "E")]))
    end = 3 * BAND_DX + 60
    probes: dict[str, tuple[int, int]] = {}
    for i in range(4):
        cells.append((end, i * BAND_DY + 7, f[("E",)]))
        probes[f"s{i}"] = (end - 1, i * BAND_DY + 7)
    cells.append((end, 3 * BAND_DY + 6, f[("E",)]))
    probes["c4"] = (end - 1, 3 * BAND_DY + 6)
    return cells, probes


DEMO_PAIRS = [(3, 5), (15, 1), (9, 9), (7, 8), (0, 0), (15, 15), (6, 11), (12, 3)]


def adder_pattern(pairs: list[tuple[int, int]] = DEMO_PAIRS):
    from camlab88.apps.ca.patterns import Pattern

    cells, _ = adder_layout(pairs)
    return Pattern.from_cells(cells, ref=(0, 0), name="4-bit adder",
                              rule="circuits",
                              comments=["sums " + " ".join(f"{a}+{b}" for a, b in pairs)])


def run_adder(engine_factory, pairs: list[tuple[int, int]], generations: int | None = None,
              carry_in: int = 0):
    """Run the adder; return the 5-bit results read from the output streams, in order."""
    cells, probes = adder_layout(pairs, carry_in)
    e = engine_factory()
    e.set_cells([c[0] + 1000 for c in cells], [c[1] + 1000 for c in cells],
                [c[2] for c in cells])
    inv = {n: k for k, n in FORMS.numbers.items()}
    seen: dict[str, list[int]] = {k: [] for k in probes}
    total = generations or (3 * BAND_DX + 100 + len(pairs) * PERIOD + 4 * BAND_DY)
    for _ in range(total):
        e.step()
        for name, (x, y) in probes.items():
            t = e.get(x + 1000, y + 1000)
            if t and inv[t][0] == "P":
                seen[name].append(inv[t][1])
    return seen


def library_files() -> dict[str, str]:
    from camlab88.apps.ca.patterns import format_native

    return {"circuits.rules": rules_text(), "adder_demo.pat": format_native(adder_pattern())}
