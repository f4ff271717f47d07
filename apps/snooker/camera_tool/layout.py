"""Where the camera tool's parts sit on the 768 x 576 screen: the live view (4:3, as the
visualiser's full screen) top left, the script down the right, the frame's values and the
time line under the view."""

from __future__ import annotations

VIEW = (0, 0, 432, 324)
SCRIPT = (432, 0, 336, 576)  # 55 columns: the thesis's longest script line is 49
INFO = (0, 324, 432, 204)
TIMELINE = (0, 528, 432, 48)
CHAR_W, CHAR_H = 6, 10  # the Rainbow's text cells
SCRIPT_COLS = SCRIPT[2] // CHAR_W - 1
SCRIPT_ROWS = SCRIPT[3] // CHAR_H - 1  # the last row is the file's status
INFO_COLS = INFO[2] // CHAR_W
TIMELINE_X0, TIMELINE_X1 = 10, 422  # frame 1 .. the last frame


def timeline_x(frame: int, n_frames: int) -> int:
    if n_frames <= 1:
        return TIMELINE_X0
    return TIMELINE_X0 + (frame - 1) * (TIMELINE_X1 - TIMELINE_X0) // (n_frames - 1)


def timeline_frame(x: int, n_frames: int) -> int:
    span = TIMELINE_X1 - TIMELINE_X0
    f = 1 + round((x - TIMELINE_X0) * max(n_frames - 1, 0) / span)
    return max(1, min(n_frames, f))
