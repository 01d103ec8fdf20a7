"""scenefile.read, loads and check against the tools: the same scenes, the
same diagnostics, the same first error."""

import json
import os
import threading

import pytest

import scenefile
from conftest import EXAMPLES, TESTDATA, corpus, run

# Files every reader takes, in every format: read here and by sfconvert.
READABLE = corpus("valid/*.sf", "valid/*.txt", "gltf/*.gltf", "pov/valid/*.pov",
                  "pov/export/*", "view/*") + [
    os.path.join(EXAMPLES, "red-sphere.sf"), os.path.join(EXAMPLES, "blue-cube.txt")]
# Every file of the corpus, valid or not, for the diagnostics.
CHECKED = corpus("valid/*", "invalid/*", "gltf/*.gltf", "gltf-hostile/*.gltf",
                 "gltf-hostile/*.glb", "pov/*/*.pov")
# sfcheck's own policy about OUTPUT_FILE (tools/common), not the library's.
TOOL_POLICY = ("output-file-escapes", "output-file-format", "output-file-link-loop")


# The tools' flags for the settings a hint names, and the tool said once
# before those that are another tool's (tools/common/diagnostic_printer.cpp).
TOOL_FLAGS = {"max-file-size": ("", "--max-file-size", False),
              "max-objects": ("", "--max-objects", False),
              "max-gltf-nodes": ("", "--max-nodes", False),
              "transposed-matrices": ("sfconvert", "--transpose-matrices", False),
              "skip-unsupported": ("", "--skip-unsupported", False),
              "approximate": ("", "--approximate", False),
              "field-of-view": ("sfrender", "--fov", True),
              "width": ("sfrender", "--width", True), "height": ("sfrender", "--height", True),
              "depth": ("", "--depth", True), "output-path": ("sfrender", "-o", True)}


def as_the_tools_say(d):
    """The hint with each remedy said as the tools' flag."""
    said = set()

    def flag(remedy):
        tool, name, shows_value = TOOL_FLAGS[remedy.setting]
        words = f"{tool} {name}" if tool and tool not in said else name
        said.add(tool)
        return words + (f" {remedy.value}" if shows_value and remedy.value else "")
    return d.hint_in(flag)


def shown(d):
    """A diagnostic as the comparison sees it: every field sfcheck's JSON has."""
    notes = [(n.line, n.column, n.length, n.message) for n in d.notes]
    return (d.file, d.severity.value, d.code, d.line, d.column, d.length, d.message,
            as_the_tools_say(d), notes)


def shown_json(d):
    notes = [(n["line"], n["column"], n["length"], n["message"]) for n in d.get("notes", [])]
    return (d["file"], d["severity"], d["code"], d["line"], d["column"], d["length"],
            d["message"], d.get("hint", ""), notes)


def test_check_gives_what_sfcheck_gives_on_the_whole_corpus(sfcheck):
    assert len(CHECKED) > 200
    report = json.loads(run(sfcheck, "--format", "json", *CHECKED, check=False).stdout)
    assert len(report["files"]) == len(CHECKED)
    compared = 0
    for path, entry in zip(CHECKED, report["files"]):
        assert entry["file"] == path
        want = [shown_json(d) for d in entry["diagnostics"] if d["code"] not in TOOL_POLICY]
        got = [shown(d) for d in scenefile.check(path)]
        # sfcheck shows bytes that are no printable text as escapes of its own.
        if any("\\x" in g[6] or "\\x" in g[7] for g in got):
            got_codes = [(g[2], g[3], g[4]) for g in got]
            assert got_codes == [(w[2], w[3], w[4]) for w in want], path
            continue
        assert got == want, path
        compared += 1
    assert compared > 200


@pytest.mark.parametrize("path", READABLE, ids=os.path.basename)
def test_read_then_write_is_sfconvert(sfconvert, tmp_path, path):
    # The scene read here and written by the library's writers: byte for byte
    # what sfconvert makes of the file, in both line formats, or refused by
    # both (an instruction file cannot hold shear).
    for extension in (".sf", ".txt"):
        theirs = tmp_path / ("theirs" + extension)
        ours = tmp_path / ("ours" + extension)
        status = run(sfconvert, path, theirs, "--quiet", check=False).returncode
        scene = scenefile.read(path)
        if status == 0:
            scenefile.write(scene, ours)
            assert ours.read_bytes() == theirs.read_bytes().replace(b"theirs.ppm", b"ours.ppm")
        else:
            with pytest.raises(scenefile.SceneError):
                scenefile.write(scene, ours)
            assert not ours.exists()


