"""Every argument of the package's functions is checked when it is given: the
wrong type is a TypeError and a number that is not finite or out of range a
ValueError, each naming the argument (docs/PYTHON.md, "Arguments"); an
OUTPUT_FILE is one the instruction files can hold, by the library's rule."""

import inspect
import math
import os
import typing

import numpy as np
import pytest

import scenefile
from scenefile import Camera
from conftest import TESTDATA, run

ALL = os.path.join(TESTDATA, "valid", "all-primitives.sf")
NAN, INF = float("nan"), float("inf")


@pytest.fixture
def scene():
    return scenefile.read(ALL)


@pytest.mark.parametrize("name", ["a b.ppm", "a\nb.ppm", "", "café.ppm", "\x1b[31m.ppm",
                                  "tab\there.ppm", "del\x7f.ppm"])
def test_an_output_file_an_instruction_file_cannot_hold_is_refused(scene, tmp_path, name):
    for path in (tmp_path / "o.txt", tmp_path / "o.gltf", tmp_path / "o.pov"):
        with pytest.raises(ValueError, match="output_file"):
            scenefile.write(scene, path, output_file=name)
    with pytest.raises(ValueError, match="output_file"):
        scenefile.convert(ALL, tmp_path / "c.txt", output_file=name)
    assert os.listdir(tmp_path) == []


def test_a_good_output_file_reads_back(scene, tmp_path):
    scenefile.write(scene, tmp_path / "o.txt", output_file="out/image-1.png")
    assert scenefile.read(tmp_path / "o.txt").output_file == "out/image-1.png"


@pytest.mark.parametrize("name, image", [("my scene.txt", "my_scene.ppm"),
                                         ("my café.txt", "my_caf_.ppm"),
                                         ("tab\there.txt", "tab_here.ppm")])
def test_an_output_file_made_from_the_file_name_is_one_too(scene, sfconvert, tmp_path, name,
                                                           image):
    # As sfconvert: the image is named after the instruction file, what an
    # instruction file cannot hold in a name made '_' (the library's rule).
    (tmp_path / "ours").mkdir()
    (tmp_path / "theirs").mkdir()
    scenefile.write(scene, tmp_path / "ours" / name)
    assert scenefile.read(tmp_path / "ours" / name).output_file == image
    run(sfconvert, ALL, tmp_path / "theirs" / name, "--quiet")
    assert (tmp_path / "ours" / name).read_bytes() == (tmp_path / "theirs" / name).read_bytes()


def positions_and_triangles():
    positions, _, triangles = scenefile.primitive_mesh("CUBE")
    return positions, triangles


# (call, the argument it names, the exception)
BAD_CALLS = [
    (lambda s: scenefile.fit_primitive(*positions_and_triangles(), tolerance=NAN), "tolerance",
     ValueError),
    (lambda s: scenefile.fit_primitive(*positions_and_triangles(), tolerance=INF), "tolerance",
     ValueError),
    (lambda s: scenefile.fit_primitive(*positions_and_triangles(), tolerance=-1), "tolerance",
     ValueError),
    (lambda s: scenefile.fit_primitive(*positions_and_triangles(), tolerance=0), "tolerance",
     ValueError),
    (lambda s: scenefile.fit_primitive(*positions_and_triangles(), tolerance="0.1"), "tolerance",
     TypeError),
    (lambda s: scenefile.fit_primitive(*positions_and_triangles(), tolerance=True), "tolerance",
     TypeError),
    (lambda s: scenefile.decompose_transform(np.zeros((4, 4))), "matrix", ValueError),
    (lambda s: scenefile.decompose_transform(np.diag([1.0, 1.0, 0.0, 1.0])), "matrix",
     ValueError),
    (lambda s: scenefile.decompose_transform(np.full((4, 4), NAN)), "matrix", ValueError),
    (lambda s: scenefile.decompose_transform(np.identity(3)), "matrix", ValueError),
    (lambda s: scenefile.decompose_transform([["a"] * 4] * 4), "matrix", TypeError),
    (lambda s: scenefile.primitive_mesh("PLANE", plane_half_size=NAN), "plane_half_size",
     ValueError),
    (lambda s: scenefile.primitive_mesh("PLANE", plane_half_size=-INF), "plane_half_size",
     ValueError),
    (lambda s: scenefile.primitive_mesh("PLANE", plane_half_size=0), "plane_half_size",
     ValueError),
    (lambda s: scenefile.primitive_mesh("PLANE", plane_half_size=1e-50), "plane_half_size",
     ValueError),
    (lambda s: scenefile.primitive_mesh("PLANE", plane_half_size=1e39), "plane_half_size",
     ValueError),
    (lambda s: scenefile.primitive_mesh("PLANE", plane_half_size="1"), "plane_half_size",
     TypeError),
    (lambda s: scenefile.primitive_mesh("SPHERE", segments="8"), "segments", TypeError),
    (lambda s: scenefile.primitive_mesh("SPHERE", segments=8.5), "segments", TypeError),
    (lambda s: scenefile.primitive_mesh("SPHERE", segments=2), "segments", ValueError),
    (lambda s: Camera.looking_at((NAN, 0, 0), (0, 0, 0)), "location", ValueError),
    (lambda s: Camera.looking_at((0, 0, 5), (0, INF, 0)), "look_at", ValueError),
    (lambda s: Camera.looking_at((0, 0, 5), ("0", 0, 0)), "look_at", TypeError),
    (lambda s: scenefile.render(s, 8, 8, fov="60"), "fov", TypeError),
    (lambda s: scenefile.render(s, 8, 8, fov=NAN), "fov", ValueError),
    (lambda s: scenefile.render(s, 8, 8, fov=True), "fov", TypeError),
    (lambda s: scenefile.render(s, 8.0, 8), "width", TypeError),
    (lambda s: scenefile.render(s, 8, 8, seed=-1), "seed", ValueError),
    (lambda s: scenefile.render(None, 8, 8), "scene", TypeError),
    (lambda s: scenefile.validate(None), "scene", TypeError),
    (lambda s: scenefile.validate("scene.sf"), "scene", TypeError),
    (lambda s: scenefile.write(None, "x.sf"), "scene", TypeError),
    (lambda s: scenefile.write(s, 5), "path", TypeError),
    (lambda s: scenefile.write(s, "x.gltf", fov=NAN), "fov", ValueError),
    (lambda s: scenefile.write(s, "x.gltf", fov=INF), "fov", ValueError),
    (lambda s: scenefile.write(s, "x.gltf", fov="60"), "fov", TypeError),
    (lambda s: scenefile.write(s, "x.gltf", width=1.5), "width", TypeError),
    (lambda s: scenefile.write(s, "x.sf", no_loss="yes"), "no_loss", TypeError),
    (lambda s: scenefile.convert(ALL, "x.gltf", tessellation=NAN), "tessellation", TypeError),
    (lambda s: scenefile.read(ALL, max_objects=NAN), "max_objects", TypeError),
    (lambda s: scenefile.read(ALL, max_objects=0), "max_objects", ValueError),
    (lambda s: scenefile.read(ALL, max_file_size=True), "max_file_size", TypeError),
    (lambda s: scenefile.check(ALL, error_limit=2.0), "error_limit", TypeError),
    (lambda s: scenefile.loads(b"", max_objects=-1), "max_objects", ValueError),
    (lambda s: scenefile.loads(5), "data", TypeError),
    (lambda s: scenefile.compose_transform(["SCALE"]), "ops", TypeError),
    (lambda s: scenefile.compose_transform(5), "ops", TypeError),
    (lambda s: scenefile.fit_primitive("abc", [0, 1, 2]), "positions", TypeError),
    (lambda s: scenefile.fit_primitive([[0, 0]], [0, 1, 2]), "positions", ValueError),
    (lambda s: scenefile.fit_primitive([[0, 0, 0]], [0.5, 1, 2]), "triangles", ValueError),
]


