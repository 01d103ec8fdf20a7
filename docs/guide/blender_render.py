"""Renders a glTF file with Blender's own glTF importer and Cycles, headless:

    blender -b --factory-startup --python blender_render.py -- IN.gltf OUT.png WIDTH HEIGHT

The settings are those of tests/gltf/blender_brightness_check.py (the
Standard view transform, a black world: no light but the file's), so that
the picture is the one GLTF.md's brightness figures speak of."""

import sys

import numpy

# Debian 12's Blender 3.4 says numpy.bool in its glTF code, which numpy 1.24
# removed; the builtin is what it means. Set before the importer loads.
numpy.bool = bool

import bpy  # noqa: E402

source, png, width, height = sys.argv[sys.argv.index("--") + 1:]
bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.import_scene.gltf(filepath=source)
scene = bpy.context.scene
scene.camera = next(o for o in scene.objects if o.type == "CAMERA")
scene.render.engine = "CYCLES"
scene.cycles.device = "CPU"
scene.cycles.samples = 64
scene.cycles.use_denoising = False
scene.cycles.seed = 0
scene.render.resolution_x = int(width)
scene.render.resolution_y = int(height)
scene.render.resolution_percentage = 100
scene.render.film_transparent = False
scene.render.dither_intensity = 0.0
scene.view_settings.view_transform = "Standard"
scene.view_settings.look = "None"
world = bpy.data.worlds.new("black")
world.use_nodes = True
world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.0
scene.world = world
scene.render.image_settings.file_format = "PNG"
scene.render.image_settings.color_mode = "RGB"
scene.render.image_settings.color_depth = "8"
scene.render.filepath = png
bpy.ops.render.render(write_still=True)
