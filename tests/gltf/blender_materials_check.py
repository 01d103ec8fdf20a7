# Blender's glTF importer makes the default scene's mirror a mirror and its
# glass glass (docs/GLTF.md, "Materials"): the mirror's Principled BSDF is
# metallic and smooth with a light base colour, the glass transmits with
# RI's IOR and is smooth. What Cycles then renders is measured by
# bench/gltf_materials_bench.sh, not here.
#
# blender -b --factory-startup --python-exit-code 1 --python THIS -- \
#     SFCONVERT WORKDIR DEFAULT_SCENE.txt
import os
import subprocess
import sys

import bpy
import numpy

numpy.bool = bool  # Debian 12's Blender 3.4 importer still says numpy.bool

sfconvert, work, source = sys.argv[sys.argv.index("--") + 1:][:3]
os.makedirs(work, exist_ok=True)
glb = os.path.join(work, "default-scene.glb")
done = subprocess.run([sfconvert, source, glb], capture_output=True, text=True)
if done.returncode != 0:
    sys.exit(f"sfconvert failed with {done.returncode}:\n{done.stderr}")
bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.import_scene.gltf(filepath=glb)


def principled(name):
    material = bpy.data.objects[name].active_material
    nodes = [n for n in material.node_tree.nodes if n.type == "BSDF_PRINCIPLED"]
    if len(nodes) != 1:
        sys.exit(f"{name}: {len(nodes)} Principled BSDF nodes, not one")
    return {i.name: i.default_value for i in nodes[0].inputs if hasattr(i, "default_value")}


failures = []


def expect(name, what, value, low, high):
    ok = low - 1e-6 <= value <= high + 1e-6  # Blender holds floats
    print(f"{name}: {what} {value:.4f} (expected {low} to {high}){'' if ok else ' WRONG'}")
    if not ok:
        failures.append(f"{name}: {what} {value:.4f}, not within [{low}, {high}]")


# CUBE 2: COLOUR 0.05, REFLECTIVITY 0.9, SHININESS 200.
mirror = principled("CUBE 2")
expect("mirror", "Metallic", mirror["Metallic"], 0.9, 1.0)
expect("mirror", "Roughness", mirror["Roughness"], 0.0, 0.05)
expect("mirror", "Base Color (least channel)", min(mirror["Base Color"][:3]), 0.7, 1.0)
expect("mirror", "Transmission", mirror["Transmission"], 0.0, 0.0)
# SPHERE 3: TRANSPARENCY 0.9, RI 1.5, DIFFUSE 0.05.
glass = principled("SPHERE 3")
expect("glass", "Transmission", glass["Transmission"], 0.9, 1.0)
expect("glass", "IOR", glass["IOR"], 1.5, 1.5)
expect("glass", "Metallic", glass["Metallic"], 0.0, 0.0)
expect("glass", "Roughness", glass["Roughness"], 0.0, 0.05)
# SPHERE 4: a red diffuse ball stays what it was.
plain = principled("SPHERE 4")
expect("red sphere", "Metallic", plain["Metallic"], 0.0, 0.0)
expect("red sphere", "Base Color (red)", plain["Base Color"][0], 0.85, 0.85)
if failures:
    sys.exit("\n".join(failures))
print("blender materials: the mirror imports as a mirror, the glass as glass")
