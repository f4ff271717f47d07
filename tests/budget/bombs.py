"""Inputs that ask for more than their size: the bomb trial's rows (issue "every input has a
budget"), each made at any scale so a test can trip the same check small and the slow test
at the trial's size."""

from __future__ import annotations

from pathlib import Path


def dense_mc(path: Path, level: int) -> Path:
    """A macrocell of a full 2**level square in level - 2 lines (8192² at level 13)."""
    lines = ["[M2] (bomb)", "#R B3/S23", "$".join(["********"] * 8) + "$"]
    for lv in range(4, level + 1):
        k = len(lines) - 2
        lines.append(f"{lv} {k} {k} {k} {k}")
    path.write_text("\n".join(lines) + "\n")
    return path


def many_node_mc(path: Path, nodes: int) -> Path:
    """One leaf and ``nodes`` level-4 node lines over it (the trial: 10^7, 100 MB)."""
    with open(path, "w") as fh:
        fh.write("[M2] (bomb)\n#R B3/S23\n**$\n")
        fh.write("4 1 1 1 1\n" * nodes)
    return path


def many_leaf_mc(path: Path, leaves: int) -> Path:
    """``leaves`` distinct 8 x 8 leaves of two rows each (the trial: 3x10^6, 57 MB) and the
    nodes that place them side by side."""
    with open(path, "w") as fh:
        fh.write("[M2] (bomb)\n#R B3/S23\n")
        for k in range(leaves):
            a, b = k & 0xFF, (k >> 8) & 0xFF
            row = lambda v: "".join("*" if v >> i & 1 else "." for i in range(8)) or "."  # noqa: E731
            fh.write(f"{row(a | 1)}${row(b | 1)}$\n")
        ids, level, nxt = list(range(1, leaves + 1)), 4, leaves + 1
        while len(ids) > 1:
            parents = []
            for i in range(0, len(ids), 4):
                quad = (ids[i:i + 4] + [0, 0, 0])[:4]
                fh.write(f"{level} {quad[0]} {quad[1]} {quad[2]} {quad[3]}\n")
                parents.append(nxt)
                nxt += 1
            ids, level = parents, level + 1
    return path


def dense_rle(path: Path, side: int) -> Path:
    """An RLE of a full side x side square in a few bytes a row (the trial: 30000²)."""
    with open(path, "w") as fh:
        fh.write(f"x = {side}, y = {side}, rule = B3/S23\n")
        row = f"{side}o$\n"
        fh.write(row * (side - 1) + f"{side}o!\n")
    return path


def _dense_square(path: Path, header: str, cell: str, side: int) -> Path:
    """A text pattern of a full side x side square: ``header``, then ``side`` rows of
    ``side`` ``cell`` characters."""
    with open(path, "w") as fh:
        fh.write(header)
        row = cell * side + "\n"
        for _ in range(side):
            fh.write(row)
    return path


def dense_cells(path: Path, side: int) -> Path:
    """A plaintext .cells of a full side x side square (the trial: 8000², 64 MB)."""
    return _dense_square(path, "!Name: bomb\n", "O", side)


