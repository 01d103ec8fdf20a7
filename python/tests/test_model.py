"""The scene model in Python: built, edited, compared, and kept consistent."""

import math
import os
import re

import numpy as np
import pytest

import scenefile
from scenefile import (CUBE, CYLINDER, PLANE, SPHERE, Camera, Light, Material, Object, Scene,
                       TransformOp, View)
from conftest import EXAMPLES, SOURCE, TESTDATA


def built_scene():
    scene = Scene(Camera.looking_at((0, 2, 8), (0, 0.5, 0)))
    scene.lights.append(Light((4, 6, 5), (1, 1, 1)))
    # An empty list, as an instruction file's empty TRANSFORMATION gives:
    # as in C++, no list and an empty one are different values.
    scene.objects.append(Object(PLANE, colour=(0.8, 0.8, 0.8), transforms=[]))
    scene.objects.append(Object(SPHERE, transforms=[TransformOp.scale(0.5),
                                                    TransformOp.translate(-1, 0.5, 0)],
                                material=Material((1, 0, 0), reflectivity=0.3)))
    scene.objects.append(Object("CUBE", transforms=[TransformOp.rotate_y(math.pi / 5),
                                                    TransformOp.translate(1, 0.5, -1)]))
    return scene


def test_a_scene_built_in_python_comes_back_from_each_line_format(tmp_path):
    scene = built_scene()
    assert scenefile.validate(scene) == []
    scene.output_file = "built.png"
    scenefile.write(scene, tmp_path / "built.txt")
    back = scenefile.read(tmp_path / "built.txt")
    assert back == scene
    assert back.objects[1].transforms == scene.objects[1].transforms
    assert back.camera.look_at == (0.0, 0.5, 0.0)
    # A scene file keeps the matrices and colours, and loses the rest.
    losses = scenefile.write(scene, tmp_path / "built.sf")
    assert [d.code for d in losses] == ["loss-material", "dropped-output-file"]
    flat = scenefile.read(tmp_path / "built.sf")
    assert [o.matrix.tolist() for o in flat.objects] == [o.matrix.tolist() for o in scene.objects]
    assert flat.objects[1].material.reflectivity == 0.0


def test_defaults_are_the_formats():
    # The model's defaults are FORMATS.md's, as a scene file's reader gives them.
    sphere = scenefile.loads("CAMERA\n0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n"
                             "SPHERE\n1 1 1\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n").objects[0]
    assert sphere.material == Material()
    assert sphere.material.is_default()
    assert Material().shininess == 200.0 and Material().ri == 1.0
    assert Scene().camera == Camera()


def test_matrices_are_float64_4x4_row_by_row():
    scene = scenefile.read(os.path.join(TESTDATA, "valid", "all-primitives.sf"))
    m = scene.objects[0].matrix
    assert m.dtype == np.float64 and m.shape == (4, 4)
    assert list(m[3]) == [0, 0, 0, 1]
    lines = [line for line in open(os.path.join(TESTDATA, "valid", "all-primitives.sf"))
             .read().splitlines() if line.strip()]
    first = next(i for i in range(0, len(lines), 6) if lines[i] not in ("CAMERA", "LIGHT"))
    rows = [[float(x) for x in lines[first + 2 + r].split()] for r in range(4)]
    assert m.tolist() == rows
    source = np.identity(4)
    obj = Object(CUBE, source)
    source[0, 3] = 5.0
    assert obj.matrix[0, 3] == 0.0, "the object keeps a copy"
    with pytest.raises(ValueError, match="4 x 4"):
        Object(CUBE, np.identity(3))
    with pytest.raises(TypeError):
        Object(CUBE, "identity")


def test_colours_are_tuples_of_three_floats():
    obj = Object(SPHERE, colour=np.array([1, 0.5, 0]))
    assert obj.colour == (1.0, 0.5, 0.0) and type(obj.colour[0]) is float
    obj.colour = [0.25, 0.25, 0.25]
    assert obj.material.colour == (0.25, 0.25, 0.25)
    for bad in ((1, 2), (1, 2, 3, 4), "red", (1, None, 0)):
        with pytest.raises((ValueError, TypeError)):
            obj.colour = bad
    with pytest.raises(TypeError):
        obj.material.ambient = "0.5"


