"""Scripted mouse and keyboard input for the snooker program: the one Rainbow script format,
protocols.rainbow.script (``move``, ``glide``, ``press``, ``release``, ``click``, ``drag``,
``key``, ``type``, ``wait``/``frames``); see there for the language and its bounds."""

from __future__ import annotations

from camlab88.protocols.rainbow.script import Player, Script, ScriptError, load, parse

__all__ = ["Player", "Script", "ScriptError", "load", "parse"]
