"""Same input, same frame, bit for bit — in this process, another, or after pickling."""

from __future__ import annotations

import hashlib
import pickle
import subprocess
import sys
from pathlib import Path

import numpy as np

from camlab88.apps.snooker.render.palette import fixed_palette
from camlab88.apps.snooker.render.sigma_host import SigmaHost
from camlab88.apps.snooker.render.truecolour import RenderOptions, render_frame
from tests.snooker_render.helpers import break_scene, break_views

ROOT = Path(__file__).resolve().parents[2]
OPTS = RenderOptions(320, 200)


def test_truecolour_frames_are_bit_identical_across_processes(tmp_path: Path) -> None:
    scene, view = break_scene(), break_views()[20]
    here = render_frame(scene, view, OPTS)
    assert np.array_equal(here, render_frame(scene, view, OPTS))
    blob = tmp_path / "job.pickle"
    blob.write_bytes(pickle.dumps((scene, view, OPTS)))
    code = ("import pickle, sys, hashlib; from camlab88.apps.snooker.render.truecolour import "
            "render_frame; s, v, o = pickle.load(open(sys.argv[1], 'rb')); "
            "print(hashlib.sha256(render_frame(s, v, o).tobytes()).hexdigest())")
    out = subprocess.run([sys.executable, "-c", code, str(blob)], cwd=ROOT, check=True,
                         capture_output=True, text=True).stdout.strip()
    assert out == hashlib.sha256(here.tobytes()).hexdigest()


def test_frame_depends_only_on_its_inputs_not_on_what_was_rendered_before() -> None:
    scene, views = break_scene(), break_views()
    alone = render_frame(break_scene(), views[30], OPTS)
    for v in views[:3]:
        render_frame(scene, v, OPTS)
    assert np.array_equal(render_frame(scene, views[30], OPTS), alone)


def test_period_stream_is_identical_every_time() -> None:
    scene, view = break_scene(), break_views()[5]
    a = SigmaHost(scene, fixed_palette(scene), "period").frame(view)
    b = SigmaHost(break_scene(), fixed_palette(break_scene()), "period").frame(view)
    assert a.data == b.data and np.array_equal(a.intended, b.intended)