def test_the_first_error_is_the_tools(sfcheck):
    invalid = corpus("invalid/*.sf", "invalid/*.txt")
    assert len(invalid) > 100
    for path in invalid:
        short = run(sfcheck, "--format", "short", path, check=False).stderr.decode()
        errors = [line for line in short.splitlines() if ": error: " in line]
        with pytest.raises(scenefile.SceneError) as caught:
            scenefile.read(path)
        if "\\x" in str(caught.value):
            continue
        assert str(caught.value).split(" (and ")[0] == errors[0], path
        assert len(caught.value.errors) == len(errors)
        assert isinstance(caught.value, Exception)


def test_what_the_reader_notes_stays_on_the_scene():
    scene = scenefile.read(os.path.join(TESTDATA, "valid", "camera-only.txt"))
    assert [d.code for d in scene.warnings] == ["no-light"]
    assert scene.diagnostics[0].severity == scenefile.Severity.WARNING
    assert str(scene.diagnostics[0]).endswith(
        "camera-only.txt:2:1: warning: scene has no LIGHT [no-light]")
    assert scene.format == "instructions"
    assert scene.source.endswith("camera-only.txt")


def test_a_file_that_cannot_be_read_raises_oserror(tmp_path):
    with pytest.raises(FileNotFoundError):
        scenefile.read(tmp_path / "missing.sf")
    with pytest.raises(IsADirectoryError):
        scenefile.read(tmp_path)
    with pytest.raises(FileNotFoundError):
        scenefile.check(str(tmp_path / "missing.sf"))


def test_an_unreadable_file_is_oserror_in_pythons_words(tmp_path):
    missing = str(tmp_path / "missing.sf")
    with pytest.raises(FileNotFoundError) as caught:
        scenefile.read(missing)
    assert str(caught.value) == f"[Errno 2] No such file or directory: {missing!r}"
    assert caught.value.filename == missing
    with pytest.raises(IsADirectoryError, match=r"^\[Errno 21\] Is a directory: "):
        scenefile.check(tmp_path)


def fed_pipe(path, data):
    """A pipe at ``path`` that a thread writes ``data`` into once it is opened."""
    os.mkfifo(path)

    def feed():
        with open(path, "wb") as pipe:
            try:
                pipe.write(data)
            except BrokenPipeError:
                pass

    threading.Thread(target=feed, daemon=True).start()
    return path


def test_a_pipe_is_read_as_the_tools_read_it(tmp_path):
    # Its size unknown until read: more than the limit is refused, not cut.
    path = os.path.join(TESTDATA, "valid", "all-primitives.sf")
    data = open(path, "rb").read()
    with pytest.raises(scenefile.SceneError) as caught:
        scenefile.read(fed_pipe(tmp_path / "big.sf", data), max_file_size=10)
    assert [d.code for d in caught.value.errors] == ["file-too-large"]
    assert caught.value.errors[0].message == "the input is more than the limit of 10 bytes"
    assert scenefile.check(fed_pipe(tmp_path / "c.sf", data), max_file_size=10)[0].code == (
        "file-too-large")
    assert scenefile.read(fed_pipe(tmp_path / "whole.sf", data)) == scenefile.read(path)


def test_max_vertices_holds_obj_too():
    path = os.path.join(TESTDATA, "obj", "blender-cube.obj")
    with pytest.raises(scenefile.SceneError) as caught:
        scenefile.read(path, max_vertices=3)
    assert caught.value.errors[0].code == "obj-too-large"
    assert len(scenefile.read(path).objects) == 1


