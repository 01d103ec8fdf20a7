# Blender exports a scene of a UV sphere, a cube, a cylinder, a plane, a
# camera and a point light as glTF (.gltf with its buffer beside it, and
# .glb); sfconvert must recover each primitive with its place, size and
# rotation, the camera, the light and the colours. The light's colour is
# what sfrender must show to match Cycles at the reference distance.
#
# blender -b --factory-startup --python-exit-code 1 --python THIS -- SFCONVERT WORKDIR
import math
import os
import re
import subprocess
import sys

import bpy
from mathutils import Matrix, Vector

TOLERANCE = 1e-4
sfconvert, work = sys.argv[sys.argv.index("--") + 1:]
os.makedirs(work, exist_ok=True)

# Blender is Z-up, glTF Y-up: (x, y, z) in Blender is (x, z, -y) in glTF.
TO_GLTF = Matrix(((1, 0, 0, 0), (0, 0, 1, 0), (0, -1, 0, 0), (0, 0, 0, 1)))


def gltf_matrix(blender_world):
    return TO_GLTF @ blender_world @ TO_GLTF.inverted()


def coloured(obj, rgb):
    material = bpy.data.materials.new(obj.name + " material")
    material.use_nodes = True
    material.node_tree.nodes["Principled BSDF"].inputs["Base Color"].default_value = (*rgb, 1.0)
    obj.data.materials.append(material)


bpy.ops.wm.read_factory_settings(use_empty=True)
expected = {}  # kind -> (matrix in glTF space, colour)

bpy.ops.mesh.primitive_uv_sphere_add(segments=32, ring_count=16, radius=1.5,
                                     location=(1, 2, 3), rotation=(0.3, 0.2, 0.1))
sphere = bpy.context.object
coloured(sphere, (0.8, 0.1, 0.1))
expected["SPHERE"] = (Matrix.Diagonal((1.5, 1.5, 1.5, 1.0)), (0.8, 0.1, 0.1), sphere)

# The operator's scale is baked into the vertices (Blender x, y, z are glTF
# x, -z, y); the object's own scale goes into the node.
bpy.ops.mesh.primitive_cube_add(size=2, location=(-3, 1, 0.5), rotation=(0.1, 0.7, -0.4),
                                scale=(1.5, 1, 0.75))
cube = bpy.context.object
cube.scale = (1, 2, 0.5)
coloured(cube, (0.1, 0.7, 0.2))
expected["CUBE"] = (Matrix.Diagonal((1.5, 0.75, 1.0, 1.0)), (0.1, 0.7, 0.2), cube)

# Blender's cylinder stands along its local Z, which is glTF's local Y.
bpy.ops.mesh.primitive_cylinder_add(vertices=24, radius=0.5, depth=3, location=(2, -2, 1),
                                    rotation=(0.5, 0, 0.9))
cylinder = bpy.context.object
coloured(cylinder, (0.2, 0.3, 0.9))
expected["CYLINDER"] = (Matrix.Diagonal((0.5, 1.5, 0.5, 1.0)), (0.2, 0.3, 0.9), cylinder)

bpy.ops.mesh.primitive_plane_add(size=4, location=(0, 0, -1), rotation=(0.05, -0.1, 0.6))
plane = bpy.context.object
coloured(plane, (0.5, 0.5, 0.4))
expected["PLANE"] = (Matrix.Diagonal((2.0, 2.0, 2.0, 1.0)), (0.5, 0.5, 0.4), plane)

bpy.ops.object.camera_add(location=(0.5, -12, 4), rotation=(1.25, 0.05, 0.1))
camera = bpy.context.object
camera.data.sensor_fit = "VERTICAL"
camera.data.angle = math.radians(40)

bpy.ops.object.light_add(type="POINT", location=(4, -4, 6))
light = bpy.context.object
light.data.energy = 1000.0  # watts, Blender's default point light
light.data.color = (1.0, 0.8, 0.6)
bpy.context.view_layer.update()

# Where the camera looks, by Blender's own ray cast (on the tessellated
# meshes, so within their facets of sfconvert's fitted primitives), or on
# the plane's infinite extension, which is what a PLANE is.
eye = camera.matrix_world.translation
forward = -camera.matrix_world.to_3x3().col[2].normalized()
hits = []
hit, location, *_ = bpy.context.scene.ray_cast(bpy.context.evaluated_depsgraph_get(), eye,
                                               forward)
if hit:
    hits.append((location - eye).length)
normal = plane.matrix_world.to_3x3().col[2]
if abs(normal.dot(forward)) > 0:
    t = normal.dot(plane.matrix_world.translation - eye) / normal.dot(forward)
    if t > 0:
        hits.append(t)
looked_at = TO_GLTF @ (eye + min(hits) * forward) if hits else None

