"""Helpers the thesis's Rainbow programs used, built on the client API (program side)."""

from protocols.rainbow.ui.double_buffer import DoubleBuffer
from protocols.rainbow.ui.menu import CrossMenu, PopupMenu
from protocols.rainbow.ui.message import MessageArea
from protocols.rainbow.ui.superpad import SuperPad

__all__ = ["CrossMenu", "DoubleBuffer", "MessageArea", "PopupMenu", "SuperPad"]
