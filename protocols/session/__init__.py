"""Session recordings: a program's whole run (arguments, input files by content, input
events at virtual times, wire traffic, screen hashes), format version 1 (see ``format``)."""

from camlab88.protocols.session.format import (
    FORMAT,
    VERSION,
    ScreenHash,
    SessionFileError,
    SessionRecording,
    read,
    write,
)

__all__ = ["FORMAT", "VERSION", "ScreenHash", "SessionFileError", "SessionRecording",
           "read", "write"]
