# Blender 3.4 imports what sfconvert writes as OBJ (its own OBJ importer,
# wm.obj_import), and Cycles' silhouettes of the meshes match sfrender's
# picture of the scene: both coverage masks (sfrender --alpha, Cycles'
# transparent film), cut at one half, agree on at least MIN_AGREE of the
# pixels, and every pixel where they differ lies on an edge of sfrender's
# mask (docs/OBJ.md, "Clients"). Each object is also one Blender object.
#
# blender -b --factory-startup --python-exit-code 1 --python THIS -- \
#     SFCONVERT SFRENDER WORKDIR WIDTH HEIGHT SAMPLES MIN_AGREE SCENE...
import math
import os
import subprocess
import sys

import bpy
from mathutils import Matrix

args = sys.argv[sys.argv.index("--") + 1:]
sfconvert, sfrender, work = args[0], args[1], args[2]
width, height, samples = int(args[3]), int(args[4]), int(args[5])
min_agree = float(args[6])
scenes = args[7:]
os.makedirs(work, exist_ok=True)
FOV = 60.0  # sfrender's default; scene and instruction files carry no view
# OBJ is Y up; the importer's default axes (-Z forward, Y up) turn it into
# Blender's Z up: (x, y, z) -> (x, -z, y). A camera's matrix turns the same.
OBJ_TO_BLENDER = Matrix(((1, 0, 0, 0), (0, 0, -1, 0), (0, 1, 0, 0), (0, 0, 0, 1)))


def run(command):
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(" ".join(command) + " failed:\n" + done.stdout + done.stderr)


def camera_of(obj_file):
    """The camera matrix from the writer's exact-value comment."""
    for line in open(obj_file):
        if line.startswith("# scenefile camera matrix "):
            n = [float(w) for w in line.split()[4:20]]
            return Matrix([n[0:4], n[4:8], n[8:12], n[12:16]])
    sys.exit(obj_file + " has no camera comment")


def alpha_mask(png):
    image = bpy.data.images.load(png)
    assert tuple(image.size) == (width, height), (png, tuple(image.size))
    pixels = list(image.pixels)
    bpy.data.images.remove(image)
    return [pixels[i * 4 + 3] >= 0.5 for i in range(width * height)]


def on_edge(mask, i):
    x, y = i % width, i // width
    for dy in (-1, 0, 1):
        for dx in (-1, 0, 1):
            u, v = x + dx, y + dy
            if 0 <= u < width and 0 <= v < height and mask[v * width + u] != mask[i]:
                return True
    return False


failures = []
for scene in scenes:
    name = os.path.splitext(os.path.basename(scene))[0]
    obj = os.path.join(work, name + ".obj")
    ours = os.path.join(work, name + "-sfrender.png")
    theirs = os.path.join(work, name + "-cycles.png")
    run([sfconvert, "-q", scene, obj])
    run([sfrender, "-q", scene, "-o", ours, "--width", str(width), "--height", str(height),
         "--fov", str(FOV), "--spp", "16", "--alpha"])

    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.ops.wm.obj_import(filepath=obj)
    objects = sum(1 for line in open(obj) if line.startswith("o "))
    imported = [o for o in bpy.context.scene.objects if o.type == "MESH"]
    if len(imported) != objects:
        failures.append(f"{name}: Blender made {len(imported)} objects of {objects} groups")
    data = bpy.data.cameras.new("camera")
    data.sensor_fit = "VERTICAL"
    data.angle_y = math.radians(FOV)
    data.clip_start, data.clip_end = 0.001, 1e6
    camera = bpy.data.objects.new("camera", data)
    bpy.context.scene.collection.objects.link(camera)
    camera.matrix_world = OBJ_TO_BLENDER @ camera_of(obj)
    s = bpy.context.scene
    s.camera = camera
    s.render.engine = "CYCLES"
    s.cycles.device = "CPU"
    s.cycles.samples = samples
    s.cycles.use_denoising = False
    s.cycles.pixel_filter_type = "BOX"
    s.cycles.filter_width = 1.0
    s.cycles.max_bounces = 0
    s.render.film_transparent = True
    s.render.resolution_x, s.render.resolution_y = width, height
    s.render.resolution_percentage = 100
    s.render.image_settings.file_format = "PNG"
    s.render.image_settings.color_mode = "RGBA"
    s.render.filepath = theirs
    bpy.ops.render.render(write_still=True)

    a, b = alpha_mask(ours), alpha_mask(theirs)
    differ = [i for i in range(width * height) if a[i] != b[i]]
    agree = 1 - len(differ) / (width * height)
    inside = [i for i in differ if not on_edge(a, i)]
    covered = sum(a) / (width * height)
    print(f"{name}: {objects} objects; silhouettes agree on {agree:.2%} of the pixels "
          f"(sfrender covers {covered:.1%}), {len(differ)} differ, {len(inside)} off the edges")
    if agree < min_agree or inside:
        failures.append(f"{name}: {agree:.2%} agree, {len(inside)} differing pixels off the edges")

if failures:
    sys.exit("\n".join(failures))
