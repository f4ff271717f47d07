"""The period film: every frame computed on the host and sent to one T5688 over the
9600-baud line as Sigma orders (apps.actors.sigma_host), frame after frame, as in 1987.
The device is whatever ``send`` talks to (the command wires an emulated T5688's host port):
``send(orders) -> (the screen's RGB picture, the line time the orders took)``."""

from __future__ import annotations

from collections.abc import Callable, Iterator
from dataclasses import dataclass

import numpy as np

from camlab88.apps.actors.render import Look, render_linear
from camlab88.apps.actors.sigma_host import SCREEN_H, SCREEN_W, ActorsSigmaHost, fixed_palette
from camlab88.apps.cafilm.film import CaFilm, stage_at

Send = Callable[[bytes], tuple[np.ndarray, float]]


@dataclass(frozen=True)
class PeriodFrame:
    frame: int
    image: np.ndarray  # what the terminal shows, (512, 768, 3) uint8
    orders: int  # bytes sent for this frame
    line_seconds: float
    intended: np.ndarray  # the LUT indices the host meant


def host_for(film: CaFilm) -> ActorsSigmaHost:
    lights = film.lights
    top = float(lights.ambient.mean() + lights.colours.sum(axis=0).mean())
    actor_colours = [film.actors.actors[s].colour for s in sorted(film.actors.actors)]
    return ActorsSigmaHost(fixed_palette(actor_colours, sorted(film.tile_colours.values()),
                                         top))


def period_frames(film: CaFilm, send: Send) -> Iterator[PeriodFrame]:
    host = host_for(film)
    send(host.setup())
    look = Look(SCREEN_W, SCREEN_H, film.look.ss, film.look.shadows, film.look.shadow_map)
    for n in range(1, film.n_frames + 1):
        stage, shot = stage_at(film, n)
        sent = host.frame(render_linear(stage, shot, look))
        screen, seconds = send(sent.data)
        yield PeriodFrame(n, screen, len(sent.data), seconds, sent.intended)
