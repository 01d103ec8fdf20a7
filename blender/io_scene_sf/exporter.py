"""Blender's scene as a scene file or an instruction file.

Each object that the importer made and nobody edited is written from the
exact numbers it carries ("sf"); an edited one from Blender's matrix, with
the shape the importer put in its mesh, or, when the mesh itself was
edited, with the primitive scenefile.fit_primitive recognises in it (the
glTF reader's fitting). A mesh made in Blender is recognised the same way;
what is no primitive is reported and skipped.
"""

import numpy as np

from . import importer, mapping

# Helpers that draw nothing: skipped without a word.
_SILENT = {"EMPTY", "ARMATURE", "LIGHT_PROBE", "SPEAKER", "LATTICE"}


def _group(obj, role):
    """The object's "sf" custom property when the importer made it for `role`."""
    sf = obj.get("sf")
    if sf is None or not hasattr(sf, "get") or sf.get("role") != role:
        return None
    return sf


def _unchanged(sf, obj):
    return sf is not None and list(sf["blender_matrix"]) == importer.blender_matrix(obj)


def _order(obj):
    sf = obj.get("sf")
    index = sf.get("index") if sf is not None and hasattr(sf, "get") else None
    return (0, index, obj.name) if isinstance(index, int) else (1, 0, obj.name)


def camera(scenefile, obj, render, notes):
    """The scene's camera, and where the exact one is kept, its look-at and colour."""
    sf = _group(obj, "CAMERA")
    if _unchanged(sf, obj):
        result = scenefile.Camera(mapping.unflat(sf["matrix"]), sf["colour"])
        if "look_at" in sf:
            result.look_at = list(sf["look_at"])
    else:
        matrix = mapping.camera_from_blender(obj.matrix_world)
        eye, forward = matrix[:3, 3], -matrix[:3, 2]
        result = scenefile.Camera.looking_at(eye, eye + forward)
        if not mapping.is_float_noise(result.matrix, matrix):
            # Rolled about its forward axis: no LOOK_AT describes it.
            result = scenefile.Camera(matrix)
        if sf is not None:
            result.colour = sf["colour"]
    data = obj.data
    fov = mapping.vertical_fov(data.lens, data.sensor_width, data.sensor_height, data.sensor_fit,
                               render.resolution_x, render.resolution_y)
    if abs(fov - mapping.DEFAULT_FOV) > 1e-4:
        notes.append(("INFO", f"{obj.name}: its vertical field of view, {fov:.6g} degrees, is not "
                              f"held by the file: render it with sfrender --fov {fov:.6g}"))
    return result


def material(scenefile, obj, sf):
    """The Phong material: the exact values where the Principled BSDF's
    inputs are as the importer left them, Blender's where they were edited."""
    if sf is not None:
        result = scenefile.Material(sf["colour"], *sf["values"])
    else:
        result = scenefile.Material((0.8, 0.8, 0.8))  # Blender's default grey
    slot = obj.material_slots[0].material if obj.material_slots else None
    node = importer.principled(slot)
    if node is None:
        if slot is not None and sf is None:
            result.colour = tuple(slot.diffuse_color)[:3]
        return result
    # A value is Blender's where the inputs it depends on were edited; the
    # rest stay exact.
    now = mapping.material_values(importer.principled_snapshot(node))
    before = mapping.material_values(sf["material_inputs"]) if sf is not None else {}
    for prop, value in now.items():
        if prop not in before or before[prop] != value:
            setattr(result, prop, value)
    if sf is None and result.transparency == 0.0:
        result.ri = 1.0  # IOR matters only where light refracts
    if result.ri <= 0.0:
        result.ri = 1.0
    return result