def test_kinds_are_checked_with_a_suggestion():
    assert Object("SPHERE").kind is SPHERE and SPHERE == "SPHERE"
    assert str(CYLINDER) == "CYLINDER"
    with pytest.raises(ValueError, match="did you mean SPHERE"):
        Object("sphere")
    with pytest.raises(ValueError, match="ROTATE_X"):
        TransformOp("ROTATE", 1.0)


def test_the_kinds_are_those_of_object_kinds_def_in_its_order():
    # Python cannot include the C++ list, so it is read here: a kind added
    # there and not to ObjectKind, or the other way round, fails.
    with open(os.path.join(SOURCE, "include", "scenefile", "object_kinds.def")) as f:
        text = f.read()
    records = re.findall(r"^SCENEFILE_OBJECT_KIND\(\w+, (\w+), \w+\)$", text, re.M)
    assert records and len(records) == text.count("\nSCENEFILE_OBJECT_KIND(")
    assert [kind.name for kind in scenefile.ObjectKind] == records
    assert [kind.value for kind in scenefile.ObjectKind] == records
    for record in records:
        assert getattr(scenefile, record) is scenefile.ObjectKind[record]
        assert record in scenefile.__all__
        assert scenefile.primitive_mesh(record, 8, 1.0)[2].shape[1] == 3


def test_transforms_describe_the_matrix_while_they_agree():
    obj = Object(SPHERE, transforms=[TransformOp.scale(2), TransformOp.translate(1, 2, 3)])
    assert obj.matrix.tolist() == [[2, 0, 0, 1], [0, 2, 0, 2], [0, 0, 2, 3], [0, 0, 0, 1]]
    assert obj.transforms == (TransformOp.scale(2, 2, 2), TransformOp.translate(1, 2, 3))
    # Changed in place, or replaced: the matrix is the truth.
    obj.matrix[0, 3] = 5.0
    assert obj.transforms is None
    obj.transforms = [TransformOp.rotate_z(math.pi / 2)]
    assert obj.transforms is not None
    obj.matrix = obj.matrix @ np.diag([1.0, 3.0, 1.0, 1.0])
    assert obj.transforms is None
    with pytest.raises(ValueError, match="not the one the transforms make"):
        Object(SPHERE, np.identity(4), transforms=[TransformOp.scale(2)])
    # Read from a file, they are the file's.
    cube = scenefile.read(os.path.join(EXAMPLES, "blue-cube.txt")).objects[1]
    assert [op.kind.value for op in cube.transforms] == ["SCALE", "TRANSLATE", "ROTATE_X",
                                                         "ROTATE_Y", "ROTATE_Z"]
    assert np.array_equal(scenefile.compose_transform(cube.transforms), cube.matrix)


def test_an_edited_object_is_written_from_its_matrix(tmp_path):
    scene = scenefile.read(os.path.join(EXAMPLES, "blue-cube.txt"))
    scene.objects[1].matrix[:3, 3] += (0.0, 1.0, 0.0)
    scenefile.write(scene, tmp_path / "moved.txt")
    moved = scenefile.read(tmp_path / "moved.txt").objects[1]
    assert np.allclose(moved.matrix, scene.objects[1].matrix, rtol=0, atol=1e-12)
    assert moved.transforms[-1].kind == scenefile.TransformKind.TRANSLATE


def test_an_instruction_camera_keeps_its_look_at_while_its_matrix_is_the_one_it_gave():
    camera = Camera.looking_at((4, 3, 6), (0, 0.5, 0))
    assert camera.look_at == (0.0, 0.5, 0.0)
    assert camera.eye == (4.0, 3.0, 6.0)
    assert np.allclose(np.cross(camera.forward, camera.up), camera.matrix[:3, 0])
    camera.matrix[:3, 3] = (1, 1, 1)
    assert camera.look_at is None
    camera.look_at = (0, 0, 0)
    assert camera.look_at == (0.0, 0.0, 0.0) and camera.eye == (1.0, 1.0, 1.0)
    with pytest.raises(ValueError, match="same point"):
        Camera.looking_at((1, 1, 1), (1, 1, 1))