outputs = {}
for name, fmt in (("blender.gltf", "GLTF_SEPARATE"), ("blender.glb", "GLB")):
    path = os.path.join(work, name)
    # The default lighting mode, "Standard": W / (4 pi) * 683 candela.
    bpy.ops.export_scene.gltf(filepath=path, export_format=fmt, export_cameras=True,
                              export_lights=True)
    sf = os.path.join(work, name + ".sf")
    # -v: the camera's and the light's notes, read below.
    run = subprocess.run([sfconvert, "-v", path, sf], capture_output=True, text=True)
    print(run.stderr)
    if run.returncode != 0:
        sys.exit(f"sfconvert {name} failed with {run.returncode}")
    outputs[name] = (open(sf).read(), run.stderr)

text, diagnostics = outputs["blender.gltf"]
if outputs["blender.glb"][0] != text:
    sys.exit("the .gltf and the .glb give different scene files")

records = []
lines = [line for line in text.splitlines() if line.strip()]
for i in range(0, len(lines), 6):
    colour = [float(x) for x in lines[i + 1].split()]
    rows = [[float(x) for x in lines[i + 2 + r].split()] for r in range(4)]
    records.append((lines[i], colour, Matrix(rows)))


def worst(a, b):
    return max(abs(a[r][c] - b[r][c]) for r in range(4) for c in range(4))


failures = []


def check(what, error, tolerance=TOLERANCE):
    print(f"{what}: largest error {error:.3g}")
    if not error <= tolerance:
        failures.append(f"{what}: error {error:.3g} above {tolerance}")


kinds = [r[0] for r in records]
for kind, (shape, colour, obj) in expected.items():
    if kinds.count(kind) != 1:
        failures.append(f"expected one {kind}, got {kinds.count(kind)}")
        continue
    _, got_colour, got = records[kinds.index(kind)]
    want = gltf_matrix(obj.matrix_world) @ shape
    check(f"{kind} matrix", worst(got, want))
    check(f"{kind} colour", max(abs(a - b) for a, b in zip(got_colour, colour)))

name, _, got = records[0]
world = camera.matrix_world
eye = TO_GLTF @ world.translation
forward = (TO_GLTF.to_3x3() @ -world.to_3x3().col[2]).normalized()
up = (TO_GLTF.to_3x3() @ world.to_3x3().col[1]).normalized()
right = forward.cross(up)
want = Matrix(((right.x, up.x, -forward.x, eye.x), (right.y, up.y, -forward.y, eye.y),
               (right.z, up.z, -forward.z, eye.z), (0, 0, 0, 1)))
check("CAMERA matrix", worst(got, want) if name == "CAMERA" else math.inf)
fov = re.search(r"--fov ([0-9.e+-]+)", diagnostics)
check("CAMERA --fov", abs(float(fov.group(1)) - 40.0) if fov else math.inf)

lights = [r for r in records if r[0] == "LIGHT"]
if len(lights) != 1:
    failures.append(f"expected one LIGHT, got {len(lights)}")
else:
    _, got_colour, got = lights[0]
    position = TO_GLTF @ light.matrix_world.translation
    check("LIGHT position", max(abs(got[r][3] - position[r]) for r in range(3)))
    # The note states the reference distance and the point the camera looks
    # at (to six digits), which must be Blender's own within a facet.
    note = re.search(r"reference distance ([0-9.e+-]+), from the light to the point the camera "
                     r"looks at, on the first object its forward ray meets, \(([^)]*)\)",
                     diagnostics)
    if not note or looked_at is None:
        failures.append(f"no reference point where the camera looks (Blender: {looked_at}): "
                        + diagnostics)
    else:
        distance = float(note.group(1))
        point = Vector([float(x) for x in note.group(2).split()])
        # The note gives six digits; a facet of the meshes is further off.
        check("reference point", (point - looked_at).length, 1e-2)
        check("reference distance", abs((position - point).length - distance) / distance, 1e-5)
        # What Cycles shows on a surface of 0.8 facing the light there (W / (4
        # pi^2 d^2), sRGB-encoded) is what sfrender shows under the LIGHT.
        def encode(v):
            return 12.92 * v if v <= 0.0031308 else 1.055 * v ** (1 / 2.4) - 0.055
        linear = [c * 1000.0 / (4 * math.pi ** 2 * distance ** 2) for c in (1.0, 0.8, 0.6)]
        want_colour = [encode(0.8 * v) / 0.8 for v in linear]
        print(f"LIGHT colour {got_colour}, from Cycles' view {want_colour}")
        check("LIGHT colour", max(abs(a - b) / b for a, b in zip(got_colour, want_colour)), 1e-5)

if failures:
    sys.exit("\n".join(failures))
print("blender export: every primitive, the camera and the light recovered")
