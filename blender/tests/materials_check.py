# The add-on's materials follow the glTF writer's mapping:
#   - the default scene imported through the add-on has a mirror that is a
#     smooth metal (Metallic at least 0.9, Roughness at most 0.05) and a
#     glass that transmits (Transmission at least 0.9, IOR 1.5);
#   - for every object of the scenes given, mapping.principled_inputs gives
#     the numbers the glTF writer writes (libscene's gltf_mapping.cpp), and
#     mapping.material_values what the glTF reader makes of them without
#     extras, so that the two copies of the numbers cannot drift apart.
#
# blender -b --factory-startup --python-exit-code 1 --python THIS -- ADDONS WORK DEFAULT SCENE...
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402  (sets numpy.bool before Blender's glTF code runs)

import bpy  # noqa: E402

addons, work, default_scene = common.arguments()[:3]
scenes = [default_scene] + common.arguments()[3:]
addon, scenefile = common.load_addon(addons)
from io_scene_sf import importer, mapping  # noqa: E402

failures = common.Failures()
TOLERANCE = 1e-12  # the same formulas in doubles


def within(name, what, value, low, high):
    failures.check(low - 1e-6 <= value <= high + 1e-6,  # Blender holds floats
                   f"{name}: {what} {value:.4f}, not within [{low}, {high}]")


def imported_as_mirror_and_glass():
    common.fresh()
    result, error = common.operator(bpy.ops.import_scene.sf, filepath=default_scene)
    failures.check(result == {"FINISHED"}, f"default scene: import {result} {error}")
    scene = scenefile.read(default_scene)
    mirrors = glasses = 0
    for obj in bpy.data.objects:
        if "sf" not in obj or obj["sf"]["role"] != "OBJECT":
            continue
        material = scene.objects[obj["sf"]["index"]].material
        node = importer.principled(obj.material_slots[0].material)
        inputs = {i: node.inputs[i].default_value for i in ("Metallic", "Roughness",
                                                           "Transmission", "IOR")}
        if material.transparency >= 0.5:
            glasses += 1
            within(obj.name, "Transmission", inputs["Transmission"], 0.9, 1.0)
            within(obj.name, "IOR", inputs["IOR"], 1.5, 1.5)
            within(obj.name, "Roughness", inputs["Roughness"], 0.0, 0.05)
        elif material.reflectivity >= 0.5:
            mirrors += 1
            within(obj.name, "Metallic", inputs["Metallic"], 0.9, 1.0)
            within(obj.name, "Roughness", inputs["Roughness"], 0.0, 0.05)
    failures.check(mirrors == 1 and glasses == 1,
                   f"default scene: {mirrors} mirrors and {glasses} glasses, not 1 and 1")


def close(a, b):
    return abs(a - b) <= TOLERANCE * max(1.0, abs(a), abs(b))


def same_as_the_gltf_writer(path):
    name = os.path.basename(path)
    scene = scenefile.read(path)
    gltf_path = common.same_folder_name(work, "gltf", name + ".gltf")
    scenefile.write(scene, gltf_path)
    document = json.load(open(gltf_path))
    for node in document["nodes"]:
        if "mesh" not in node:
            continue
        index = node["extras"]["sf"]["object"] - 1
        written = document["materials"][document["meshes"][node["mesh"]]["primitives"][0]
                                         ["material"]]
        pbr = written["pbrMetallicRoughness"]
        extensions = written.get("extensions", {})
        gltf = {
            "Base Color": pbr.get("baseColorFactor", [1.0, 1.0, 1.0, 1.0]),
            "Metallic": pbr.get("metallicFactor", 1.0),
            "Roughness": pbr.get("roughnessFactor", 1.0),
            "Transmission": extensions.get("KHR_materials_transmission", {})
                                      .get("transmissionFactor", 0.0),
            "IOR": extensions.get("KHR_materials_ior", {}).get("ior", 1.5),
        }
        ours = mapping.principled_inputs(scene.objects[index].material)
        for key, value in gltf.items():
            if key == "IOR" and "KHR_materials_ior" not in extensions:
                continue  # glTF's default IOR stands for RI 1, which refracts nothing
            got = ours[key][:3] if key == "Base Color" else [ours[key]]
            want = value[:3] if key == "Base Color" else [value]
            failures.check(all(close(a, b) for a, b in zip(got, want)),
                           f"{name} {node['name']}: {key} {got}, the glTF writer's {want}")
        # Without its extras, the glTF reader inverts the mapping.
        del written["extras"]
        node.pop("extras")
        document.setdefault("_inverse", []).append((node["name"], index, gltf))
    inverse = document.pop("_inverse", [])
    bare = common.same_folder_name(work, "bare", name + ".gltf")
    for item in document["nodes"] + document["materials"]:
        item.pop("extras", None)
    with open(bare, "w") as out:
        json.dump(document, out)
    read = scenefile.read(bare)
    for node_name, index, gltf in inverse:
        gltf = dict(gltf, Specular=mapping.principled_inputs(scene.objects[index].material)
                    ["Specular"])
        want = mapping.material_values(gltf)
        got = read.objects[index].material
        for key in ("colour", "reflectivity", "transparency", "shininess"):
            a = want[key] if key == "colour" else [want[key]]
            b = tuple(got.colour) if key == "colour" else [getattr(got, key)]
            failures.check(all(close(x, y) for x, y in zip(a, b)),
                           f"{name} {node_name}: {key} {a}, the glTF reader's {b}")


imported_as_mirror_and_glass()
for path in scenes:
    same_as_the_gltf_writer(path)
failures.finish(f"the add-on's materials on {len(scenes)} scenes")
