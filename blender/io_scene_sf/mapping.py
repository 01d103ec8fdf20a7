"""How a scene maps onto Blender and back: axes, materials, lights, the
field of view. Numbers only (numpy, no bpy), so that both directions use
the same rules; docs/PYTHON.md ("The Blender add-on") states them.

Matrices here are numpy float64 arrays, [row, column], as scenefile's.
"""

import hashlib
import math

import numpy as np

# The scene is +Y up, Blender +Z up: (x, y, z) in the scene is (x, -z, y) in
# Blender, the glTF importer's convention. A scene-space matrix M is C M C^-1
# in Blender; a camera, which looks along its local -Z with +Y up in both,
# is C M.
C = np.array([[1.0, 0.0, 0.0, 0.0], [0.0, 0.0, -1.0, 0.0], [0.0, 1.0, 0.0, 0.0],
              [0.0, 0.0, 0.0, 1.0]])
C_INVERSE = C.T.copy()

DEFAULT_FOV = 60.0  # sfrender's vertical field of view, in degrees
SPECULAR_SCALE = 0.5 / 0.9  # SPECULAR 0.9, the default, is Blender's default 0.5
# Lights are matched where a surface of this COLOUR is lit (docs/GLTF.md).
REFERENCE_ALBEDO = 0.8


def srgb_to_linear(v):
    v = max(0.0, float(v))
    return v / 12.92 if v <= 0.04045 else ((v + 0.055) / 1.055) ** 2.4


def linear_to_srgb(v):
    v = max(0.0, float(v))
    return v * 12.92 if v <= 0.0031308 else 1.055 * v ** (1 / 2.4) - 0.055


def flat(matrix):
    """A 4x4 as 16 floats, row by row (how the custom properties hold it)."""
    return [float(x) for x in np.asarray(matrix, dtype=np.float64).reshape(16)]


def unflat(values):
    return np.array(list(values), dtype=np.float64).reshape(4, 4)


def to_blender(matrix):
    return C @ matrix @ C_INVERSE


def from_blender(matrix):
    return C_INVERSE @ matrix @ C


# Blender holds matrices in floats: a rotation and a scale come back with
# errors of 1e-7, which an instruction file would have to call shear. Where
# that is all they are, they are taken away.
FLOAT_NOISE = 1e-6


def without_float_noise(matrix):
    """An affine matrix whose 3x3 block is a rotation (or mirror) times a
    scale along its own axes but for float rounding, made exactly that (in
    doubles); any other matrix (true shear) as it is."""
    u, s, vt = np.linalg.svd(matrix[:3, :3])
    stretch = vt.T @ np.diag(s) @ vt  # the polar decomposition: block = (u vt) stretch
    scale = np.diag(stretch)
    if np.abs(stretch - np.diag(scale)).max() > FLOAT_NOISE * max(np.abs(scale).max(), 1e-300):
        return matrix
    out = np.array(matrix, dtype=np.float64)
    out[:3, :3] = (u @ vt) @ np.diag(scale)
    out[3] = (0.0, 0.0, 0.0, 1.0)
    return out


def camera_from_blender(matrix):
    """A scene camera from a Blender camera's world matrix: its eye, forward
    and up, orthonormalised as sfrender does (forward first), the scale left
    out (it means nothing to a camera)."""
    m = C_INVERSE @ np.asarray(matrix, dtype=np.float64)
    eye = m[:3, 3]
    forward = -m[:3, 2] / np.linalg.norm(m[:3, 2])
    right = np.cross(forward, m[:3, 1])
    right /= np.linalg.norm(right)
    up = np.cross(right, forward)
    out = np.identity(4)
    out[:3, 0], out[:3, 1], out[:3, 2], out[:3, 3] = right, up, -forward, eye
    return out


def is_float_noise(a, b):
    """Whether two matrices differ by no more than Blender's float rounding."""
    return np.abs(a - b).max() <= FLOAT_NOISE * max(1.0, np.abs(b).max())


# Materials: the Principled BSDF stands for the Phong material with the glTF
# writer's numbers (libscene/formats/gltf/gltf_mapping.cpp; docs/GLTF.md,
# "Materials"), so that a mirror imports as a mirror and glass as glass.
# The renderer adds the diffuse colour d and a sharp share g (REFLECTIVITY
# decoded, or TRANSPARENCY); the BSDF blends one base colour min(d + g, 1)
# by f = g / (max(d) + g) between its diffuse and its metal or transmission.
# blender/tests/materials_check.py holds both directions to the glTF
# writer's and reader's numbers.
def _sharp_weight(material):
    if material.transparency > 0.0:
        return min(1.0, material.transparency)
    return srgb_to_linear(_unit(material.reflectivity))


def _unit(value):
    return min(1.0, max(0.0, float(value)))


def principled_inputs(material):
    """The Principled BSDF's inputs for a scenefile.Material."""
    lit = _unit(material.ambient + material.diffuse)
    g = _sharp_weight(material)
    diffuse = [_unit(c) * lit for c in material.colour]
    largest = max(diffuse)
    sharp = g / (largest + g) if largest + g > 0.0 else 0.0
    roughness = (1.0 - sharp) * (2.0 / (material.shininess + 2.0)) ** 0.25
    return {
        "Base Color": tuple(min(d + g, 1.0) for d in diffuse) + (1.0,),
        "Roughness": _unit(roughness),
        "Metallic": 0.0 if material.transparency > 0.0 else sharp,
        "Transmission": sharp if material.transparency > 0.0 else 0.0,
        "IOR": max(material.ri, 1.0),
        "Specular": _unit(material.specular * SPECULAR_SCALE),
    }


