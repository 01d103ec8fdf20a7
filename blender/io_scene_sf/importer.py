"""A scene file or an instruction file into Blender.

The camera at the scene's field of view, the point lights, and each object
as a mesh of its primitive (scenefile.primitive_mesh) under its matrix, with
a Principled BSDF that approximates its Phong material. The exact numbers
ride in each object's custom property "sf", with what Blender held of them
once placed, so that the exporter can tell what was edited.
"""

import math
import os

import bpy
import numpy as np
from mathutils import Matrix

from . import mapping

SEGMENTS = 32


def mesh_arrays(mesh):
    """The vertices (n, 3) float32 and the triangles (m, 3) of a mesh."""
    positions = np.empty(len(mesh.vertices) * 3, dtype=np.float32)
    mesh.vertices.foreach_get("co", positions)
    mesh.calc_loop_triangles()
    triangles = np.empty(len(mesh.loop_triangles) * 3, dtype=np.int32)
    mesh.loop_triangles.foreach_get("vertices", triangles)
    return positions.reshape(-1, 3), triangles.reshape(-1, 3)


def blender_matrix(obj):
    """The object's world matrix as Blender holds it, 16 floats row by row."""
    return [float(x) for row in obj.matrix_world for x in row]


def principled(material):
    """The material's Principled BSDF node, or None."""
    if not material or not material.use_nodes or not material.node_tree:
        return None
    for node in material.node_tree.nodes:
        if node.type == "BSDF_PRINCIPLED":
            return node
    return None


def principled_snapshot(node):
    """The inputs the mapping uses, as Blender holds them."""
    values = {}
    for name in ("Base Color", "Roughness", "Metallic", "Transmission", "IOR", "Specular"):
        value = node.inputs[name].default_value
        values[name] = [float(x) for x in value] if name == "Base Color" else float(value)
    return values


def new_material(name, material):
    blender = bpy.data.materials.new(name)
    blender.use_nodes = True
    node = principled(blender)
    for input_name, value in mapping.principled_inputs(material).items():
        node.inputs[input_name].default_value = value
    blender.diffuse_color = mapping.principled_inputs(material)["Base Color"]
    return blender


def link(collection, name, data):
    obj = bpy.data.objects.new(name, data)
    collection.objects.link(obj)
    return obj


def add_camera(context, collection, scene, filepath):
    data = bpy.data.cameras.new("CAMERA")
    data.sensor_fit = "VERTICAL"
    fov = scene.view.fov if scene.view is not None else mapping.DEFAULT_FOV
    data.angle_y = math.radians(fov)
    # No near plane but the eye in sfrender: Blender's clipping is set far
    # enough out, and near enough in, for the scene's size.
    places = [l.position for l in scene.lights] + [o.matrix[:3, 3] for o in scene.objects]
    far = max((4.0 * float(np.linalg.norm(np.asarray(p) - scene.camera.eye)) for p in places),
              default=0.0)
    data.clip_end = max(100.0, far, 4.0 * mapping.plane_half_size(scene))
    data.clip_start = min(0.1, data.clip_end * 1e-6)
    obj = link(collection, "CAMERA", data)
    obj.matrix_world = Matrix((mapping.C @ scene.camera.matrix).tolist())
    context.scene.camera = obj
    sf = {"role": "CAMERA", "matrix": mapping.flat(scene.camera.matrix),
          "colour": list(scene.camera.colour), "source": os.path.basename(filepath)}
    if scene.camera.look_at is not None:
        sf["look_at"] = list(scene.camera.look_at)
    if scene.view is not None:
        sf["fov"] = scene.view.fov
        if scene.view.aspect_ratio is not None:
            sf["aspect_ratio"] = scene.view.aspect_ratio
    if scene.output_file is not None:
        sf["output_file"] = scene.output_file
    return obj, sf