def test_transform_ops_are_immutable_values():
    a = TransformOp.rotate_x(0.5)
    assert a.value == (0.5, 0.0, 0.0) and a.angle == 0.5
    assert a == TransformOp("ROTATE_X", 0.5) and hash(a) == hash(TransformOp("ROTATE_X", 0.5))
    with pytest.raises(AttributeError):
        a.kind = "SCALE"
    with pytest.raises(ValueError):
        TransformOp.scale(1).angle
    with pytest.raises(ValueError, match="one angle"):
        TransformOp("ROTATE_Y", (0.1, 0.2, 0))
    c, s = math.cos(0.5), math.sin(0.5)
    assert np.allclose(a.matrix[1:3, 1:3], [[c, -s], [s, c]])
    ops, exact = scenefile.decompose_transform(scenefile.compose_transform(
        [TransformOp.scale(1, 2, 3), TransformOp.rotate_x(0.5), TransformOp.translate(1, 0, 0)]))
    assert exact and [op.kind.value for op in ops] == ["SCALE", "ROTATE_X", "TRANSLATE"]
    sheared = np.identity(4)
    sheared[0, 1] = 0.5
    assert scenefile.decompose_transform(sheared)[1] is False


def test_equality_is_of_values_and_copies_are_deep():
    a = scenefile.read(os.path.join(EXAMPLES, "blue-cube.txt"))
    b = scenefile.read(os.path.join(EXAMPLES, "blue-cube.txt"))
    assert a == b and a is not b
    c = a.copy()
    c.objects[0].colour = (0, 0, 0)
    c.lights[0].position = (9, 9, 9)
    assert a == b and c != a
    assert a.lights[0].position != (9.0, 9.0, 9.0)
    a.view = View(45.0, 1.5)
    assert a != b
    assert a.view == View(45.0, 1.5) and a.view != View(45.0)


def test_wrong_types_in_the_lists_are_named():
    scene = built_scene()
    scene.objects.append("a sphere")
    with pytest.raises(TypeError, match=r"objects\[3\] is a str"):
        scenefile.validate(scene)


def test_validate_points_at_what_is_wrong():
    scene = built_scene()
    scene.lights.clear()
    scene.objects[0].colour = (-1, 0, 0)
    scene.objects[2].matrix = np.diag([1.0, 1.0, 0.0, 1.0])
    codes = [(d.severity.value, d.code) for d in scenefile.validate(scene)]
    assert ("error", "negative-colour") in codes
    assert ("error", "matrix-singular") in codes
    assert ("warning", "no-light") in codes
    nan = built_scene()
    nan.objects[1].material.ri = float("nan")
    assert [d.code for d in scenefile.validate(nan)] == ["value-not-finite"]


@pytest.mark.parametrize("fov, aspect_ratio", [(60, -1), (60, 0), (60, 1e9), (-5, None),
                                               (1e-300, None), (0, None), (180, None),
                                               (float("nan"), None), (60, float("inf"))])
def test_a_view_out_of_range_is_a_validation_error(tmp_path, fov, aspect_ratio):
    # The readers' range for a view: what validate() passes reads back.
    scene = built_scene()
    scene.view = View(fov, aspect_ratio)
    errors = [d for d in scenefile.validate(scene) if d.severity == "error"]
    assert [d.code for d in errors] in (["value-out-of-range"], ["value-not-finite"])
    for name in ("v.gltf", "v.pov", "v.sf"):
        with pytest.raises(scenefile.SceneError):
            scenefile.write(scene, tmp_path / name)
    with pytest.raises(scenefile.SceneError):
        scenefile.render(scene, 4, 4, fov=None)
    assert os.listdir(tmp_path) == []


def test_a_view_in_range_reads_back(tmp_path):
    scene = built_scene()
    for view in (View(0.001, 1 / 32768), View(179.999, 32768), View(45, None)):
        scene.view = view
        assert scenefile.validate(scene) == []
        scenefile.write(scene, tmp_path / "v.gltf")
        assert scenefile.read(tmp_path / "v.gltf").view.fov == pytest.approx(view.fov)


@pytest.mark.parametrize("fov", [1e-300, 4.9e-324, -5, 0, 180, 1e300])
def test_an_fov_given_is_held_to_the_views_range(tmp_path, fov):
    scene = built_scene()
    for name in ("f.gltf", "f.pov"):
        with pytest.raises(ValueError, match="fov"):
            scenefile.write(scene, tmp_path / name, fov=fov)
    with pytest.raises(ValueError, match="fov"):
        scenefile.render(scene, 4, 4, fov=fov)
    assert os.listdir(tmp_path) == []
