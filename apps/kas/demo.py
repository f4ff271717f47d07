"""'A line taking a walk': the shipped demo, built from library data by the KAS pipeline.

A wandering line walks across the field along a hand-drawn path with hand-placed tick
marks; a sun (second element, its own keyframes and a timing curve) rises, starting later,
and is superimposed on the walk (§3.1.2, §3.1.3).
"""

from __future__ import annotations

from camlab88.apps.kas import files
from camlab88.apps.kas.inbetween import inbetween
from camlab88.apps.kas.library import LIBRARY
from camlab88.apps.kas.model import AnimSequence
from camlab88.apps.kas.superimpose import superimpose

SUN_OFFSET = 8  # frames after the walk starts


def walk() -> AnimSequence:
    return inbetween(files.load_keyframe(LIBRARY / "walk_a.kas"),
                     files.load_keyframe(LIBRARY / "walk_b.kas"),
                     path=files.load_path(LIBRARY / "walk_path.kas"),
                     timing=files.load_timing(LIBRARY / "walk_ticks.kas"))


def sun(frames: int = 20) -> AnimSequence:
    # No sample path: the sun rises straight, easing in and out.  (The one path fitted to
    # each point of a growing circle would bend every point differently, deforming it.)
    return inbetween(files.load_keyframe(LIBRARY / "sun_a.kas"),
                     files.load_keyframe(LIBRARY / "sun_b.kas"),
                     timing=files.load_timing(LIBRARY / "ease-in-out.kas"), frames=frames)


def build() -> AnimSequence:
    return superimpose([(walk(), 0), (sun(), SUN_OFFSET)])