def many_point_kas(path: Path, points: int) -> Path:
    """A KAS keyframe of one chain of ``points`` points (the trial: 10^7, 100 MB)."""
    with open(path, "w") as fh:
        fh.write(f"KAS keyframe 1\nchains 1\nchain section=0 points={points}\n")
        block = "".join(f"{i % 500} {i % 300} 1\n" for i in range(1000))
        for _ in range(points // 1000):
            fh.write(block)
        fh.write("".join(f"{i % 500} {i % 300} 1\n" for i in range(points % 1000)))
        fh.write("end\n")
    return path


_HEADER = ('{"type": "header", "format": "camlab88-session", "version": 1, "argv": ["sigma", '
           '"run", "--in", "x.sig", "--seconds", "1"], "headless": true, "hash_every": 10}\n')
_END = ('{"type": "end", "frames": 0, "ticks": 1, "time": "0", "sha256": "' + "0" * 64 + '"}\n')


def _empty_input() -> str:
    """The file record of the recorded command's input, x.sig (empty)."""
    import base64
    import hashlib
    import zlib

    data = base64.b64encode(zlib.compress(b"")).decode()
    return (f'{{"type": "file", "name": "x.sig", "sha256": "{hashlib.sha256(b"").hexdigest()}", '
            f'"data": "{data}"}}\n')


def many_record_session(path: Path, records: int, direction: str = ">") -> Path:
    """A session recording of ``records`` wire records (the trial: 4x10^6 of the program's
    traffic, ``>``, 228 MB; ``+``: outside input, which a replay keeps)."""
    line = f'{{"type": "wire", "tick": 0, "dir": "{direction}", "data": "eJwzBAAAMgAy"}}\n'
    with open(path, "w") as fh:
        fh.write(_HEADER)
        fh.write(_empty_input())
        for _ in range(records // 10000):
            fh.write(line * 10000)
        fh.write(line * (records % 10000))
        fh.write(_END)
    return path


def long_line_session(path: Path, size: int) -> Path:
    """A session recording one of whose lines is ``size`` bytes long (the trial: 200 MB)."""
    with open(path, "w") as fh:
        fh.write(_HEADER)
        fh.write('{"type": "file", "name": "x.sig", "sha256": "' + "0" * 64 + '", "data": "')
        chunk = "A" * (1 << 20)
        for _ in range(size >> 20):
            fh.write(chunk)
        fh.write('"}\n')
        fh.write(_END)
    return path


def heavy_actors(path: Path, lathes: int, points: int) -> Path:
    """Life's actor (state 1) of ``lathes`` lathes of ``points`` points each (the trial: 63
    lathes of 511 points, inside the 64-part / 512-point limits; 483 KB)."""
    profile = "  ".join(f"0.3 {k / points:.6f}" for k in range(points))
    with open(path, "w") as fh:
        fh.write("rules life\n\nactor 1 heavy\n  colour 200 200 200\n")
        for _ in range(lathes):
            fh.write(f"  lathe {profile}\n")
        fh.write("end\n")
    return path


def many_lights(path: Path, count: int) -> Path:
    """A renderer lights file of ``count`` lights (the trial: 200,000, 5 MB)."""
    with open(path, "w") as fh:
        for k in range(count):
            fh.write(f"{k % 7 - 3} {k % 5 - 2} 2.5 0.001\n")
    return path


def dense_lif(path: Path, side: int) -> Path:
    """A Life 1.05 file of a full side x side square, one ``*`` a cell (8000²: 64 MB)."""
    return _dense_square(path, "#Life 1.05\n#D bomb\n#N\n#P 0 0\n", "*", side)


def many_cell_life106(path: Path, cells: int) -> Path:
    """A Life 1.06 file of ``cells`` cells, one ``x y`` line each (4x10^6: 45 MB)."""
    side = max(int(cells ** 0.5), 1)
    with open(path, "w") as fh:
        fh.write("#Life 1.06\n")
        for y in range(-(-cells // side)):
            fh.write("".join(f"{x} {y}\n" for x in range(min(side, cells - y * side))))
    return path


def many_frame_rainbow(path: Path, frames: int) -> Path:
    """A Rainbow recording of ``frames`` one-byte command frames (2x10^7: 100 MB)."""
    with open(path, "w") as fh:
        fh.write("# camlab88 rainbow recording v1\n")
        for done in range(0, frames, 100000):
            fh.write("> 00\n" * min(100000, frames - done))
    return path


def with_idle_events(src: Path, dst: Path, per_tick: int) -> Path:
    """The recording ``src`` with ``per_tick`` key releases (of a key never pressed: no
    program answers them, so the screen hashes still agree) at every tick of the run, in
    tick order: a recording as long as many hours of typing, that ``replay --check``
    passes. The run's time must be linear in its ticks (sigma run's: 1/100 s a tick)."""
    import json
    from fractions import Fraction

    lines = src.read_text().splitlines()
    end = json.loads(lines[-1])
    step = Fraction(end["time"]) / end["ticks"]
    head = [ln for ln in lines[:-1] if json.loads(ln)["type"] in ("header", "file")]
    body = [(json.loads(ln)["tick"], 1, ln) for ln in lines[:-1]
            if json.loads(ln)["type"] not in ("header", "file")]
    event = '{{"type":"event","tick":{t},"time":"{v}","event":{{"kind":"KeyUp","key":"f15"}}}}'
    body += [(t, 0, event.format(t=t, v=t * step)) for t in range(end["ticks"])
             for _ in range(per_tick)]
    body.sort(key=lambda r: (r[0], r[1]))
    dst.write_text("\n".join(head + [ln for _t, _k, ln in body] + [lines[-1]]) + "\n")
    return dst


def one_tick_of_events(path: Path, events: int) -> Path:
    """A recording whose ``events`` key releases all fall on tick 0: a window of one tick
    as long as the file (nothing a recorder writes; a crafted file)."""
    line = '{"type": "event", "tick": 0, "time": "0", "event": {"kind": "KeyUp", "key": "f15"}}\n'
    with open(path, "w") as fh:
        fh.write(_HEADER)
        fh.write(_empty_input())
        for done in range(0, events, 10000):
            fh.write(line * min(10000, events - done))
        fh.write(_END)
    return path


def with_empty_reads(src: Path, dst: Path, per_poll: int) -> Path:
    """The recording ``src`` with ``per_poll`` empty reads (``raw`` entries of no bytes: the
    decoder is fed nothing, so the screen hashes still agree) at every poll its tablet tape
    has entries for: a tape as long as a tablet streaming ``per_poll`` times faster, that
    ``replay --check`` passes."""
    import base64
    import json
    import zlib

    out = []
    for line in src.read_text().splitlines():
        obj = json.loads(line)
        if obj["type"] == "wire" and obj["dir"] == "T":
            entries = json.loads(zlib.decompress(base64.b64decode(obj["data"])))
            for poll in sorted({e[0] for e in entries}):
                entries += [[poll, "raw", ""]] * per_poll
            entries.sort(key=lambda e: e[0])  # stable: the recorded ones first at a poll
            data = json.dumps(entries, separators=(",", ":")).encode()
            obj["data"] = base64.b64encode(zlib.compress(data, 9)).decode("ascii")
            line = json.dumps(obj, separators=(",", ":"))
        out.append(line)
    dst.write_text("\n".join(out) + "\n")
    return dst
