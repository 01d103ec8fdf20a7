"""fit_primitive and primitive_mesh: the library's mesh fitting from Python."""

import math

import numpy as np
import pytest

import scenefile
from scenefile import CUBE, CYLINDER, PLANE, SPHERE


def placed(positions, matrix):
    points = np.c_[positions.astype(np.float64), np.ones(len(positions))]
    return (points @ matrix.T)[:, :3]


def rotation(axis, angle):
    axis = np.asarray(axis, dtype=np.float64) / np.linalg.norm(axis)
    k = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    m = np.identity(4)
    m[:3, :3] = np.identity(3) + math.sin(angle) * k + (1 - math.cos(angle)) * k @ k
    return m


def on_unit_surface(kind, local):
    """How far the points lie from the unit primitive's surface."""
    x, y, z = local[:, 0], local[:, 1], local[:, 2]
    if kind is PLANE:
        return np.abs(y).max()
    if kind is SPHERE:
        return np.abs(np.linalg.norm(local, axis=1) - 1).max()
    if kind is CUBE:
        return np.abs(np.abs(local).max(axis=1) - 1).max()
    radial = np.hypot(x, z)
    side = np.abs(radial - 1) + np.maximum(np.abs(y) - 1, 0)
    cap = np.abs(np.abs(y) - 1) + np.maximum(radial - 1, 0)
    return np.minimum(side, cap).max()


@pytest.mark.parametrize("kind", [PLANE, SPHERE, CYLINDER, CUBE], ids=str)
def test_each_primitive_is_recognised_where_it_was_put(kind):
    positions, normals, triangles = scenefile.primitive_mesh(kind, 24, plane_half_size=2.0)
    assert positions.dtype == np.float32 and positions.shape[1] == 3
    assert normals.shape == positions.shape and triangles.shape[1] == 3
    # A sphere stays round, and a cylinder's section a circle.
    scale = {SPHERE: [1.5, 1.5, 1.5], CYLINDER: [1.5, 0.5, 1.5]}.get(kind, [1.5, 0.5, 2.0])
    scale = np.diag(scale + [1.0])
    move = np.identity(4)
    move[:3, 3] = (3.0, -1.0, 2.0)
    m = move @ rotation((1, 2, 3), 0.7) @ scale
    fit = scenefile.fit_primitive(placed(positions, m), triangles)
    assert fit and fit.kind is kind, fit.reason
    assert fit.error < scenefile.FIT_TOLERANCE
    local = placed(placed(positions, m), np.linalg.inv(fit.matrix))
    assert on_unit_surface(kind, local) < 1e-4, "the fitted matrix maps the mesh onto the primitive"
    assert np.allclose(fit.matrix[:3, 3], (3.0, -1.0, 2.0), atol=1e-6)


def test_what_is_no_primitive_is_named_with_the_reason():
    angles = np.linspace(0, 2 * math.pi, 24, endpoint=False)
    ring = [((2 + 0.5 * math.cos(b)) * math.cos(a), 0.5 * math.sin(b),
             (2 + 0.5 * math.cos(b)) * math.sin(a)) for a in angles for b in angles]
    quads = [(i * 24 + j, i * 24 + (j + 1) % 24, ((i + 1) % 24) * 24 + j)
             for i in range(24) for j in range(24)]
    fit = scenefile.fit_primitive(ring, quads)
    assert not fit and fit.kind is None and fit.reason
    positions, _, triangles = scenefile.primitive_mesh(CUBE)
    assert scenefile.fit_primitive(positions, triangles.reshape(-1)).kind is CUBE
    bad = positions.copy()
    bad[0, 0] = np.nan
    assert scenefile.fit_primitive(bad, triangles).reason == "vertex 0 is not finite"
    assert "is past the" in scenefile.fit_primitive(positions[:4], triangles).reason
    with pytest.raises(ValueError, match="vertex indices"):
        scenefile.fit_primitive(positions, -triangles.astype(np.int64))
    with pytest.raises(ValueError, match="no object kind"):
        scenefile.primitive_mesh("TORUS")
