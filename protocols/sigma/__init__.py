"""The Sigma T5684/T5688 command set, described once (orders.ORDERS) and used both ways."""

from protocols.sigma.commands import (
    AgsEnd,
    AgsEscape,
    AgsPoints,
    AlphaText,
    Command,
    DecoderStats,
    Dots,
    DotsEnd,
    GraphicsFlag,
    GraphicsText,
    Order,
    Point,
    Points,
)
from protocols.sigma.cursor import CursorReport, format_report, parse_report
from protocols.sigma.decoder import Decoder
from protocols.sigma.encoder import Encoder
from protocols.sigma.orders import ORDERS, OrderSpec

__all__ = [
    "ORDERS", "AgsEnd", "AgsEscape", "AgsPoints", "AlphaText", "Command", "CursorReport",
    "DecoderStats", "Decoder", "Dots", "DotsEnd", "Encoder", "GraphicsFlag", "GraphicsText",
    "Order", "OrderSpec", "Point", "Points", "format_report", "parse_report",
]
