# The add-on's import and export in Blender, on each scene given:
#   - every object, light and the camera stands where the file puts it
#     (each mesh vertex where the scene's matrix takes the primitive's, shear
#     included, within Blender's floats);
#   - exported without an edit, the file is exactly what scenefile writes of
#     the scene read (in both formats, or refused by both);
#   - an object moved in Blender is written from Blender's matrix, the rest
#     still exactly; a material made diffuse in Blender gives its new colour.
#
# blender -b --factory-startup --python-exit-code 1 --python THIS -- ADDONS WORK SCENE...
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402  (sets numpy.bool before Blender's glTF code runs)

import bpy  # noqa: E402
import numpy as np  # noqa: E402

addons, work, scenes = common.arguments()[0], common.arguments()[1], common.arguments()[2:]
addon, scenefile = common.load_addon(addons)
from io_scene_sf import exporter, importer, mapping  # noqa: E402

failures = common.Failures()
TOLERANCE = 1e-5  # relative to the size of the numbers: Blender holds floats


def placed_as_the_file_says(name, scene):
    """Every vertex of every object where the scene's matrix puts it."""
    objects = {o["sf"]["index"]: o for o in bpy.data.objects
               if "sf" in o and o["sf"]["role"] == "OBJECT"}
    failures.check(len(objects) == len(scene.objects), f"{name}: {len(objects)} objects made")
    size = mapping.plane_half_size(scene)
    worst = 0.0
    for i, item in enumerate(scene.objects):
        positions, _, _ = scenefile.primitive_mesh(item.kind, importer.SEGMENTS, size)
        want = (np.c_[positions, np.ones(len(positions))] @ (mapping.C @ item.matrix).T)[:, :3]
        obj = objects[i]
        local, _ = importer.mesh_arrays(obj.data)
        world = np.array(obj.matrix_world, dtype=np.float64)
        got = (np.c_[local.astype(np.float64), np.ones(len(local))] @ world.T)[:, :3]
        scale = max(1.0, float(np.abs(want).max()))
        worst = max(worst, float(np.abs(got - want).max()) / scale)
    failures.check(worst < TOLERANCE, f"{name}: a vertex is {worst:.2g} from its place")
    camera = bpy.context.scene.camera
    want = mapping.C @ scene.camera.matrix
    got = np.array(camera.matrix_world, dtype=np.float64)
    failures.check(np.abs(got - want).max() <= TOLERANCE * max(1.0, np.abs(want).max()),
                   f"{name}: the camera is not where the file puts it")
    failures.check(abs(math.degrees(camera.data.angle_y) - 60.0) < 1e-4,
                   f"{name}: the camera's field of view is {math.degrees(camera.data.angle_y)}")
    lights = sorted((o for o in bpy.data.objects if o.type == "LIGHT"),
                    key=lambda o: o["sf"]["index"])
    for light, want in zip(lights, scene.lights):
        where = np.array(light.matrix_world, dtype=np.float64)[:3, 3]
        expected = (mapping.C @ np.append(want.position, 1.0))[:3]
        failures.check(np.allclose(where, expected, rtol=TOLERANCE, atol=TOLERANCE),
                       f"{name}: {light.name} is at {where}, not {expected}")


def exported_exactly(name, scene):
    for fmt, extension in (("SF", ".sf"), ("INSTRUCTIONS", ".txt")):
        ours = common.same_folder_name(work, "blender", name + extension)
        expected = common.same_folder_name(work, "expected", name + extension)
        try:
            scenefile.write(scene, expected)
            writable = True
        except scenefile.SceneError:
            writable = False
        result, error = common.operator(bpy.ops.export_scene.sf, filepath=ours, format=fmt)
        if not writable:
            failures.check(result == {"CANCELLED"}, f"{name} {fmt}: written, but cannot be")
            # The cure is named as the option the exporter shows.
            failures.check("'Approximate' writes" in error, f"{name} {fmt}: told {error!r}")
            continue
        failures.check(result == {"FINISHED"}, f"{name} {fmt}: {result} {error}")
        same = os.path.exists(ours) and open(ours, "rb").read() == open(expected, "rb").read()
        failures.check(same, f"{name} {fmt}: the export is not the file scenefile writes")


def edits_are_blenders(name, scene):
    if len(scene.objects) < 2:
        return
    objects = {o["sf"]["index"]: o for o in bpy.data.objects
               if "sf" in o and o["sf"]["role"] == "OBJECT"}
    objects[0].location.z += 1.0  # Blender's +Z is the scene's +Y
    node = importer.principled(objects[1].material_slots[0].material)
    # Made a plain diffuse colour: the base colour is then COLOUR itself.
    node.inputs["Base Color"].default_value = (0.25, 0.5, 0.75, 1.0)
    node.inputs["Metallic"].default_value = 0.0
    node.inputs["Transmission"].default_value = 0.0
    bpy.context.view_layer.update()
    path = common.same_folder_name(work, "edited", name + ".sf")
    result, error = common.operator(bpy.ops.export_scene.sf, filepath=path, format="SF")
    failures.check(result == {"FINISHED"}, f"{name} edited: {result} {error}")
    back = scenefile.read(path)
    # What was not edited is what a scene file of the scene holds.
    scene = scenefile.read(common.same_folder_name(work, "expected", name + ".sf"))
    moved = scene.objects[0].matrix.copy()
    moved[1, 3] += 1.0
    scale = max(1.0, np.abs(moved).max())
    failures.check(np.abs(back.objects[0].matrix - moved).max() < TOLERANCE * scale,
                   f"{name}: the moved object is not where Blender moved it")
    failures.check(back.objects[1].colour == (0.25, 0.5, 0.75),
                   f"{name}: the edited colour is {back.objects[1].colour}")
    # A scene file keeps only the colour: the rest as the exporter makes it.
    edited = exporter.material(scenefile, objects[1], objects[1]["sf"])
    failures.check(edited.colour == (0.25, 0.5, 0.75) and edited.reflectivity == 0.0
                   and edited.transparency == 0.0,
                   f"{name}: a material made diffuse is {edited.colour}, reflects "
                   f"{edited.reflectivity} and transmits {edited.transparency}")
    failures.check(np.array_equal(back.objects[1].matrix, scene.objects[1].matrix),
                   f"{name}: an object that was not moved did not keep its exact matrix")
    failures.check(back.objects[2:] == scene.objects[2:] and back.lights == scene.lights
                   and back.camera == scene.camera, f"{name}: what was not edited changed")


for path in scenes:
    name = os.path.basename(path)
    common.fresh()
    result, error = common.operator(bpy.ops.import_scene.sf, filepath=path)
    failures.check(result == {"FINISHED"}, f"{name}: import {result} {error}")
    scene = scenefile.read(path)
    placed_as_the_file_says(name, scene)
    exported_exactly(name, scene)
    edits_are_blenders(name, scene)
    print(f"{name}: {len(scene.objects)} objects, {len(scene.lights)} lights checked")

# The menu entries are there.
import_entries = [f.__name__ for f in bpy.types.TOPBAR_MT_file_import._dyn_ui_initialize()]
export_entries = [f.__name__ for f in bpy.types.TOPBAR_MT_file_export._dyn_ui_initialize()]
failures.check("menu_import" in import_entries, "no entry under File > Import")
failures.check("menu_export" in export_entries, "no entry under File > Export")
failures.finish(f"import and export of {len(scenes)} scenes")
