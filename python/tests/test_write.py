"""scenefile.write and convert against sfconvert: the same bytes, the same
losses, the same refusals; files written whole or not at all."""

import json
import os
import stat
import struct

import pytest

import scenefile
from conftest import EXAMPLES, SOURCE, TESTDATA, run

SHEAR = os.path.join(SOURCE, "tests", "gltf", "scenes", "shear-scale-mirror.sf")
ALL = os.path.join(TESTDATA, "valid", "all-primitives.sf")
CUBE = os.path.join(EXAMPLES, "blue-cube.txt")
POV = os.path.join(TESTDATA, "view", "wide-angle.pov")
GLTF = os.path.join(TESTDATA, "gltf", "torus-and-sphere.gltf")

# (input, output name, sfconvert's flags, convert()'s options)
CONVERSIONS = [
    (CUBE, "cube.gltf", ["--fov", "45", "--width", "800", "--height", "600",
                         "--tessellation", "12"],
     {"fov": 45, "width": 800, "height": 600, "tessellation": 12}),
    (ALL, "all.glb", [], {}),
    (ALL, "all-for-assimp.gltf", ["--no-lights", "--no-extras", "--light-falloff", "none"],
     {"no_lights": True, "no_extras": True, "light_falloff": "none"}),
    (ALL, "all.pov", ["--flat", "--width", "320"], {"flat": True, "width": 320}),
    (SHEAR, "shear.txt", ["--approximate"], {"approximate": True}),
    (GLTF, "torus.sf", [], {}),
    (POV, "wide.txt", ["--width", "300", "--height", "100"], {"width": 300, "height": 100}),
    (CUBE, "cube.sf", ["--to", "sf"], {"format": "sf"}),
]


def same_but_generator(ours, theirs):
    """The two files are the same but for glTF's asset.generator, which names
    the program that wrote it (in a .glb, the JSON chunk, padded to 4 bytes)."""
    def parts(data, generator):
        if data[:4] == b"glTF":
            size = struct.unpack_from("<I", data, 12)[0]
            return [data[20:20 + size].rstrip(b" ").replace(generator, b"G"), data[20 + size:]]
        return [data.replace(generator, b"G")]

    version = scenefile.__version__
    return parts(ours, f"scenefile {version} (Python)".encode()) == parts(
        theirs, f"sfconvert {version}".encode())


def test_a_hint_names_the_keyword_that_cures_it(tmp_path):
    # Where sfconvert says '--approximate', Python says its keyword.
    with pytest.raises(scenefile.SceneError) as caught:
        scenefile.convert(SHEAR, tmp_path / "shear.txt")
    hints = {d.hint for d in caught.value.errors}
    assert "'approximate=True' writes the nearest rotation and scale" in hints, hints
    assert not (tmp_path / "shear.txt").exists()


def test_losses_name_the_file_read_else_the_file_written(tmp_path):
    read = scenefile.read(CUBE)
    assert all(d.file == CUBE for d in scenefile.write(read, tmp_path / "a.sf"))
    built = scenefile.Scene(read.camera, read.lights, read.objects)
    target = str(tmp_path / "b.sf")
    losses = scenefile.write(built, target)
    assert losses and all(str(d).startswith(target + ":") for d in losses), losses


def sfconvert_losses(sfconvert, source, target, flags):
    result = run(sfconvert, source, target, *flags, "--format", "json", "--quiet", check=False)
    return result.returncode, [(d["code"], d["line"], d["message"])
                               for d in json.loads(result.stderr or b"[]")]


@pytest.mark.parametrize("source, name, flags, options", CONVERSIONS, ids=lambda c: str(c)[:20])
def test_convert_is_sfconvert(sfconvert, tmp_path, source, name, flags, options):
    theirs, ours = tmp_path / "theirs", tmp_path / "ours"
    theirs.mkdir()
    ours.mkdir()
    status, their_losses = sfconvert_losses(sfconvert, source, theirs / name, flags)
    assert status == 0
    losses = scenefile.convert(source, ours / name, **options)
    assert same_but_generator((ours / name).read_bytes(), (theirs / name).read_bytes())
    assert [(d.code, d.line, d.message) for d in losses] == their_losses


def test_a_gltf_buffer_beside_the_file(sfconvert, tmp_path):
    run(sfconvert, ALL, tmp_path / "theirs.gltf", "--external-buffers", "--quiet")
    scenefile.convert(ALL, tmp_path / "ours.gltf", external_buffers=True)
    assert (tmp_path / "ours.bin").read_bytes() == (tmp_path / "theirs.bin").read_bytes()
    assert same_but_generator((tmp_path / "ours.gltf").read_bytes(),
                              (tmp_path / "theirs.gltf").read_bytes().replace(b"theirs.bin",
                                                                            b"ours.bin"))
    with pytest.raises(ValueError, match="external_buffers"):
        scenefile.convert(ALL, tmp_path / "x.glb", external_buffers=True)


