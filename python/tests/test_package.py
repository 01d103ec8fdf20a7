"""The package as its users see it: what it exports, its stubs, its documents."""

import ast
import inspect
import os

import scenefile
from scenefile import _core


def stub_names(path):
    tree = ast.parse(open(path).read())
    names = set()
    for node in tree.body:
        if isinstance(node, ast.FunctionDef):
            names.add(node.name)
        elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name):
            names.add(node.target.id)
    return names


def test_the_stub_of_the_extension_is_what_it_has():
    folder = os.path.dirname(scenefile.__file__)
    declared = stub_names(os.path.join(folder, "_core.pyi")) - {"SceneData", "DiagnosticData",
                                                                "Matrix"}
    present = {name for name in dir(_core) if not name.startswith("_") or name == "__version__"}
    assert declared == present
    assert os.path.exists(os.path.join(folder, "py.typed")), "PEP 561: the package is typed"


def test_every_name_exported_is_there_and_documented():
    for name in scenefile.__all__:
        value = getattr(scenefile, name)
        if inspect.isfunction(value) or inspect.isclass(value):
            assert value.__doc__, f"{name} has no docstring"
            if inspect.isfunction(value):
                hints = value.__annotations__
                assert "return" in hints, f"{name} has no return annotation"
    assert scenefile.__version__.count(".") == 2


def test_the_public_interfaces_keep_their_names():
    # Scripts call these: their names and parameters are a promise.
    assert list(inspect.signature(scenefile.read).parameters) == ["path", "format", "limits"]
    assert list(inspect.signature(scenefile.check).parameters)[0] == "path"
    assert list(inspect.signature(scenefile.write).parameters)[:4] == ["scene", "path", "format",
                                                                      "no_loss"]
    assert list(inspect.signature(scenefile.convert).parameters)[:2] == ["src", "dst"]
    render = inspect.signature(scenefile.render).parameters
    assert list(render)[:7] == ["scene", "width", "height", "spp", "depth", "fov", "threads"]
    assert (render["width"].default, render["height"].default, render["spp"].default,
            render["depth"].default, render["fov"].default,
            render["threads"].default) == (640, 480, 1, 5, 60, 0)
    assert issubclass(scenefile.SceneError, Exception)
    assert {k.value for k in scenefile.ObjectKind} == {"SPHERE", "CUBE", "CYLINDER", "PLANE"}
    diagnostic = scenefile.check(__file__)[0]
    for field in ("severity", "code", "file", "line", "column", "message", "hint", "remedies"):
        assert hasattr(diagnostic, field)