def add_light(collection, index, light, point):
    distance = mapping.reference_distance(light.position, point)
    colour, watts = mapping.light_power(light.colour, distance)
    data = bpy.data.lights.new(f"LIGHT {index + 1}", "POINT")
    data.color = colour
    data.energy = watts
    data.shadow_soft_size = 0.0  # a point: hard shadows, as sfrender's
    obj = link(collection, f"LIGHT {index + 1}", data)
    obj.location = (mapping.C @ np.append(light.position, 1.0))[:3].tolist()
    sf = {"role": "LIGHT", "index": index, "matrix": mapping.flat(light.matrix),
          "colour": list(light.colour), "reference_distance": distance}
    return obj, sf


def add_object(collection, index, item):
    name = f"{item.kind.value} {index + 1}"
    obj = link(collection, name, bpy.data.meshes.new(name))
    obj.matrix_world = Matrix(mapping.to_blender(item.matrix).tolist())
    obj.data.materials.append(new_material(name, item.material))
    m = item.material
    sf = {"role": "OBJECT", "index": index, "kind": item.kind.value,
          "matrix": mapping.flat(item.matrix), "colour": list(m.colour),
          "values": [m.ambient, m.diffuse, m.specular, m.shininess, m.reflectivity,
                     m.transparency, m.ri]}
    if item.transforms is not None:
        sf["transform_kinds"] = " ".join(op.kind.value for op in item.transforms)
        sf["transform_values"] = [v for op in item.transforms for v in op.value]
    return obj, sf


def fill_mesh(scenefile, obj, kind, exact, plane_size, sf):
    """The primitive's mesh in the object's local space: what Blender's
    matrix (location, rotation and scale, no shear) leaves of the exact one
    (the shear, beyond float rounding) is put into the vertices, so that the
    mesh stands where the scene says."""
    kept = np.array(obj.matrix_world, dtype=np.float64)
    shape = np.linalg.inv(kept) @ mapping.to_blender(exact) @ mapping.C
    if mapping.is_float_noise(shape, mapping.C):
        shape = mapping.C  # Blender kept all of it: the mesh is the primitive's own
    positions, normals, triangles = scenefile.primitive_mesh(kind, SEGMENTS, plane_size)
    placed = np.c_[positions.astype(np.float64), np.ones(len(positions))] @ shape.T
    obj.data.from_pydata(placed[:, :3].tolist(), [], triangles.tolist())
    if kind in ("SPHERE", "CYLINDER"):
        obj.data.polygons.foreach_set("use_smooth", [True] * len(obj.data.polygons))
    obj.data.update()
    sf["shape"] = mapping.flat(shape)
    sf["mesh"] = mapping.mesh_hash(*mesh_arrays(obj.data))


def import_scene(context, filepath, scenefile, skip_unsupported=False):
    """Reads the file and builds it in the active collection; returns the
    scene read (its diagnostics are its warnings and notes)."""
    scene = scenefile.read(filepath, skip_unsupported=skip_unsupported)
    collection = context.collection
    made = [add_camera(context, collection, scene, filepath)]
    point = mapping.reference_point(scene)
    made += [add_light(collection, i, light, point) for i, light in enumerate(scene.lights)]
    objects = [add_object(collection, i, item) for i, item in enumerate(scene.objects)]
    # Blender recomposes each matrix from location, rotation and scale: what
    # it keeps is known once the view layer is updated.
    context.view_layer.update()
    plane_size = mapping.plane_half_size(scene)
    for (obj, sf), item in zip(objects, scene.objects):
        fill_mesh(scenefile, obj, item.kind.value, item.matrix, plane_size, sf)
        sf["material_inputs"] = principled_snapshot(principled(obj.data.materials[0]))
    for obj, sf in made + objects:
        sf["blender_matrix"] = blender_matrix(obj)
        if obj.type == "LIGHT":
            sf["blender_light"] = list(obj.data.color) + [obj.data.energy]
        obj["sf"] = sf
    return scene
