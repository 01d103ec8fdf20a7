"""Finding the scenefile Python module, which does the reading and writing.

Installed under the prefix /usr or /usr/local, the module is on Blender's
sys.path already (lib/python3.X/dist-packages). Elsewhere it is looked for
in the folders the build or `cmake --install` wrote into _site.py (absolute,
and relative to this add-on's folder, for a prefix that was moved), then in
the folder set in the add-on's preferences. Loaded on first use, so that
the add-on registers (and its menu entries show) even without it.
"""

import importlib
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))


def _site_folders():
    try:
        from . import _site  # written by the build and by cmake --install
    except ImportError:
        return []
    folders = list(getattr(_site, "MODULE_FOLDERS", []))
    folders += [os.path.normpath(os.path.join(HERE, f))
                for f in getattr(_site, "RELATIVE_MODULE_FOLDERS", [])]
    return folders


def search_folders(preference=""):
    """Where scenefile is looked for when it is not on sys.path, in order."""
    folders = _site_folders()
    if preference:
        folders.append(bpy_path(preference))
    return [f for f in folders if f]


def bpy_path(path):
    try:
        import bpy
        return bpy.path.abspath(path)
    except ImportError:
        return path


def load(preference=""):
    """The scenefile module; ImportError saying where it was looked for."""
    try:
        return importlib.import_module("scenefile")
    except ImportError as first:
        failure = first
    for folder in search_folders(preference):
        if os.path.isfile(os.path.join(folder, "scenefile", "__init__.py")):
            if folder not in sys.path:
                sys.path.append(folder)
            try:
                return importlib.import_module("scenefile")
            except ImportError as error:
                failure = error
    looked = ", ".join(search_folders(preference)) or "nowhere else"
    raise ImportError(f"the scenefile Python module cannot be imported ({failure}); looked on "
                      f"sys.path and in {looked}: install scenefile (cmake --install), or name "
                      f"the folder that holds it in the add-on's preferences")
