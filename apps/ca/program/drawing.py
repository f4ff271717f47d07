"""Everything the program shows, drawn through the pad library (protocols.rainbow only).

- The grid: two "super pads" (section 7.3: one large pad mapped four times into a cluster),
  one per buffer of the double buffer; each sits in its own 752 x 576 cluster and the two
  clusters' arcs are swapped to show a new generation whole. Panning moves the arcs of both
  and draws only the strips about to come into view (each from the state its buffer shows).
- The 16-pixel band at the right, with the current-colour marker in its top corner.
- The editing cursor and the rubber-band / advance-area rectangles: clusters holding four
  thin virtual pads, so the inside shows the grid beneath and moving them draws nothing.
- Message areas for prompts, typed text, statistics and errors.
"""

from __future__ import annotations

from camlab88.apps.ca.engine import Engine
from camlab88.apps.ca.program import colours, raster
from camlab88.apps.ca.program.viewport import BAND_W, VIEW_H, VIEW_W, Viewport
from camlab88.protocols.rainbow.client import SCREEN, RainbowClient
from camlab88.protocols.rainbow.ui import MessageArea, SuperPad
from camlab88.protocols.rainbow.ui.double_buffer import Flip

PAD_W, PAD_H = VIEW_W + BAND_W, VIEW_H + BAND_W  # the super pad: the view plus a margin
BAND_PAGE, CURSOR_PAGE, RUBBER_PAGE, AREA_PAGE = 5, 6, 7, 8
PROMPT_PAGE, STATS_PAGE = 9, 10
GRID_PRIORITY, BOX_PRIORITY, CURSOR_PRIORITY, MESSAGE_PRIORITY = 1, 20, 30, 40


class GridBuffer(SuperPad):
    """One buffer: a super pad whose strips are drawn from ``self.engine``."""

    def __init__(self, client: RainbowClient, cluster: int, view: Viewport) -> None:
        self.engine: Engine | None = None
        self.view = view
        self.stale = True  # must be redrawn whole before it is shown
        super().__init__(client, cluster, VIEW_W, VIEW_H, PAD_W, PAD_H, 8, self._strip,
                         lut_page=colours.PAGE_COLOUR, view_x=view.px, view_y=view.py)

    def _strip(self, wx: int, wy: int, w: int, h: int, pad_x: int, pad_y: int) -> None:
        if self.engine is None:
            self.client.rect(self.pad, pad_x, pad_y, w, h, raster.DEAD)
            return
        v = raster.values(self.engine, self.view.zoom, self.view.side, wx, wy, w, h)
        self.client.put_pixels(self.pad, pad_x, pad_y, v)

    def redraw(self) -> None:
        """Draw the whole view from scratch at the viewport's position."""
        self.vx, self.vy = self.view.px, self.view.py
        self._fill(self.vx, self.vy, self.view_w, self.view_h)
        self._place()
        self.stale = False

    def redraw_world(self, wx: int, wy: int, w: int, h: int) -> None:
        """Redraw the part of world rectangle [wx, wx+w) x [wy, wy+h) that is in view."""
        x0, y0 = max(wx, self.vx), max(wy, self.vy)
        x1, y1 = min(wx + w, self.vx + self.view_w), min(wy + h, self.vy + self.view_h)
        if x1 > x0 and y1 > y0:
            self._fill(x0, y0, x1 - x0, y1 - y0)


class Outline:
    """A rectangle outline: four virtual pads in a clipping cluster (nothing redrawn)."""

    def __init__(self, client: RainbowClient, lut_page: int, colour: str, priority: int,
                 thickness: int = 1) -> None:
        self.client = client
        client.set_lut(lut_page * 256, [colour])
        self.cluster = client.create_cluster(VIEW_W, VIEW_H)
        self.arc = client.map(SCREEN, self.cluster, 0, 0, priority, on=False)
        t = thickness
        self.t = t
        hpad = client.create_pad(2 * VIEW_W, t, 0, lut_page=lut_page)
        vpad = client.create_pad(t, 2 * VIEW_H, 0, lut_page=lut_page)
        self.top = client.map(self.cluster, hpad, 0, 0)
        self.bottom = client.map(self.cluster, hpad, 0, 0)
        self.left = client.map(self.cluster, vpad, 0, 0)
        self.right = client.map(self.cluster, vpad, 0, 0)
        self.shape: tuple[int, int, int, int] | None = None
        self.visible = False

    def show(self, x: int, y: int, w: int, h: int) -> None:
        """Outline of the screen rectangle (x, y, w, h); may reach beyond the view."""
        w, h = max(w, 1), max(h, 1)
        c = self.client
        if self.shape is None or self.shape[2:] != (w, h):
            c.resize(self.cluster, w, h)
            c.move(self.bottom, 0, h - self.t)
            c.move(self.right, w - self.t, 0)
        if self.shape is None or self.shape[:2] != (x, y):
            c.move(self.arc, x, y)
        self.shape = (x, y, w, h)
        if not self.visible:
            c.set_on(self.arc, True)
            self.visible = True

    def hide(self) -> None:
        if self.visible:
            self.client.set_on(self.arc, False)
            self.visible = False


