"""What the tests of the scenefile package share: the tools to compare with
(SFCHECK, SFCONVERT, SFRENDER from ctest's environment) and the corpus."""

import glob
import os
import shutil
import subprocess

import pytest

SOURCE = os.environ.get("SCENEFILE_SOURCE_DIR",
                        os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))
TESTDATA = os.path.join(SOURCE, "testdata")
EXAMPLES = os.path.join(SOURCE, "examples")


def tool(name):
    """The path of a tool of the build, from the environment ctest sets."""
    path = os.environ.get(name.upper()) or shutil.which(name)
    if not path:
        pytest.skip(f"{name} is not known (set {name.upper()})")
    return path


def run(*args, check=True):
    """A tool's run, its output captured as bytes."""
    result = subprocess.run([str(a) for a in args], capture_output=True)
    if check and result.returncode != 0:
        raise AssertionError(f"{args} exited {result.returncode}: {result.stderr.decode()}")
    return result


def corpus(*patterns):
    """The corpus files matching the patterns under testdata/, sorted."""
    files = []
    for pattern in patterns:
        files += glob.glob(os.path.join(TESTDATA, pattern))
    return sorted(f for f in files if not f.endswith(".expect") and os.path.isfile(f))


@pytest.fixture
def sfcheck():
    return tool("sfcheck")


@pytest.fixture
def sfconvert():
    return tool("sfconvert")


@pytest.fixture
def sfrender():
    return tool("sfrender")
