"""What write() and convert() do to the files they are given, as the tools do
(docs/SECURITY.md, "What each tool writes"): a folder, a device or a pipe is
refused, a link is followed and kept, the permissions of a replaced file
stay, a set of files is written whole or not at all, and convert() never
writes over its input, by file identity."""

import os
import stat

import pytest

import scenefile
from conftest import TESTDATA

ALL = os.path.join(TESTDATA, "valid", "all-primitives.sf")


@pytest.fixture
def scene():
    return scenefile.read(ALL)


def entries(folder):
    return sorted(os.listdir(folder))


def test_a_pipe_is_refused_and_stays_a_pipe(scene, tmp_path):
    os.mkfifo(tmp_path / "pipe.sf")
    with pytest.raises(OSError, match="pipe.sf.*it is a pipe, not a regular file"):
        scenefile.write(scene, tmp_path / "pipe.sf")
    assert stat.S_ISFIFO(os.lstat(tmp_path / "pipe.sf").st_mode)
    assert entries(tmp_path) == ["pipe.sf"], "no temporary left behind"


def test_a_device_is_refused_through_a_link_and_the_link_stays(scene, tmp_path):
    os.symlink("/dev/null", tmp_path / "dev.sf")
    with pytest.raises(OSError, match="it is a character device, not a regular file"):
        scenefile.write(scene, tmp_path / "dev.sf")
    assert os.readlink(tmp_path / "dev.sf") == "/dev/null"
    try:
        os.mknod(tmp_path / "made.sf", 0o600 | stat.S_IFCHR, os.makedev(1, 3))
    except PermissionError:
        return  # no CAP_MKNOD: the link above stands for the device
    with pytest.raises(OSError, match="character device"):
        scenefile.write(scene, tmp_path / "made.sf")
    assert stat.S_ISCHR(os.lstat(tmp_path / "made.sf").st_mode)


def test_a_folder_is_refused(scene, tmp_path):
    (tmp_path / "folder.sf").mkdir()
    with pytest.raises(OSError, match="it is a directory"):
        scenefile.write(scene, tmp_path / "folder.sf")
    assert entries(tmp_path) == ["folder.sf"]


def test_a_link_is_followed_its_target_replaced_and_the_link_kept(scene, tmp_path):
    (tmp_path / "real").mkdir()
    (tmp_path / "real" / "scene.sf").write_text("old\n")
    os.symlink("real/scene.sf", tmp_path / "link.sf")
    scenefile.write(scene, tmp_path / "link.sf")
    assert os.readlink(tmp_path / "link.sf") == "real/scene.sf"
    assert scenefile.read(tmp_path / "real" / "scene.sf") == scene
    # A link to nothing yet: the file is made where it leads.
    os.symlink("real/new.sf", tmp_path / "dangling.sf")
    scenefile.write(scene, tmp_path / "dangling.sf")
    assert os.path.islink(tmp_path / "dangling.sf")
    assert scenefile.read(tmp_path / "real" / "new.sf") == scene
    assert entries(tmp_path / "real") == ["new.sf", "scene.sf"]


def test_a_replaced_file_keeps_its_permissions(scene, tmp_path):
    target = tmp_path / "private.sf"
    target.write_text("old\n")
    os.chmod(target, 0o600)
    scenefile.write(scene, target)
    assert stat.S_IMODE(target.stat().st_mode) == 0o600
    os.chmod(target, 0o664)
    scenefile.convert(ALL, target)
    assert stat.S_IMODE(target.stat().st_mode) == 0o664


def test_a_gltf_and_its_buffer_are_written_both_or_neither(scene, tmp_path):
    (tmp_path / "out.gltf").mkdir()
    with pytest.raises(OSError, match="out.gltf.*it is a directory"):
        scenefile.write(scene, tmp_path / "out.gltf", external_buffers=True)
    assert entries(tmp_path) == ["out.gltf"], "the buffer was not written either"
    with pytest.raises(OSError, match="does not exist"):
        scenefile.write(scene, tmp_path / "no" / "such.sf")
    assert entries(tmp_path) == ["out.gltf"]


