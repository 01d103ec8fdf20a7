"""The package's annotations and stubs, as an editor or mypy sees them:
mypy --strict accepts the package, the examples type-check, and a wrong call
is caught. Skipped where mypy is not installed (Debian's mypy)."""

import glob
import os
import subprocess
import sys

import pytest

import scenefile
from conftest import EXAMPLES

pytest.importorskip("mypy")
PACKAGE_ROOT = os.path.dirname(os.path.dirname(scenefile.__file__))


def mypy(tmp_path, *args):
    result = subprocess.run(
        [sys.executable, "-m", "mypy", "--cache-dir", os.path.join(PACKAGE_ROOT, ".mypy_cache"),
         "--no-error-summary", *args],
        capture_output=True, text=True, env=dict(os.environ, MYPYPATH=PACKAGE_ROOT),
        cwd=tmp_path)
    return result.returncode, result.stdout + result.stderr


def test_the_package_and_the_examples_type_check(tmp_path):
    examples = glob.glob(os.path.join(EXAMPLES, "python", "*.py"))
    assert len(examples) >= 3
    status, out = mypy(tmp_path, "--strict", os.path.join(PACKAGE_ROOT, "scenefile"), *examples)
    assert status == 0, out


def test_a_wrong_call_is_caught(tmp_path):
    (tmp_path / "wrong.py").write_text(
        "import scenefile\n"
        "scene: scenefile.Scene = scenefile.read('a.sf')\n"
        "kind: scenefile.ObjectKind = scene.objects[0].kind\n"
        "image = scenefile.render(scene, width='64')\n"
        "scene.objects[0].material.ri = 'glass'\n")
    status, out = mypy(tmp_path, "--strict", "wrong.py")
    assert status == 1
    assert 'wrong.py:4: error: Argument "width" to "render" has incompatible type "str"' in out
    assert "wrong.py:5: error: Incompatible types in assignment" in out
