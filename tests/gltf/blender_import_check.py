# Blender imports the .glb that sfconvert writes for each scene file given,
# and every object, the camera and the light must stand where the scene
# file put them.
#
# blender -b --factory-startup --python-exit-code 1 --python THIS -- SFCONVERT WORKDIR SCENE.sf...
import math
import os
import subprocess
import sys

import bpy
import numpy
from mathutils import Matrix, Vector

# Debian 12's Blender 3.4 importer still says numpy.bool, which numpy 1.24
# removed; the builtin is what it means.
numpy.bool = bool

TOLERANCE = 1e-5  # relative to the largest entry of the matrix (Blender holds floats)
args = sys.argv[sys.argv.index("--") + 1:]
sfconvert, work, scenes = args[0], args[1], args[2:]
os.makedirs(work, exist_ok=True)

# glTF is Y-up, Blender Z-up: (x, y, z) in glTF is (x, -z, y) in Blender.
TO_BLENDER = Matrix(((1, 0, 0, 0), (0, 0, -1, 0), (0, 1, 0, 0), (0, 0, 0, 1)))


def read_records(path):
    lines = [line for line in open(path).read().splitlines() if line.strip()]
    records = []
    for i in range(0, len(lines), 6):
        rows = [[float(x) for x in lines[i + 2 + r].split()] for r in range(4)]
        records.append((lines[i].strip(), Matrix(rows)))
    return records


def relative(a, b):
    scale = max(1.0, max(abs(a[r][c]) for r in range(4) for c in range(4)))
    return max(abs(a[r][c] - b[r][c]) for r in range(4) for c in range(4)) / scale


failures = []
worst_seen = 0.0
for scene in scenes:
    glb = os.path.join(work, os.path.basename(scene) + ".glb")
    run = subprocess.run([sfconvert, scene, glb], capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit(f"sfconvert {scene} failed: {run.stderr}")
    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.ops.import_scene.gltf(filepath=glb)
    lights = 0
    objects = 0
    for kind, m in read_records(scene):
        if kind == "CAMERA":
            name = "CAMERA"
        elif kind == "LIGHT":
            lights += 1
            name = f"LIGHT {lights}"
        else:
            objects += 1
            name = f"{kind} {objects}"
        obj = bpy.data.objects.get(name)
        if obj is None:
            failures.append(f"{scene}: Blender has no object '{name}'")
            continue
        world = obj.matrix_world
        if kind == "CAMERA":
            # Blender's camera looks along its local -Z with +Y up, as glTF's.
            eye = TO_BLENDER @ Vector((m[0][3], m[1][3], m[2][3]))
            forward = TO_BLENDER.to_3x3() @ -Vector((m[0][2], m[1][2], m[2][2])).normalized()
            up = TO_BLENDER.to_3x3() @ Vector((m[0][1], m[1][1], m[2][1])).normalized()
            error = max((world.translation - eye).length / max(1.0, eye.length),
                        (-world.to_3x3().col[2].normalized() - forward).length,
                        (world.to_3x3().col[1].normalized() - up).length)
        elif kind == "LIGHT":
            position = TO_BLENDER @ Vector((m[0][3], m[1][3], m[2][3]))
            error = (world.translation - position).length / max(1.0, position.length)
        else:
            error = relative(world, TO_BLENDER @ m @ TO_BLENDER.inverted())
        worst_seen = max(worst_seen, error)
        print(f"{os.path.basename(scene)}: {name}: relative error {error:.3g}")
        if not error <= TOLERANCE:
            failures.append(f"{scene}: {name} is off by {error:.3g}")

if failures:
    sys.exit("\n".join(failures))
print(f"blender import: every record in place in {len(scenes)} scenes "
      f"(largest relative error {worst_seen:.3g})")