def test_an_obj_and_its_mtl_are_written_both_or_neither(scene, tmp_path):
    (tmp_path / "out.obj").mkdir()
    with pytest.raises(OSError, match="out.obj.*it is a directory"):
        scenefile.write(scene, tmp_path / "out.obj")
    assert entries(tmp_path) == ["out.obj"], "the MTL file was not written either"


def test_an_obj_through_a_link_has_its_mtl_beside_the_file_it_leads_to(scene, tmp_path):
    (tmp_path / "real").mkdir()
    os.symlink("real/scene.obj", tmp_path / "link.obj")
    scenefile.write(scene, tmp_path / "link.obj")
    assert entries(tmp_path / "real") == ["scene.mtl", "scene.obj"]
    assert b"\nmtllib scene.mtl\n" in (tmp_path / "real" / "scene.obj").read_bytes()


def test_an_obj_named_mtl_and_an_mtl_over_the_input_are_refused(tmp_path):
    with pytest.raises(ValueError, match="the MTL file .* is the output itself; name the "
                                         "output NAME.obj"):
        scenefile.convert(ALL, tmp_path / "scene.mtl", format="obj")
    source = copy_of(ALL, tmp_path / "scene.mtl")
    with pytest.raises(ValueError, match="scene.mtl.*input"):
        scenefile.convert(source, tmp_path / "scene.obj")
    assert entries(tmp_path) == ["scene.mtl"], "nothing written"


def test_write_may_replace_the_file_the_scene_came_from(tmp_path):
    path = tmp_path / "scene.sf"
    path.write_bytes(open(ALL, "rb").read())
    scene = scenefile.read(path)
    scene.objects.pop()
    scenefile.write(scene, path)
    assert scenefile.read(path) == scene


def copy_of(source, path):
    path.write_bytes(open(source, "rb").read())
    return path


def test_convert_never_writes_a_buffer_over_its_input(tmp_path):
    source = copy_of(ALL, tmp_path / "scene.bin")
    before = source.read_bytes()
    with pytest.raises(ValueError, match="scene.bin.*input"):
        scenefile.convert(source, tmp_path / "scene.gltf", external_buffers=True)
    assert source.read_bytes() == before
    assert entries(tmp_path) == ["scene.bin"], "nothing written"


@pytest.mark.parametrize("how", ["symlink", "hard link", "dot spelling"])
def test_convert_knows_its_input_by_identity_not_by_name(tmp_path, how):
    (tmp_path / "in").mkdir()
    source = copy_of(ALL, tmp_path / "in" / "scene.sf")
    before = source.read_bytes()
    if how == "symlink":
        os.symlink(source, tmp_path / "out.bin")
        output = tmp_path / "out.gltf"
    elif how == "hard link":
        os.link(source, tmp_path / "out.bin")
        output = tmp_path / "out.gltf"
    else:
        output = os.path.join(str(tmp_path), ".", "in", "..", "in", "scene.sf")
    with pytest.raises(ValueError, match="input"):
        scenefile.convert(source, output, external_buffers=how != "dot spelling")
    assert source.read_bytes() == before
    assert not (tmp_path / "out.gltf").exists()


def test_a_gltf_named_bin_with_its_buffer_is_refused(tmp_path):
    with pytest.raises(ValueError, match="buffer"):
        scenefile.convert(ALL, tmp_path / "scene.bin", format="gltf", external_buffers=True)
    assert entries(tmp_path) == []


@pytest.mark.parametrize("length", [241, 250, 255])
def test_a_long_legal_name_is_written(scene, tmp_path, length):
    name = "n" * (length - 3) + ".sf"
    scenefile.write(scene, tmp_path / name)
    assert scenefile.read(tmp_path / name) == scene
    assert entries(tmp_path) == [name]


def test_a_buffer_that_is_the_gltf_itself_by_a_link_is_refused(scene, tmp_path):
    # Neither file is there yet: the tools' identity check knows a file not
    # there by its folder and name, through the link.
    os.symlink("out.gltf", tmp_path / "out.bin")
    with pytest.raises(ValueError, match="its buffer.*same file"):
        scenefile.write(scene, tmp_path / "out.gltf", external_buffers=True)
    assert entries(tmp_path) == ["out.bin"]
