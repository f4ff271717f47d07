"""The Sigma T5684/T5688 command set, described once (orders.ORDERS) and used both ways."""

from camlab88.protocols.sigma import commands
from camlab88.protocols.sigma.commands import *  # noqa: F403  (the typed commands: commands.__all__)
from camlab88.protocols.sigma.cursor import CursorReport, format_report, parse_report
from camlab88.protocols.sigma.decoder import Decoder
from camlab88.protocols.sigma.encoder import Encoder
from camlab88.protocols.sigma.orders import ORDERS, OrderSpec

__all__ = [*commands.__all__, "ORDERS", "CursorReport", "Decoder", "Encoder", "OrderSpec",
           "format_report", "parse_report"]