@pytest.mark.parametrize("flags, options", [([], {}), (["--tessellation", "7"],
                                                      {"tessellation": 7})])
def test_an_obj_and_its_mtl_are_sfconverts(sfconvert, tmp_path, flags, options):
    theirs, ours = tmp_path / "theirs", tmp_path / "ours"
    theirs.mkdir()
    ours.mkdir()
    status, their_losses = sfconvert_losses(sfconvert, ALL, theirs / "all.obj", flags)
    assert status == 0
    losses = scenefile.convert(ALL, ours / "all.obj", **options)
    assert sorted(os.listdir(ours)) == ["all.mtl", "all.obj"]
    for name in ["all.obj", "all.mtl"]:
        assert (ours / name).read_bytes() == (theirs / name).read_bytes(), name
    assert [(d.code, d.line, d.message) for d in losses] == their_losses
    scenefile.write(scenefile.read(ALL), tmp_path / "written.obj", **options)
    assert (tmp_path / "written.obj").read_bytes() == (theirs / "all.obj").read_bytes().replace(
        b"mtllib all.mtl", b"mtllib written.mtl")
    assert (tmp_path / "written.mtl").read_bytes() == (theirs / "all.mtl").read_bytes()


def test_no_loss_writes_nothing(sfconvert, tmp_path):
    target = tmp_path / "cube.sf"
    target.write_text("before\n")
    status, _ = sfconvert_losses(sfconvert, CUBE, tmp_path / "theirs.sf", ["--no-loss"])
    assert status == 1
    with pytest.raises(scenefile.SceneError) as caught:
        scenefile.convert(CUBE, target, no_loss=True)
    assert caught.value.errors[0].code == "loss-material"
    with pytest.raises(scenefile.SceneError):
        scenefile.write(scenefile.read(CUBE), target, no_loss=True)
    assert target.read_text() == "before\n"
    assert sorted(os.listdir(tmp_path)) == ["cube.sf"], "no temporary left behind"


def test_convert_never_writes_over_its_input(tmp_path):
    copy = tmp_path / "cube.txt"
    copy.write_bytes(open(CUBE, "rb").read())
    with pytest.raises(ValueError, match="is the input file"):
        scenefile.convert(copy, copy)
    os.link(copy, tmp_path / "link.txt")
    with pytest.raises(ValueError, match="is the input file"):
        scenefile.convert(copy, tmp_path / "link.txt")


def test_the_format_comes_from_the_extension_or_is_named(tmp_path):
    scene = scenefile.read(ALL)
    with pytest.raises(ValueError, match="cannot tell the format"):
        scenefile.write(scene, tmp_path / "scene.dat")
    scenefile.write(scene, tmp_path / "scene.dat", format="sf")
    assert scenefile.read(tmp_path / "scene.dat") == scene
    names = [row["name"] for row in scenefile.formats()]
    assert names == ["sf", "instructions", "gltf", "glb", "pov", "obj"]
    for row in scenefile.formats():
        path = tmp_path / ("every" + row["extensions"][0])
        scenefile.write(scene, path)
        assert path.stat().st_size > 0
        back = scenefile.read(path)
        assert len(back.objects) == len(scene.objects), row["name"]
    with pytest.raises(TypeError, match="did you mean 'tessellation'"):
        scenefile.write(scene, tmp_path / "x.gltf", tesselation=8)
    with pytest.raises(ValueError, match="between 3 and 1024"):
        scenefile.write(scene, tmp_path / "x.gltf", tessellation=2)
    with pytest.raises(ValueError, match="light_falloff must be 'inverse-square' or 'none'"):
        scenefile.write(scene, tmp_path / "x.gltf", light_falloff="linear")
    assert not (tmp_path / "x.gltf").exists()


def test_files_get_the_mode_umask_leaves(tmp_path):
    old = os.umask(0o027)
    try:
        scenefile.write(scenefile.read(ALL), tmp_path / "scene.sf")
    finally:
        os.umask(old)
    assert stat.S_IMODE((tmp_path / "scene.sf").stat().st_mode) == 0o640


def test_an_invalid_scene_is_not_written(tmp_path):
    scene = scenefile.read(ALL)
    scene.objects[0].colour = (-1, 0, 0)
    with pytest.raises(scenefile.SceneError, match="negative-colour"):
        scenefile.write(scene, tmp_path / "bad.sf")
    assert os.listdir(tmp_path) == []
