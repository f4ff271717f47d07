"""Helpers the thesis's Rainbow programs used, built on the client API (program side)."""

from camlab88.protocols.rainbow.ui.double_buffer import DoubleBuffer
from camlab88.protocols.rainbow.ui.menu import CrossMenu, PopupMenu
from camlab88.protocols.rainbow.ui.message import MessageArea
from camlab88.protocols.rainbow.ui.superpad import SuperPad

__all__ = ["CrossMenu", "DoubleBuffer", "MessageArea", "PopupMenu", "SuperPad"]
