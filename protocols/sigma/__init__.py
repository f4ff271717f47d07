"""The Sigma T5684/T5688 command set, described once (orders.ORDERS) and used both ways."""

from protocols.sigma import commands
from protocols.sigma.commands import *  # noqa: F403  (the typed commands: commands.__all__)
from protocols.sigma.cursor import CursorReport, format_report, parse_report
from protocols.sigma.decoder import Decoder
from protocols.sigma.encoder import Encoder
from protocols.sigma.orders import ORDERS, OrderSpec

__all__ = [*commands.__all__, "ORDERS", "CursorReport", "Decoder", "Encoder", "OrderSpec",
           "format_report", "parse_report"]
