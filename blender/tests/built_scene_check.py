# A scene built with bpy, as a Blender user makes one (Blender's own
# primitives, moved, turned and scaled, a point light, a camera), exported
# by the add-on: sfcheck accepts both formats, the mesh that is no primitive
# is reported and skipped, and sfrender draws the objects where Blender
# does: each pixel shows the same object in sfrender's flat picture as in
# Cycles' (objects in flat colours, one sample at each pixel's centre), but
# for a few along the silhouettes.
#
# blender -b --factory-startup --python-exit-code 1 --python THIS -- ADDONS WORK SFCHECK SFRENDER
import math
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402  (sets numpy.bool before Blender's glTF code runs)

import bpy  # noqa: E402
import numpy as np  # noqa: E402
from mathutils import Vector  # noqa: E402

addons, work, sfcheck, sfrender = common.arguments()
addon, scenefile = common.load_addon(addons)
from io_scene_sf import exporter  # noqa: E402

os.makedirs(work, exist_ok=True)
failures = common.Failures()
WIDTH, HEIGHT = 96, 72
# The objects' flat colours: pure primaries, the same in sRGB and linear.
PALETTE = [(1, 0, 0), (0, 1, 0), (0, 0, 1), (1, 1, 0)]


def principled(name, colour):
    material = bpy.data.materials.new(name)
    material.use_nodes = True
    material.node_tree.nodes["Principled BSDF"].inputs["Base Color"].default_value = colour + (1,)
    return material


def build():
    common.fresh()
    ops = bpy.ops.mesh
    ops.primitive_plane_add(size=400.0)
    ops.primitive_uv_sphere_add(radius=0.7, location=(-1.5, 0.3, 0.7))
    ops.primitive_cube_add(size=1.0, location=(1.2, 0.6, 0.75), rotation=(0.0, 0.0, 0.5),
                           scale=(1.0, 1.5, 1.5))
    ops.primitive_cylinder_add(radius=0.4, depth=1.6, location=(0.2, -1.4, 0.9),
                               rotation=(0.3, 0.2, 0.0))
    ops.primitive_monkey_add(location=(30.0, 30.0, 1.0))
    # In the exporter's order for objects made in Blender: by name.
    meshes = sorted((o for o in bpy.context.scene.objects
                     if o.type == "MESH" and o.name != "Suzanne"), key=lambda o: o.name)
    for obj, colour in zip(meshes, [(0.1, 0.3, 0.9), (0.2, 0.8, 0.3), (0.8, 0.8, 0.8),
                                    (0.9, 0.2, 0.1)]):
        obj.data.materials.append(principled(obj.name, colour))
    bpy.ops.object.light_add(type="POINT", location=(3.0, -4.0, 6.0))
    bpy.context.object.data.energy = 1000.0
    # What a scene cannot hold: a sun and a collection instance, reported.
    bpy.ops.object.light_add(type="SUN", location=(0.0, 0.0, 20.0))
    bpy.context.object.data.energy = 0.0  # not to light Cycles' flat picture
    group = bpy.data.collections.new("group")
    instance = bpy.data.objects.new("instance", None)
    instance.instance_type, instance.instance_collection = "COLLECTION", group
    bpy.context.scene.collection.objects.link(instance)
    bpy.ops.object.camera_add(location=(3.0, -3.6, 4.8))
    camera = bpy.context.object
    camera.rotation_euler = (-Vector(camera.location)).to_track_quat("-Z", "Y").to_euler()
    camera.data.sensor_fit = "VERTICAL"
    camera.data.angle_y = math.radians(60.0)
    bpy.context.scene.camera = camera
    render = bpy.context.scene.render
    render.resolution_x, render.resolution_y, render.resolution_percentage = WIDTH, HEIGHT, 100
    bpy.context.view_layer.update()
    return meshes


def cycles_flat(meshes, path):
    """Cycles' picture of the objects, each an emission of its palette colour."""
    for obj, colour in zip(meshes, PALETTE):
        material = bpy.data.materials.new(obj.name + " flat")
        material.use_nodes = True
        nodes = material.node_tree.nodes
        nodes.remove(nodes["Principled BSDF"])
        emission = nodes.new("ShaderNodeEmission")
        emission.inputs["Color"].default_value = colour + (1,)
        material.node_tree.links.new(emission.outputs[0], nodes["Material Output"].inputs[0])
        obj.data.materials[0] = material
    scene = bpy.context.scene
    scene.render.engine = "CYCLES"
    scene.cycles.device = "CPU"
    scene.cycles.samples = 1
    scene.cycles.use_denoising = False
    scene.cycles.pixel_filter_type = "BOX"
    scene.cycles.filter_width = 0.01  # every sample at the pixel's centre
    scene.view_settings.view_transform = "Standard"
    scene.world = bpy.data.worlds.new("black")
    scene.world.color = (0.0, 0.0, 0.0)
    scene.render.image_settings.file_format = "PNG"
    scene.render.filepath = path
    bpy.ops.render.render(write_still=True)
    image = bpy.data.images.load(path)
    pixels = np.array(image.pixels[:], dtype=np.float64).reshape(HEIGHT, WIDTH, 4)[::-1, :, :3]
    return pixels


def sfrender_flat(exported, path):
    """sfrender's picture of the exported scene, each object flat in its colour:
    AMBIENT 1 under one white light, nothing else."""
    scene = scenefile.read(exported)
    for obj, colour in zip(scene.objects, PALETTE):
        obj.material = scenefile.Material(colour, ambient=1.0, diffuse=0.0, specular=0.0)
    scene.lights = [scenefile.Light(scene.lights[0].position, (1.0, 1.0, 1.0))]
    flat = os.path.join(work, "flat.txt")  # with its materials
    scenefile.write(scene, flat)
    subprocess.run([sfrender, flat, "-o", path, "--width", str(WIDTH), "--height", str(HEIGHT),
                    "--quiet"], check=True)
    data = open(path, "rb").read()
    return np.frombuffer(data.split(b"\n", 3)[3], np.uint8).reshape(HEIGHT, WIDTH, 3) / 255.0


def labels(pixels):
    """Which palette colour (0 to 3) or the background (4) each pixel is nearest."""
    colours = np.array(PALETTE + [(0, 0, 0)], dtype=np.float64)
    distance = ((pixels[:, :, None, :] - colours[None, None, :, :]) ** 2).sum(axis=3)
    return distance.argmin(axis=2)


meshes = build()
scene, notes = exporter.build_scene(scenefile, bpy.context)
kinds = [o.kind.value for o in scene.objects]
failures.check(kinds == ["CUBE", "CYLINDER", "PLANE", "SPHERE"], f"the objects are {kinds}")
failures.check(any("Suzanne" in m and "no primitive" in m for _, m in notes),
               f"the monkey is not reported: {notes}")
failures.check(len(scene.lights) == 1, "the point light alone is exported")
failures.check(any("Sun" in m and "sun light" in m for _, m in notes), "the sun is not reported")
failures.check(any("instance" in m and "not expanded" in m for _, m in notes),
               "the collection instance is not reported")
for fmt, name in (("SF", "built.sf"), ("INSTRUCTIONS", "built.txt")):
    path = os.path.join(work, name)
    result, error = common.operator(bpy.ops.export_scene.sf, filepath=path, format=fmt)
    failures.check(result == {"FINISHED"}, f"{fmt}: {result} {error}")
    check = subprocess.run([sfcheck, "--werror", path], capture_output=True, text=True)
    failures.check(check.returncode == 0, f"sfcheck {name}: {check.stderr}")
# Blender's colours, and the sphere, cube and cylinder where Blender made them.
back = scenefile.read(os.path.join(work, "built.txt"))
failures.check(back.objects[3].colour == scene.objects[3].colour, "the sphere's colour")
failures.check(abs(back.objects[3].colour[0] - 0.9) < 1e-6, "Blender's base colour")
sphere = back.objects[3].matrix
failures.check(np.allclose(sphere[:3, 3], (-1.5, 0.7, -0.3), atol=1e-5)
               and np.allclose(np.linalg.norm(sphere[:3, :3], axis=0), 0.7, atol=1e-4),
               f"the sphere is at {sphere[:3, 3]} with radii {np.linalg.norm(sphere[:3, :3], axis=0)}")

theirs = labels(cycles_flat(meshes, os.path.join(work, "cycles.png")))
ours = labels(sfrender_flat(os.path.join(work, "built.sf"), os.path.join(work, "flat.ppm")))
shown = {int(k): int((ours == k).sum()) for k in range(5)}
failures.check(all(shown[k] > 50 for k in range(4)), f"each object fills pixels: {shown}")
differ = float((theirs != ours).mean())
print(f"sfrender and Cycles disagree on {100 * differ:.2f}% of the pixels; objects: {shown}")
failures.check(differ < 0.02, f"{100 * differ:.2f}% of the pixels show another object")
failures.finish("a scene built in Blender, exported")
