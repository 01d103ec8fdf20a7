"""What the add-on's Blender checks share: the add-on of the build, loaded
as Blender loads an add-on, and its scenefile module."""

import os
import sys

import numpy

# Debian 12's Blender 3.4 says numpy.bool in its glTF code, which numpy 1.24
# removed; the builtin is what it means. Set before anything imports it.
numpy.bool = bool

import bpy  # noqa: E402


def arguments():
    return sys.argv[sys.argv.index("--") + 1:]


def load_addon(addons_dir):
    """Registers io_scene_sf from the build's add-ons folder; returns the
    add-on and the scenefile module it found through its _site.py."""
    sys.path.insert(0, addons_dir)
    import io_scene_sf
    io_scene_sf.register()
    return io_scene_sf, io_scene_sf._module.load()


def fresh():
    bpy.ops.wm.read_factory_settings(use_empty=True)


class Failures:
    def __init__(self):
        self.items = []

    def check(self, condition, message):
        if not condition:
            self.items.append(message)
            print("FAIL:", message)

    def finish(self, what):
        if self.items:
            sys.exit(f"FAIL: {len(self.items)} checks of {what}")
        print(f"PASS: {what}")


def operator(call, **kwargs):
    """An operator's result, or the error it reported ({'CANCELLED'} then)."""
    try:
        return call(**kwargs), ""
    except RuntimeError as error:
        return {"CANCELLED"}, str(error)


def same_folder_name(work, kind, name):
    folder = os.path.join(work, kind)
    os.makedirs(folder, exist_ok=True)
    return os.path.join(folder, name)
