"""§6.4.1: the table's surface, cushions, wooden surround and legs are constant-shaded: one
colour a face, ambient plus every light's diffuse term, worked out here by hand."""

from __future__ import annotations

import numpy as np

from camlab88.apps.snooker.render.materials import SURFACES
from camlab88.apps.snooker.render.painter import PolygonItem, plan
from camlab88.apps.snooker.render.shading import Phong
from tests.snooker_render.helpers import break_scene


def test_every_table_face_has_one_colour_ambient_plus_diffuse_at_its_centre() -> None:
    s = break_scene()
    p, lights = Phong(), s.lights
    faces = [it for it in plan(s, 0, np.array([-2.6, 0.0, 0.6]), np.zeros(22))
             if isinstance(it, PolygonItem)]
    assert {f.face.group for f in faces} >= {"surface", "leg"}
    for it in faces:
        f = it.face
        albedo = np.array(SURFACES[f.material])
        diffuse = np.zeros(3)
        for lp, li in zip(lights.positions, lights.colours, strict=True):
            to_light = (lp - f.centre) / np.linalg.norm(lp - f.centre)
            diffuse += max(float(f.normal @ to_light), 0.0) * li
        want = albedo * (p.ka * lights.ambient + p.kd * diffuse)
        assert it.colour.shape == (3,) and np.allclose(it.colour, want, atol=1e-12)
