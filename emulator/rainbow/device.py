"""The Rainbow workstation as one object: graph + memory + compiler + video processor + inputs.

This is the device side of the pad library: ``camlab88.protocols.rainbow`` clients reach it through
the command stream (emulator/rainbow/executor.py), never directly.
"""

from __future__ import annotations

import numpy as np

from camlab88.emulator.rainbow.bands import BandStructure
from camlab88.emulator.rainbow.compiler import Compiler
from camlab88.emulator.rainbow.draw import Canvas
from camlab88.emulator.rainbow.errors import RainbowError
from camlab88.emulator.rainbow.graph import MAX_COORD, SCREEN, Cluster, Pad, PadGraph
from camlab88.emulator.rainbow.inputs import InputController
from camlab88.emulator.rainbow.memory import VideoMemory
from camlab88.emulator.rainbow.reference import reference_frame
from camlab88.emulator.rainbow.video import LUT_SIZE, render
from camlab88.protocols.rainbow.events import Event

FRAME_MS = 20  # 50 Hz
PAGES = LUT_SIZE // 256


class Rainbow:
    def __init__(self, memory: VideoMemory | None = None, strict: bool = False) -> None:
        self.memory = memory or (VideoMemory.strict() if strict else VideoMemory())
        self.graph = PadGraph()
        self.compiler = Compiler()
        self.inputs = InputController()
        self.lut = np.zeros((LUT_SIZE, 3), np.uint8)  # what the video processor uses
        self.lut_pending = self.lut.copy()  # what programs write; latched each frame
        self.frame_count = 0
        self.time_ms = 0
        self._compiled_version = -1

    def new_session(self) -> None:
        """Power-on state again for the next program (pads, clusters, arcs, colour tables,
        pending input, the frame counter), with video memory of the same size."""
        Rainbow.__init__(self, VideoMemory(self.memory.width, self.memory.height))

    # -- state -----------------------------------------------------------------------------
    def save_state(self) -> tuple[dict, dict[str, bytes]]:
        """(JSON values, raw arrays): each part gives its own (graph, memory, inputs), then
        the LUTs and the clock. The band structure is recompiled on load (a compile from
        scratch equals the incremental one)."""
        head = {"memory": [self.memory.width, self.memory.height],
                "graph": self.graph.save_state(), "inputs": self.inputs.save_state(),
                "clock": [self.frame_count, self.time_ms]}
        blobs = dict(self.memory.save_state(), lut=self.lut.tobytes(),
                     lut_pending=self.lut_pending.tobytes())
        return head, blobs

    def load_state(self, head: dict, blobs: dict[str, bytes]) -> None:
        """Put back save_state()'s parts (ValueError/KeyError/TypeError if damaged)."""
        if head["memory"] != [self.memory.width, self.memory.height]:
            raise ValueError(f"state has {head['memory']} video memory, this device "
                             f"{[self.memory.width, self.memory.height]}")
        for name in ("lut", "lut_pending"):
            if len(blobs[name]) != self.lut.nbytes:
                raise ValueError(f"state {name!r} is {len(blobs[name])} bytes")
        frames, ms = (int(v) for v in head["clock"])
        scratch = PadGraph()  # check the graph and the queue before changing anything
        scratch.load_state(head["graph"])
        InputController().load_state(head["inputs"])
        self.memory.load_state(blobs)
        self.graph = scratch
        self.inputs.load_state(head["inputs"])
        self.lut[...] = np.frombuffer(blobs["lut"], np.uint8).reshape(self.lut.shape)
        self.lut_pending[...] = np.frombuffer(blobs["lut_pending"], np.uint8).reshape(
            self.lut.shape)
        self.frame_count, self.time_ms = frames, ms
        self.compiler = Compiler()
        self._compiled_version = -1

    # -- nodes and arcs --------------------------------------------------------------------
    def create_pad(self, width: int, height: int, depth: int, plane: int = 0,
                   lut_page: int = 0, node: int | None = None) -> int:
        # Sizes are bounded by the coordinate range only: a virtual (depth 0) pad needs no
        # memory, and a pad too big for memory is refused by the allocator as out of memory.
        for name, v, lo, hi in (("width", width, 1, MAX_COORD),
                                ("height", height, 1, MAX_COORD),
                                ("depth", depth, 0, 8), ("plane", plane, 0, 7),
                                ("lut_page", lut_page, 0, PAGES - 1)):
            if not isinstance(v, int) or isinstance(v, bool) or not lo <= v <= hi:
                raise RainbowError(f"pad {name} {v!r} must be an integer {lo}..{hi}")
        if plane + depth > 8:
            raise RainbowError(f"pad planes {plane}..{plane + depth - 1} go past plane 7")
        if node is not None and node in self.graph.nodes:
            raise RainbowError(f"node {node} already exists")
        alloc = self.memory.allocate(width, height, plane, depth) if depth else None
        try:
            return self.graph.add_pad(width, height, depth, plane, lut_page, alloc, node).id
        except RainbowError:
            if alloc:
                self.memory.free(alloc)
            raise

    def create_cluster(self, width: int, height: int, node: int | None = None) -> int:
        return self.graph.add_cluster(width, height, node).id

    def destroy(self, node: int) -> None:
        n = self.graph.remove_node(node)
        if isinstance(n, Pad) and n.alloc is not None:
            self.memory.free(n.alloc)

    def map(self, parent: int, child: int, x: int = 0, y: int = 0, priority: int = 0,
            on: bool = True, arc: int | None = None) -> int:
        return self.graph.add_arc(parent, child, x, y, priority, on, arc).id

    def unmap(self, arc: int) -> None:
        self.graph.remove_arc(arc)

    def move(self, arc: int, x: int, y: int) -> None:
        self.graph.move(arc, x, y)

    def set_priority(self, arc: int, priority: int) -> None:
        self.graph.set_priority(arc, priority)

    def set_on(self, arc: int, on: bool) -> None:
        self.graph.set_on(arc, on)

    def resize(self, cluster: int, width: int, height: int) -> None:
        self.graph.resize(cluster, width, height)

    def set_page(self, pad: int, lut_page: int) -> None:
        if not isinstance(lut_page, int) or not 0 <= lut_page < PAGES:
            raise RainbowError(f"lut_page {lut_page!r} must be 0..{PAGES - 1}")
        self.graph.pad(pad).lut_page = lut_page
        self.graph.version += 1

    # -- lookup table ----------------------------------------------------------------------
    def set_lut(self, start: int, colours: np.ndarray | list) -> None:
        """Write entries start.. (each (r, g, b)); seen from the next frame on."""
        c = np.asarray(colours, dtype=np.int64).reshape(-1, 3)
        if not isinstance(start, int) or start < 0 or start + len(c) > LUT_SIZE:
            raise RainbowError(f"LUT entries {start}..{start + len(c) - 1} outside 0..4095")
        if c.size and (c.min() < 0 or c.max() > 255):
            raise RainbowError("LUT colour components must be 0..255")
        self.lut_pending[start: start + len(c)] = c

    # -- drawing ---------------------------------------------------------------------------
    def canvas(self, pad: int) -> Canvas:
        return Canvas(self.memory.words, self.graph.pad(pad))

    def copy(self, src: int, sx: int, sy: int, w: int, h: int, dst: int, dx: int,
             dy: int) -> None:
        """Pad-to-pad copy of a block (clipped to both pads; values masked to dst's depth)."""
        s, d = self.canvas(src), self.canvas(dst)
        xa, ya = max(sx, 0, sx - dx), max(sy, 0, sy - dy)
        xb = min(sx + w, s.w, sx + d.w - dx)
        yb = min(sy + h, s.h, sy + d.h - dy)
        if xa >= xb or ya >= yb:
            return
        block = s.read(xa, ya, xb - xa, yb - ya) & d.vmax
        d.put(dx + xa - sx, dy + ya - sy, block)

    # -- inputs ----------------------------------------------------------------------------
    def post_event(self, event: Event) -> Event:
        return self.inputs.post(event, self.time_ms)

    def take_events(self, limit: int = 256) -> list[Event]:
        return self.inputs.take(limit)

    # -- video -----------------------------------------------------------------------------
    def bands(self) -> BandStructure:
        """The band structure for the graph as it is now (recompiled if anything changed)."""
        if self._compiled_version != self.graph.version:
            self.compiler.compile(self.graph)
            self._compiled_version = self.graph.version
        return self.compiler.structure

    def frame(self, out: np.ndarray | None = None) -> np.ndarray:
        """Compose one frame (latching LUT writes first) and advance the clock 20 ms."""
        self.lut[:] = self.lut_pending
        img = render(self.bands(), self.memory.words, self.lut, out)
        self.frame_count += 1
        self.time_ms += FRAME_MS
        return img

    def peek(self) -> np.ndarray:
        """The frame as the screen shows it now, without advancing time or latching the LUT."""
        return render(self.bands(), self.memory.words, self.lut)

    def reference(self) -> np.ndarray:
        """The same frame from the straightforward per-pixel compositor (latched LUT)."""
        return reference_frame(self.graph, self.memory.words, self.lut)

    @property
    def screen(self) -> int:
        return SCREEN

    def node_kind(self, node: int) -> str:
        n = self.graph.node(node)
        return "cluster" if isinstance(n, Cluster) else "pad"
