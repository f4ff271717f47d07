"""`camlab88 link ...`: inspect recordings and test connections (dump, stream, echo)."""

from protocols.link.cli import register

__all__ = ["register"]
