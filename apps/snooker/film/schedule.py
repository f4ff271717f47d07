"""Rendering a film's frames in parallel, resumably (thesis 6.4: each frame is independent,
"compiled into a finished sequence" afterwards).

Frames whose PNG is exactly what was written for the same scene, view and look are skipped
(``DIR/film.json`` records each frame's key and the SHA-256 of the bytes written: a PNG
copied over another, or a few pixels repainted, is a different file and is made again);
the others are handed to the backend, at most ``2 x workers`` at a time so a dead worker
costs little; each result is checked (it decodes whole, at the right size) and written
atomically, so the directory never holds a broken PNG. A frame that fails, or whose worker
dies, is tried again up to ``attempts`` times; every failed attempt is reported.
"""

from __future__ import annotations

import hashlib
import json
import os
import time
from collections.abc import Callable, Sequence
from concurrent.futures import FIRST_COMPLETED, Future, wait
from concurrent.futures.process import BrokenProcessPool
from dataclasses import dataclass, field
from pathlib import Path

from camlab88.apps.snooker.film.backends import Backend
from camlab88.apps.snooker.film.pngcheck import png_size
from camlab88.apps.snooker.film.task import FrameTask, task_key
from camlab88.base.atomicfile import write_atomic


class Manifest:
    """frame -> (key of what its PNG shows, SHA-256 of the bytes written), rewritten
    atomically at most every ``every_s`` seconds and at the end (a frame whose entry did not
    reach the disk before a kill is simply rendered again; one fsync a frame would cap the
    frame rate)."""

    def __init__(self, path: Path, every_s: float = 0.5) -> None:
        self.path, self.every_s = path, every_s
        self.dirty, self.saved_at = False, time.monotonic()
        try:
            raw = json.loads(path.read_text(encoding="utf-8"))
            self.keys = {int(k): (str(v["key"]), str(v["sha256"]))
                         for k, v in raw.get("frames", {}).items()}
        except (OSError, ValueError, AttributeError, KeyError, TypeError):
            self.keys = {}  # missing, damaged or without hashes: every frame is made again

    def holds(self, frame: int, key: str, png: Path) -> bool:
        """Is ``png`` exactly the file written for ``frame`` made as ``key``?"""
        entry = self.keys.get(frame)
        if entry is None or entry[0] != key:
            return False
        try:
            return hashlib.sha256(png.read_bytes()).hexdigest() == entry[1]
        except OSError:
            return False

    def put(self, frame: int, key: str, data: bytes) -> None:
        """``data``: the bytes just written for ``frame``."""
        self.keys[frame] = (key, hashlib.sha256(data).hexdigest())
        self.dirty = True
        if time.monotonic() - self.saved_at >= self.every_s:
            self.save()

    def save(self) -> None:
        if self.dirty:
            frames = {str(k): {"key": v[0], "sha256": v[1]} for k, v in sorted(self.keys.items())}
            text = json.dumps({"frames": frames}, indent=0)
            write_atomic(self.path, text + "\n")
            self.dirty, self.saved_at = False, time.monotonic()

Progress = Callable[[int, int], None]
MANIFEST = "film.json"


class FilmError(RuntimeError):
    pass


@dataclass
class FilmReport:
    rendered: list[int] = field(default_factory=list)
    skipped: list[int] = field(default_factory=list)
    retries: list[tuple[int, str]] = field(default_factory=list)  # (frame, what went wrong)
    failed: list[int] = field(default_factory=list)


def frame_file(directory: str | os.PathLike[str], frame: int) -> Path:
    """``DIR/frame_NNNNN.png``, as every camlab88 command names a sequence's frames."""
    return Path(directory) / f"frame_{frame:05d}.png"


def render_film(tasks: Sequence[FrameTask], out_dir: str | os.PathLike[str], backend: Backend,
                digest: str, progress: Progress | None = None,
                attempts: int = 3, manifest: str = MANIFEST) -> FilmReport:
    """``digest``: task.scene_digest of the scene the backend renders; ``manifest``: the
    resume record's name in ``out_dir`` (``snooker render`` keeps it hidden)."""
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    report = FilmReport()
    keys = Manifest(out / manifest)
    todo = []
    for t in tasks:
        done = keys.holds(t.frame, task_key(digest, t), frame_file(out, t.frame))
        (report.skipped.append(t.frame) if done else todo.append(t))
    run = _Run(backend, out, report, progress, attempts, len(tasks))
    run.written = lambda t, data: keys.put(t.frame, task_key(digest, t), data)
    try:
        run.go(todo)
    finally:
        keys.save()
    if report.failed:
        raise FilmError(f"frames {', '.join(map(str, report.failed))} failed after "
                        f"{attempts} attempts: {report.retries[-1][1]}")
    return report


class _Run:
    def __init__(self, backend: Backend, out: Path, report: FilmReport,
                 progress: Progress | None, attempts: int, total: int) -> None:
        self.backend, self.out, self.report = backend, out, report
        self.progress, self.attempts, self.total = progress, attempts, total
        self.tries: dict[int, int] = {}
        self.running: dict[Future, FrameTask] = {}
        self.written: Callable[[FrameTask, bytes], None] = lambda t, data: None

    def go(self, todo: list[FrameTask]) -> None:
        queue = list(reversed(todo))
        self._tick()
        while queue or self.running:
            while queue and len(self.running) < 2 * self.backend.workers:
                t = queue.pop()
                try:
                    self.running[self.backend.submit(t)] = t
                except BrokenProcessPool:  # the pool died since the last wait
                    self._failed(t, "its worker process died", queue)
                    self._lost(queue)
            if not self.running:
                continue
            finished, _ = wait(list(self.running), return_when=FIRST_COMPLETED)
            broken = False
            for f in finished:
                t = self.running.pop(f)
                problem = self._take(f, t)
                if problem is not None:
                    broken |= isinstance(f.exception(), BrokenProcessPool)
                    self._failed(t, problem, queue)
            if broken:
                self._lost(queue)

    def _lost(self, queue: list[FrameTask]) -> None:
        """A dead pool: every frame still in it is lost with it; start a new one."""
        for t in self.running.values():
            self._failed(t, "its worker process died", queue)
        self.running.clear()
        self.backend.restart()

    def _take(self, f: Future, t: FrameTask) -> str | None:
        exc = f.exception()
        if exc is not None:
            return f"{type(exc).__name__}: {exc}"
        data = f.result()
        if png_size(data) != (t.width, t.height):
            return "the worker returned a PNG that does not decode at the film's size"
        write_atomic(frame_file(self.out, t.frame), data)
        self.written(t, data)
        self.report.rendered.append(t.frame)
        self._tick()
        return None

    def _failed(self, t: FrameTask, problem: str, queue: list[FrameTask]) -> None:
        n = self.tries.get(t.frame, 0) + 1
        self.tries[t.frame] = n
        self.report.retries.append((t.frame, problem))
        if n >= self.attempts:
            self.report.failed.append(t.frame)
        else:
            queue.append(t)

    def _tick(self) -> None:
        if self.progress is not None:
            self.progress(len(self.report.rendered) + len(self.report.skipped), self.total)
