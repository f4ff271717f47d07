"""The optional local-socket transport, device end: serve one Rainbow on 127.0.0.1.

Policy (docs/reliability.md): the Rainbow serves one program at a time, as the real
workstation served its one host. A second program that connects meanwhile gets a REFUSED
frame saying so and is closed. Every connection starts with a fresh frame decoder, so a
half frame left by one client never reaches the next and error offsets count from the
connection's first byte. Each connection is also a fresh pad-library session: the pads,
clusters, arcs, colour tables and pending input of one program never reach the next (node 77
of one program is not "already there" for the next). A client that resets, closes mid-frame
or sends garbage loses its connection and nothing else: the server goes on to the next. A
frame still unfinished ``frame_timeout`` seconds after its first byte arrived (its age, however
the bytes trickle in), a client silent for ``idle_timeout`` seconds while another program
is waiting, or one that has been connected ``session_time`` seconds while another is waiting
(however steadily it sends: a ``hello`` frame a second held the server for ever) is hung up
on — so no client can wedge the server.
"""

from __future__ import annotations

import contextlib
import select
import socket
import time
from dataclasses import dataclass, field

from camlab88.emulator.rainbow.executor import Executor
from camlab88.protocols.rainbow.stream import REFUSED, Decoder, StreamError, encode_reply

FRAME_TIMEOUT = 10.0  # s from a frame's first byte to its last
IDLE_TIMEOUT = 60.0  # s of silence after which a client gives way to a waiting one
SESSION_TIME = 180.0  # s connected after which a client gives way to a waiting one
BACKLOG = 128  # connections the kernel queues while one program is served (then refused)
BUSY = b"the Rainbow is serving another program; try again when it has finished"


@dataclass
class ServerStats:
    served: int = 0  # connections accepted and finished
    refused: int = 0  # connections turned away while another was served
    dropped: list[str] = field(default_factory=list)  # why connections ended early


def _send(conn: socket.socket, data: bytes) -> bool:
    try:
        conn.sendall(data)
    except OSError:
        return False
    return True


def _refuse(conn: socket.socket, why: bytes) -> None:
    with conn:
        conn.settimeout(1.0)  # a client that never reads cannot hold us here
        _send(conn, encode_reply(REFUSED, why))


class _Client:
    """One connection: its socket, its own decoder and pad-library session, when it last
    sent anything and when the frame it has not finished began."""

    def __init__(self, conn: socket.socket, executor: Executor, frame_timeout: float) -> None:
        self.conn = conn
        self.executor = executor
        executor.decoder = Decoder()  # per-connection state: nothing carries over
        executor.device.new_session()
        conn.settimeout(frame_timeout)  # sendall to a client that stops reading gives up
        self.last_heard = self.began = time.monotonic()
        self.frame_began: float | None = None  # when the unfinished frame's first byte came

    def receive(self) -> str | None:
        """Handle what the client sent; returns why the connection ends, or None."""
        try:
            data = self.conn.recv(1 << 16)
        except OSError as exc:
            return f"receive failed: {exc.strerror or exc}"
        if not data:
            return "closed by the client" + (" mid-frame" if self.executor.decoder.pending
                                             else "")
        self.last_heard = time.monotonic()
        decoder = self.executor.decoder
        at = decoder.at
        try:
            replies = self.executor.feed(data)
        except StreamError:
            replies = b""
        if not decoder.pending:
            self.frame_began = None
        elif self.frame_began is None or decoder.at != at:  # a new frame began in this data
            self.frame_began = self.last_heard
        if replies and not _send(self.conn, replies):
            return "the client stopped taking replies"
        error = self.executor.decoder.error
        if error is not None:
            # A broken frame cannot be resynchronised: say why, then hang up.
            _send(self.conn, encode_reply(REFUSED, str(error).encode()))
            return f"bad frame: {error}"
        return None

    def overdue(self, now: float, someone_waiting: bool, frame_timeout: float,
                idle_timeout: float, session_time: float = SESSION_TIME) -> str | None:
        silent = now - self.last_heard
        began = self.frame_began
        if began is not None and now - began > frame_timeout:
            return f"a frame unfinished {now - began:.1f} s after its first byte"
        if someone_waiting and silent > idle_timeout:
            return f"idle for {silent:.0f} s while another program waited"
        if someone_waiting and now - self.began > session_time:
            return f"connected for {now - self.began:.0f} s while another program waited"
        return None

    def close(self) -> None:
        with contextlib.suppress(OSError):
            self.conn.close()


def listen(port: int = 0, host: str = "127.0.0.1") -> socket.socket:
    s = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
    s.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
    s.bind((host, port))
    s.listen(BACKLOG)
    return s


def _waiting(sock: socket.socket) -> bool:
    return bool(select.select([sock], [], [], 0)[0])


def serve(executor: Executor, sock: socket.socket, connections: int | None = None,
          frame_timeout: float = FRAME_TIMEOUT, idle_timeout: float = IDLE_TIMEOUT,
          poll: float = 0.5, session_time: float = SESSION_TIME) -> ServerStats:
    """Serve programs one at a time until ``connections`` have been served (None: for ever);
    see the module docstring for what happens to the others."""
    stats = ServerStats()
    client: _Client | None = None
    try:
        while connections is None or stats.served < connections:
            watch = [sock] + ([client.conn] if client else [])
            ready = select.select(watch, [], [], poll)[0]
            if client is not None and client.conn in ready:
                why = client.receive()
                if why is None:
                    why = client.overdue(time.monotonic(), _waiting(sock), frame_timeout,
                                         idle_timeout, session_time)
                    if why is None:
                        continue  # read it to its end before judging a newcomer "busy"
            elif client is not None:
                why = client.overdue(time.monotonic(), sock in ready, frame_timeout,
                                     idle_timeout, session_time)
            else:
                why = None
            if client is not None and why is not None:
                client.close()
                client = None
                stats.served += 1
                if why != "closed by the client":
                    stats.dropped.append(why)
                continue
            if sock in ready:
                client = _accept(sock, executor, client, stats, frame_timeout)
    finally:
        if client is not None:
            client.close()
    return stats


def _accept(sock: socket.socket, executor: Executor, client: _Client | None,
            stats: ServerStats, frame_timeout: float) -> _Client | None:
    try:
        conn, _ = sock.accept()
    except OSError:
        return client  # the caller went away between select and accept
    if client is not None:
        _refuse(conn, BUSY)
        stats.refused += 1
        return client
    return _Client(conn, executor, frame_timeout)
