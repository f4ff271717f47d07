"""The Rainbow pad library (client side): API, command stream, transports, recording, UI."""

from camlab88.protocols.rainbow.client import (
    LUT_SIZE,
    SCREEN,
    SCREEN_H,
    SCREEN_W,
    RainbowClient,
    RainbowRefused,
    parse_colour,
)
from camlab88.protocols.rainbow.events import LEFT, MIDDLE, RIGHT, KeyEvent, MouseEvent, TabletEvent
from camlab88.protocols.rainbow.transport import LoopbackTransport, SocketTransport

__all__ = ["LEFT", "LUT_SIZE", "MIDDLE", "RIGHT", "SCREEN", "SCREEN_H", "SCREEN_W",
           "KeyEvent", "LoopbackTransport", "MouseEvent", "RainbowClient", "RainbowRefused",
           "SocketTransport", "TabletEvent", "parse_colour"]