def mesh_object(scenefile, obj, depsgraph, notes):
    """The object for a mesh, or None (reported) when it is no primitive."""
    evaluated = obj.evaluated_get(depsgraph)
    mesh = evaluated.to_mesh()
    try:
        positions, triangles = importer.mesh_arrays(mesh)
    finally:
        evaluated.to_mesh_clear()
    sf = _group(obj, "OBJECT")
    same_mesh = sf is not None and sf["mesh"] == mapping.mesh_hash(positions, triangles)
    if same_mesh:
        kind, shape = sf["kind"], mapping.C_INVERSE @ mapping.unflat(sf["shape"])
    else:
        # Fitted in the scene's axes, so that Blender's own primitives (a
        # cylinder along Z, a plane facing +Z) are the scene's, unrotated.
        local = positions.astype(np.float64) @ mapping.C_INVERSE[:3, :3].T
        fit = scenefile.fit_primitive(local, triangles)
        if not fit:
            notes.append(("WARNING", f"{obj.name}: skipped, its mesh is no primitive: "
                                     f"{fit.reason}"))
            return None
        kind, shape = fit.kind.value, fit.matrix
        notes.append(("INFO", f"{obj.name}: a {kind}, within {fit.error:.2g} of its size"))
    transforms = None
    if same_mesh and _unchanged(sf, obj):
        matrix = mapping.unflat(sf["matrix"])
        if "transform_kinds" in sf:
            values = list(sf["transform_values"])
            transforms = [scenefile.TransformOp(k, values[3 * i:3 * i + 3])
                          for i, k in enumerate(sf["transform_kinds"].split())]
    else:
        placed = mapping.from_blender(np.array(obj.matrix_world, dtype=np.float64))
        matrix = mapping.without_float_noise(placed) @ shape
    return scenefile.Object(kind, matrix, material=material(scenefile, obj, sf),
                            transforms=transforms)


def light(scenefile, obj, point, notes):
    """The LIGHT for a point light, or None (reported) for another kind."""
    if obj.data.type != "POINT":
        notes.append(("WARNING", f"{obj.name}: skipped, a {obj.data.type.lower()} light: a scene "
                                 f"holds point lights only"))
        return None
    sf = _group(obj, "LIGHT")
    if _unchanged(sf, obj):
        matrix = mapping.unflat(sf["matrix"])
    else:
        matrix = np.identity(4)
        matrix[:3, 3] = (mapping.C_INVERSE @ np.array(obj.matrix_world, dtype=np.float64))[:3, 3]
    now = list(obj.data.color) + [obj.data.energy]
    if sf is not None and list(sf["blender_light"]) == now:
        colour = tuple(sf["colour"])
    else:
        distance = (sf["reference_distance"] if sf is not None
                    else mapping.reference_distance(matrix[:3, 3], point))
        colour = mapping.light_colour(obj.data.color, obj.data.energy, distance)
    return scenefile.Light(colour=colour, matrix=matrix)


def build_scene(scenefile, context, use_selection=False):
    """The scene of Blender's, and what was noted on the way: (level, message)."""
    notes = []
    blender_scene = context.scene
    if blender_scene.camera is None or blender_scene.camera.type != "CAMERA":
        raise ValueError("the scene has no camera: a scene file needs one")
    candidates = [o for o in blender_scene.objects
                  if not o.hide_render and (not use_selection or o.select_get())]
    depsgraph = context.evaluated_depsgraph_get()
    scene = scenefile.Scene(camera(scenefile, blender_scene.camera, blender_scene.render, notes))
    cam_sf = _group(blender_scene.camera, "CAMERA")
    if cam_sf is not None and "output_file" in cam_sf:
        scene.output_file = cam_sf["output_file"]
    for obj in sorted(candidates, key=_order):
        if obj.type == "MESH":
            made = mesh_object(scenefile, obj, depsgraph, notes)
            if made is not None:
                scene.objects.append(made)
        elif obj.type == "EMPTY" and obj.instance_type == "COLLECTION" and obj.instance_collection:
            notes.append(("WARNING", f"{obj.name}: skipped, a collection instance is not "
                                     f"expanded"))
        elif obj.type == "CAMERA" and obj != blender_scene.camera:
            notes.append(("WARNING", f"{obj.name}: skipped, a scene has one camera, the "
                                     f"scene's ({blender_scene.camera.name})"))
        elif obj.type not in _SILENT | {"CAMERA", "LIGHT"}:
            notes.append(("WARNING", f"{obj.name}: skipped, a {obj.type.lower()} is no mesh"))
    point = mapping.reference_point(scene)
    for obj in sorted((o for o in candidates if o.type == "LIGHT"), key=_order):
        made = light(scenefile, obj, point, notes)
        if made is not None:
            scene.lights.append(made)
    return scene, notes


def export_scene(scenefile, context, filepath, format="SF", approximate=False,
                 use_selection=False):
    """Writes the file; returns (scene, losses, notes). SceneError when the
    scene cannot be written as asked (invalid, or losses under no_loss)."""
    scene, notes = build_scene(scenefile, context, use_selection)
    losses = scenefile.write(scene, filepath, format=format.lower(), approximate=approximate)
    return scene, losses, notes