class Display:
    def __init__(self, client: RainbowClient, view: Viewport) -> None:
        c = self.client = client
        self.view = view
        self.rules = None
        self.mode = "colour"  # or "mono"
        self.editing = False
        clusters = (c.create_cluster(VIEW_W, VIEW_H), c.create_cluster(VIEW_W, VIEW_H))
        # double buffering: the back one is drawn while the front one is shown
        self.buffers = Flip(c, (GridBuffer(c, clusters[0], view), GridBuffer(c, clusters[1], view)),
                            (c.map(SCREEN, clusters[0], 0, 0, GRID_PRIORITY, on=True),
                             c.map(SCREEN, clusters[1], 0, 0, GRID_PRIORITY, on=False)))
        c.set_lut(BAND_PAGE * 256, ["#303040"])
        band = c.create_pad(BAND_W, VIEW_H, 0, lut_page=BAND_PAGE)
        c.map(SCREEN, band, VIEW_W, 0, GRID_PRIORITY)
        self.marker = c.create_pad(BAND_W, BAND_W, 8, lut_page=colours.PAGE_EDIT)
        c.map(SCREEN, self.marker, VIEW_W, 0, GRID_PRIORITY + 1)
        self.cursor = Outline(c, CURSOR_PAGE, "#ffff00", CURSOR_PRIORITY)
        self.rubber = Outline(c, RUBBER_PAGE, "#ff40ff", BOX_PRIORITY)
        self.area = Outline(c, AREA_PAGE, "#00e0ff", BOX_PRIORITY, thickness=2)
        self.prompt = MessageArea(c, 8, VIEW_H - 44, VIEW_W - 16, 36, PROMPT_PAGE,
                                  priority=MESSAGE_PRIORITY)
        self.stats = MessageArea(c, 8, 8, 400, 8 + 11 * 13, STATS_PAGE,
                                 priority=MESSAGE_PRIORITY)
        self.set_marker(1)

    # -- buffers ----------------------------------------------------------------------------
    def draw_back(self, engine: Engine) -> None:
        self.buffers.back.engine = engine
        self.buffers.back.redraw()

    def redraw_front(self, engine: Engine) -> None:
        self.buffers.front.engine = engine
        self.buffers.front.redraw()
        self.buffers.back.stale = True

    def pan(self) -> None:
        """The viewport moved: move both buffers' arcs, drawing only newly exposed strips."""
        for buf in self.buffers.items:
            if buf.stale:  # it is redrawn whole before being shown: no strips needed
                buf.vx, buf.vy = self.view.px, self.view.py
            else:
                buf.pan_to(self.view.px, self.view.py)

    def cell_changed(self, cx: int, cy: int) -> None:
        """One cell of the shown state changed (an edit): redraw just that cell."""
        z = self.view.zoom or 1
        wx, wy = self.view.world_of_cell(cx, cy)
        self.buffers.front.redraw_world(wx, wy, z, z)
        self.buffers.back.stale = True

    # -- colours ----------------------------------------------------------------------------
    def set_rules(self, rules) -> None:
        self.rules = rules
        self.load_luts()

    def load_luts(self) -> None:
        grid = self.view.grid and self.view.zoom >= 8
        for kind, page in (("colour", colours.PAGE_COLOUR), ("mono", colours.PAGE_MONO),
                           ("edit", colours.PAGE_EDIT), ("density", colours.PAGE_DENSITY)):
            self.client.set_lut(page * 256, colours.page(kind, self.rules, grid))
        self.apply_page()

    def page(self) -> int:
        if self.view.zoom == 0:
            return colours.PAGE_DENSITY
        if self.editing:
            return colours.PAGE_EDIT
        return colours.PAGE_MONO if self.mode == "mono" else colours.PAGE_COLOUR

    def apply_page(self) -> None:
        p = self.page()
        for buf in self.buffers.items:
            self.client.set_page(buf.pad, p)
        self.client.set_page(self.marker, colours.PAGE_EDIT if self.view.zoom == 0 else p)

    def set_marker(self, form: int) -> None:
        """The current colour (life-form value) in the corner of the screen."""
        c = self.client
        c.clear(self.marker, raster.GAP)
        c.rect(self.marker, 1, 1, BAND_W - 2, BAND_W - 2, int(raster.form_value(max(form, 1))))

    # -- cursor and rectangles --------------------------------------------------------------
    def show_cursor(self, cx: int, cy: int) -> None:
        z = self.view.zoom or 1
        sx, sy = self.view.screen_of_cell(cx, cy)
        size = max(z, 3)
        self.cursor.show(sx - (size - z) // 2, sy - (size - z) // 2, size, size)

    def show_rectangle(self, outline: Outline, a: tuple[int, int], b: tuple[int, int]) -> None:
        """Outline the cells between corners a and b (inclusive)."""
        z = self.view.zoom or 1
        s = self.view.side
        ax, ay = self.view.screen_of_cell(*a)
        bx, by = self.view.screen_of_cell(*b)
        x0, x1 = min(ax, bx), max(ax, bx) + z
        y0, y1 = min(ay, by), max(ay, by) + z
        if s > 1:
            x1, y1 = max(x1, x0 + 1), max(y1, y0 + 1)
        x0, y0, x1, y1 = x0 - 1, y0 - 1, x1, y1
        if x1 < 0 or y1 < 0 or x0 >= VIEW_W or y0 >= VIEW_H:
            outline.hide()
            return
        # clip to just beyond the view: edges off the screen stay off it, and the
        # outline's cluster stays small whatever the rectangle's size
        m = 4
        x0, y0 = max(x0, -m), max(y0, -m)
        x1, y1 = min(x1, VIEW_W + m), min(y1, VIEW_H + m)
        outline.show(x0, y0, x1 - x0 + 1, y1 - y0 + 1)