def material_values(inputs):
    """The Phong values {property: value} that the Principled inputs stand
    for (principled_inputs' inverse, the glTF reader's)."""
    metallic, transmission = _unit(inputs["Metallic"]), _unit(inputs["Transmission"])
    sharp = max(metallic, transmission)
    base = [float(c) for c in list(inputs["Base Color"])[:3]]
    g = sharp * max(base + [0.0])
    roughness = _unit(inputs["Roughness"])
    if sharp < 1.0:
        roughness = min(roughness / (1.0 - sharp), 1.0)
    r4 = roughness ** 4
    shininess = 2.0 / r4 - 2.0 if r4 > 0.0 else 1e6
    return {
        "colour": tuple(max(c - g, 0.0) for c in base),
        "reflectivity": 0.0 if transmission > 0.0 else linear_to_srgb(min(g, 1.0)),
        "transparency": min(g, 1.0) if transmission > 0.0 else 0.0,
        "shininess": min(1e6, max(1.0, shininess)),
        "ri": max(float(inputs["IOR"]), 1.0),
        "specular": min(1.0, float(inputs["Specular"]) / SPECULAR_SCALE),
    }


# Lights: a Blender point light of P watts lights a surface of albedo a,
# square to it d away, with radiance a P / (4 pi^2 d^2) in Cycles; sfrender
# shows a COLOUR c as the display value a c (the diffuse term, 0.9, aside).
# So P is chosen to make that radiance the sRGB decoding of 0.8 c at the
# reference distance, the glTF writer's rule in watts.
def light_power(colour, distance):
    """(Blender colour, watts) for a LIGHT colour at the reference distance."""
    linear = [srgb_to_linear(REFERENCE_ALBEDO * c) for c in colour]
    peak = max(linear)
    if peak <= 0.0:
        return (0.0, 0.0, 0.0), 0.0
    watts = peak * 4.0 * math.pi ** 2 * distance ** 2 / REFERENCE_ALBEDO
    return tuple(x / peak for x in linear), watts


def light_colour(blender_colour, watts, distance):
    """The LIGHT colour that a Blender point light stands for (light_power's inverse)."""
    scale = REFERENCE_ALBEDO * watts / (4.0 * math.pi ** 2 * distance ** 2)
    return tuple(linear_to_srgb(scale * float(c)) / REFERENCE_ALBEDO for c in blender_colour)


def reference_point(scene):
    """Where lights are matched: the centre of the objects' places (solids
    first), else the camera's eye."""
    solids = [o.matrix[:3, 3] for o in scene.objects if o.kind.value != "PLANE"]
    places = solids or [o.matrix[:3, 3] for o in scene.objects]
    if not places:
        return np.asarray(scene.camera.eye)
    return np.mean(places, axis=0)


def reference_distance(position, point):
    distance = float(np.linalg.norm(np.asarray(position) - np.asarray(point)))
    return distance if distance > 1e-6 else 1.0


def plane_half_size(scene):
    """The half-size of the square that shows each PLANE: the farthest that
    the camera, a light, a corner of an object's box or a plane's origin
    lies from any plane's origin along its sides, rounded up to a power of
    two, 1 to 1e30 (the glTF writer's rule)."""
    points = [np.asarray(scene.camera.eye)] + [np.asarray(l.position) for l in scene.lights]
    corners = np.array([[x, y, z, 1.0] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)])
    for o in scene.objects:
        if o.kind.value == "PLANE":
            points.append(o.matrix[:3, 3])
        else:
            points.extend((corners @ o.matrix.T)[:, :3])
    farthest = 1.0
    for o in scene.objects:
        if o.kind.value != "PLANE":
            continue
        try:
            inverse = np.linalg.inv(o.matrix)
        except np.linalg.LinAlgError:
            continue
        for p in points:
            local = inverse @ np.append(p, 1.0)
            farthest = max(farthest, abs(local[0]), abs(local[2]))
    if not math.isfinite(farthest):
        return 1e30
    return min(1e30, 2.0 ** math.ceil(math.log2(farthest)))


def vertical_fov(lens, sensor_width, sensor_height, sensor_fit, width, height):
    """A Blender camera's vertical field of view in degrees, for an image of
    width x height pixels."""
    if sensor_fit == "VERTICAL":
        return math.degrees(2.0 * math.atan(sensor_height / (2.0 * lens)))
    half = math.atan(sensor_width / (2.0 * lens))
    if sensor_fit == "HORIZONTAL" or width >= height:
        return math.degrees(2.0 * math.atan(math.tan(half) * height / width))
    return math.degrees(2.0 * half)


def mesh_hash(positions, triangles):
    """A fingerprint of a mesh's vertices and triangles, to tell an edited mesh."""
    digest = hashlib.sha1()
    digest.update(np.ascontiguousarray(positions, dtype=np.float32).tobytes())
    digest.update(np.ascontiguousarray(triangles, dtype=np.uint32).tobytes())
    return digest.hexdigest()
