# The mirrors' and the glasses' own pixels in glTF viewers beside sfrender's:
# each scene is exported to .glb, imported by Blender's glTF importer and
# rendered with Cycles (Standard view, a black world), and exported again
# with --light-falloff none for f3d 1.3; the mean of every channel over the
# pixels of the mirrors (metallic at least 0.5), of the glasses
# (transmission above 0) and of the planes (the floor a glass shows) is set beside sfrender's picture of the same scene
# at the same size and field of view (docs/GLTF_VIEWERS.md, "Materials in PBR
# viewers, measured"). The pixels are found by an object-identity render in
# Blender: the objects of one group white and unlit, the rest black.
#
# blender -b --factory-startup --python-exit-code 1 --python THIS -- \
#     SFCONVERT SFRENDER WORKDIR WIDTH HEIGHT SAMPLES SCENE...
# A SCENE written "default=FILE.txt" stands for sfrender's built-in scene.
import json
import os
import shutil
import struct
import subprocess
import sys

import bpy
import numpy

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "gltf"))
from cycles_settings import cycles_as_sfrender  # noqa: E402

numpy.bool = bool  # Debian 12's Blender 3.4 importer still says numpy.bool

args = sys.argv[sys.argv.index("--") + 1:]
sfconvert, sfrender, work = args[0], args[1], args[2]
width, height, samples = int(args[3]), int(args[4]), int(args[5])
scenes = args[6:]
os.makedirs(work, exist_ok=True)
FOV = "60"
VIEW = ["--width", str(width), "--height", str(height), "--fov", FOV]


def run(command):
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"{' '.join(command)} failed with {done.returncode}:\n{done.stderr}")


def load_png(path):
    image = bpy.data.images.load(path)
    pixels = numpy.array(image.pixels[:]).reshape(image.size[1], image.size[0], image.channels)
    bpy.data.images.remove(image)
    # Blender's rows run bottom up; only masks and means are compared.
    return numpy.rint(pixels[:, :, :3] * 255.0)


def groups_of(glb):
    """The node names of the mirrors and of the glasses, from the file's
    materials, and of the planes (the floor a glass shows)."""
    data = open(glb, "rb").read()
    length = struct.unpack_from("<I", data, 12)[0]
    doc = json.loads(data[20:20 + length])
    groups = {"mirror": [], "glass": [], "floor": []}
    for node in doc["nodes"]:
        if "mesh" not in node:
            continue
        material = doc["materials"][doc["meshes"][node["mesh"]]["primitives"][0]["material"]]
        extensions = material.get("extensions", {})
        if "KHR_materials_transmission" in extensions:
            groups["glass"].append(node["name"])
        elif material["pbrMetallicRoughness"].get("metallicFactor", 1.0) >= 0.5:
            groups["mirror"].append(node["name"])
        elif node["name"].startswith("PLANE"):
            groups["floor"].append(node["name"])
    return groups


def setup(scene, png, render_samples):
    cycles_as_sfrender(bpy, scene, width, height, render_samples, png)


def import_glb(glb):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.ops.import_scene.gltf(filepath=glb)
    scene = bpy.context.scene
    scene.camera = [o for o in scene.objects if o.type == "CAMERA"][0]
    return scene


def cycles_picture(glb, name):
    scene = import_glb(glb)
    png = os.path.join(work, name + ".cycles.png")
    setup(scene, png, samples)
    bpy.ops.render.render(write_still=True)
    return load_png(png)


def mask_of(glb, name, names):
    """Where the objects `names` show: each white and unlit, the rest black."""
    scene = import_glb(glb)
    white = bpy.data.materials.new("white")
    white.use_nodes = True
    nodes = white.node_tree.nodes
    nodes.clear()
    emission = nodes.new("ShaderNodeEmission")
    emission.inputs["Color"].default_value = (1, 1, 1, 1)
    output = nodes.new("ShaderNodeOutputMaterial")
    white.node_tree.links.new(emission.outputs[0], output.inputs[0])
    black = bpy.data.materials.new("black")
    black.use_nodes = True
    black.node_tree.nodes["Principled BSDF"].inputs["Base Color"].default_value = (0, 0, 0, 1)
    black.node_tree.nodes["Principled BSDF"].inputs["Specular"].default_value = 0.0
    for o in scene.objects:
        if o.type == "MESH":
            o.data.materials.clear()
            o.data.materials.append(white if o.name in names else black)
        elif o.type == "LIGHT":
            o.data.energy = 0.0
    png = os.path.join(work, name + ".mask.png")
    setup(scene, png, 1)
    scene.cycles.max_bounces = 0
    scene.cycles.filter_width = 0.01
    bpy.ops.render.render(write_still=True)
    return load_png(png)[:, :, 0] > 127


def png_of_ppm(ppm):
    png = ppm[:-4] + ".png"
    with open(png, "wb") as out:
        subprocess.run(["pnmtopng", ppm], stdout=out, check=True)
    return png


def f3d_picture(source, name):
    if not shutil.which("f3d") or not shutil.which("xvfb-run"):
        return None
    glb = os.path.join(work, name + ".f3d.glb")
    run([sfconvert, source, glb, "--light-falloff", "none"] + VIEW)
    png = os.path.join(work, name + ".f3d.png")
    run(["xvfb-run", "-a", "-s", "-screen 0 1024x768x24", "f3d", glb, "--output", png,
         "--resolution", f"{width},{height}", "--camera-index", "0", "--bg-color", "0,0,0",
         "--quiet"])
    # f3d writes rows top down; Blender's loader gives them bottom up.
    return load_png(png)


def mean(picture, mask):
    return float(picture[mask].mean()) if mask.any() else float("nan")


print(f"{'scene':<24} {'group':<7} {'pixels':>6} {'sfrender':>9} {'Cycles':>7} {'ratio':>6}"
      f" {'f3d':>7} {'ratio':>6}")
for spec in scenes:
    if spec.startswith("default="):
        source, name = spec[len("default="):], "default-scene"
    else:
        source, name = spec, os.path.basename(spec)
    ppm = os.path.join(work, name + ".sfrender.ppm")
    run([sfrender, source, "-o", ppm, "--quiet"] + VIEW)
    ours = load_png(png_of_ppm(ppm))
    glb = os.path.join(work, name + ".glb")
    run([sfconvert, source, glb] + VIEW)
    cycles = cycles_picture(glb, name)
    f3d = f3d_picture(source, name)
    for group, names in groups_of(glb).items():
        if not names:
            continue
        mask = mask_of(glb, f"{name}.{group}", set(names))
        a, b = mean(ours, mask), mean(cycles, mask)
        line = f"{name:<24} {group:<7} {int(mask.sum()):>6} {a:>9.1f} {b:>7.1f} {b / a:>6.2f}"
        if f3d is not None:
            c = mean(f3d, mask)
            line += f" {c:>7.1f} {c / a:>6.2f}"
        print(line, flush=True)