def test_limits_are_the_tools(tmp_path):
    path = os.path.join(TESTDATA, "valid", "all-primitives.sf")
    with pytest.raises(scenefile.SceneError) as caught:
        scenefile.read(path, max_file_size=10)
    assert caught.value.errors[0].code == "file-too-large"
    assert scenefile.check(path, max_file_size=10)[0].code == "file-too-large"
    # Told in Python's words: the keyword, and the size that would do.
    size = os.path.getsize(path)
    assert caught.value.errors[0].hint == (f"raise the limit with max_file_size={size} if the "
                                           "file is meant to be this large")
    assert caught.value.errors[0].remedies == [scenefile.Remedy("max-file-size", str(size))]
    with pytest.raises(scenefile.SceneError) as caught:
        scenefile.read(path, max_objects=2)
    assert caught.value.errors[0].code == "too-many-objects"
    assert len(scenefile.read(path, max_objects=1000).objects) > 2


def test_skip_unsupported_is_sfconverts_flag(tmp_path):
    path = tmp_path / "tutorial.pov"
    path.write_text("camera { location <0, 1, -5> look_at 0 }\n"
                    "light_source { <0, 5, -5> color rgb 1 }\n"
                    "torus { 1, 0.25 }\nsphere { 0, 1 pigment { rgb <1, 0, 0> } }\n")
    with pytest.raises(scenefile.SceneError) as caught:
        scenefile.read(path)
    error = caught.value.errors[0]
    assert error.code == "pov-unsupported"
    assert error.hint == "skip_unsupported=True converts the rest"
    assert str(error).startswith(f"{path}:3:1: error: 'torus' is not supported")
    scene = scenefile.read(path, skip_unsupported=True)
    assert [o.kind.value for o in scene.objects] == ["SPHERE"]
    assert [d.code for d in scene.warnings] == ["pov-unsupported"]
    assert scenefile.check(path, skip_unsupported=True)[0].severity == scenefile.Severity.WARNING
    image = scenefile.render(scene, width=8, height=6, fov=None)
    assert image.shape == (6, 8, 3) and image.max() > 0


def test_keyword_arguments_are_checked_as_flags_are():
    path = os.path.join(TESTDATA, "valid", "all-primitives.sf")
    with pytest.raises(TypeError, match="'max_objcts'; did you mean 'max_objects'"):
        scenefile.read(path, max_objcts=3)
    with pytest.raises(TypeError, match="whole number"):
        scenefile.read(path, max_objects=2.5)
    with pytest.raises(ValueError, match="between 1 and"):
        scenefile.read(path, max_objects=0)
    with pytest.raises(TypeError, match="True or False"):
        scenefile.read(path, no_loss="yes")


def test_a_format_can_be_named():
    sf = os.path.join(TESTDATA, "valid", "all-primitives.sf")
    assert scenefile.read(sf, format="SF") == scenefile.read(sf)
    with pytest.raises(scenefile.SceneError):
        scenefile.read(sf, format="instructions")
    with pytest.raises(ValueError, match="did you mean 'gltf'"):
        scenefile.read(sf, format="gltff")


def test_loads_reads_text():
    with open(os.path.join(EXAMPLES, "red-sphere.sf")) as f:
        text = f.read()
    scene = scenefile.loads(text, name="red.sf")
    assert scene == scenefile.read(os.path.join(EXAMPLES, "red-sphere.sf"))
    with pytest.raises(scenefile.SceneError, match=r"^bad\.sf:1:1: error: "):
        scenefile.loads("sphere\n", name="bad.sf")


def test_an_output_file_an_instruction_file_cannot_hold_is_refused(tmp_path):
    # Files are ASCII, so a name read is always one; a name set in Python
    # may be anything, and the instruction writer would write it as it is.
    scene = scenefile.read(os.path.join(EXAMPLES, "blue-cube.txt"))
    for name in ("caf\u00e9.ppm", "a b.ppm", "", "x\nSTART CAMERA"):
        scene.output_file = name
        with pytest.raises(scenefile.SceneError) as caught:
            scenefile.write(scene, tmp_path / "out.txt")
        assert caught.value.errors[0].code == "output-file-name"
    assert not (tmp_path / "out.txt").exists()
    with pytest.raises(scenefile.SceneError, match="invalid-byte"):
        scenefile.loads(b"OUTPUT_FILE caf\xe9.ppm\n")