@pytest.mark.parametrize("call, name, error", BAD_CALLS)
def test_a_bad_argument_is_named(scene, tmp_path, monkeypatch, call, name, error):
    monkeypatch.chdir(tmp_path)
    with pytest.raises(error, match=name):
        call(scene)
    assert os.listdir(tmp_path) == [], "nothing written"


def test_decompose_transform_never_gives_a_number_that_is_not_finite():
    huge = np.diag([1e308, 1e308, 1e-308, 1.0])
    try:
        ops, _ = scenefile.decompose_transform(huge)
    except ValueError as refused:
        assert "matrix" in str(refused)
    else:
        assert all(math.isfinite(v) for op in ops for v in op.value)


def numeric_parameters():
    """Every parameter of the package's functions typed as a number."""
    found = []
    for name in scenefile.__all__:
        function = getattr(scenefile, name)
        if not inspect.isfunction(function):
            continue
        hints = typing.get_type_hints(function)
        for parameter in inspect.signature(function).parameters:
            hint = hints.get(parameter)
            if hint in (int, float, typing.Optional[float], typing.Optional[int]):
                found.append((name, parameter))
    return found


def test_every_numeric_parameter_is_found():
    found = numeric_parameters()
    for expected in [("render", "fov"), ("render", "spp"), ("fit_primitive", "tolerance"),
                     ("primitive_mesh", "plane_half_size"), ("primitive_mesh", "segments")]:
        assert expected in found


def arguments_for(name, scene):
    """The least call of each function that takes numbers."""
    positions, triangles = positions_and_triangles()
    return {"render": ((scene,), {"width": 4, "height": 4}),
            "fit_primitive": ((positions, triangles), {}),
            "primitive_mesh": (("PLANE",), {})}[name]


@pytest.mark.parametrize("function, parameter", numeric_parameters())
@pytest.mark.parametrize("value, error", [(NAN, ValueError), (INF, ValueError),
                                          (-INF, ValueError), ("1", TypeError),
                                          (True, TypeError), (None, None), ([1], TypeError)])
def test_every_numeric_parameter_is_checked(scene, function, parameter, value, error):
    args, kwargs = arguments_for(function, scene)
    hint = typing.get_type_hints(getattr(scenefile, function))[parameter]
    if value is None:
        if hint in (typing.Optional[float], typing.Optional[int]):
            return  # None means something there
        error = TypeError
    if hint in (int, typing.Optional[int]) and isinstance(value, float):
        error = TypeError  # not a whole number, whatever its value
    with pytest.raises(error, match=parameter):
        getattr(scenefile, function)(*args, **dict(kwargs, **{parameter: value}))


@pytest.mark.parametrize("make, name, error", [
    (lambda: scenefile.Note("1", 0, 0, "m"), "line", TypeError),
    (lambda: scenefile.Note(1, -1, 0, "m"), "column", ValueError),
    (lambda: scenefile.FixIt(1, 1, 2.5, "x"), "length", TypeError),
    (lambda: scenefile.Diagnostic("error", "c", "f", 1, True, "m"), "column", TypeError),
    (lambda: scenefile.Diagnostic("error", "c", "f", -3, 1, "m"), "line", ValueError),
])
def test_a_place_in_a_file_is_whole_numbers_from_0(make, name, error):
    with pytest.raises(error, match=name):
        make()
