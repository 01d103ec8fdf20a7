#!/usr/bin/env python3
"""Writes testdata/gltf/ (glTF files from "other programs") and
testdata/gltf-hostile/ (malformed and malicious glTF and GLB files).

Run from anywhere; the output is deterministic. Each file's expected
diagnostics sit beside it (NAME.expect), written by hand after reading what
sfcheck says: a new file here needs its .expect too.
"""
import base64
import json
import math
import os
import struct
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent / "testdata"


def write(relative, data):
    path = ROOT / relative
    path.parent.mkdir(parents=True, exist_ok=True)
    if isinstance(data, str):
        data = data.encode()
    path.write_bytes(data)


def buffer_of(*parts):
    """Concatenates packed parts, each padded to 4 bytes; returns the bytes
    and the (offset, length) of each part."""
    out = b""
    spans = []
    for part in parts:
        out += b"\0" * ((4 - len(out) % 4) % 4)
        spans.append((len(out), len(part)))
        out += part
    return out, spans


def floats(values):
    return struct.pack("<%df" % len(values), *values)


def ushorts(values):
    return struct.pack("<%dH" % len(values), *values)


def mesh_gltf(positions, indices, nodes=None, extra=None, uri=None):
    """A glTF with one mesh (POSITION and indices) on one node."""
    flat = [c for p in positions for c in p]
    data, spans = buffer_of(floats(flat), ushorts(indices))
    lo = [min(p[i] for p in positions) for i in range(3)]
    hi = [max(p[i] for p in positions) for i in range(3)]
    doc = {
        "asset": {"version": "2.0", "generator": "make-gltf-testdata.py"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": nodes or [{"name": "shape", "mesh": 0}],
        "meshes": [{"name": "shape", "primitives": [
            {"attributes": {"POSITION": 0}, "indices": 1}]}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": len(positions), "type": "VEC3",
             "min": lo, "max": hi},
            {"bufferView": 1, "componentType": 5123, "count": len(indices), "type": "SCALAR"},
        ],
        "bufferViews": [
            {"buffer": 0, "byteOffset": spans[0][0], "byteLength": spans[0][1]},
            {"buffer": 0, "byteOffset": spans[1][0], "byteLength": spans[1][1]},
        ],
        "buffers": [{"byteLength": len(data), "uri": uri or (
            "data:application/octet-stream;base64," + base64.b64encode(data).decode())}],
    }
    for key, value in (extra or {}).items():
        doc[key] = value
    return doc


def text(doc):
    return json.dumps(doc, indent=1) + "\n"


def glb(json_bytes, bin_bytes=None, version=2, length=None, json_type=b"JSON"):
    json_bytes += b" " * ((4 - len(json_bytes) % 4) % 4)
    body = struct.pack("<I", len(json_bytes)) + json_type + json_bytes
    if bin_bytes is not None:
        bin_bytes += b"\0" * ((4 - len(bin_bytes) % 4) % 4)
        body += struct.pack("<I", len(bin_bytes)) + b"BIN\0" + bin_bytes
    total = 12 + len(body) if length is None else length
    return b"glTF" + struct.pack("<II", version, total) + body


TRIANGLE = [(0, 0, 0), (1, 0, 0), (0, 1, 0)]


def cube():
    positions = []
    indices = []
    for axis in range(3):
        for sign in (1, -1):
            n = [0, 0, 0]
            n[axis] = sign
            u = [0, 0, 0]
            u[(axis + 1) % 3] = 1
            v = [n[1] * u[2] - n[2] * u[1], n[2] * u[0] - n[0] * u[2], n[0] * u[1] - n[1] * u[0]]
            first = len(positions)
            for a, b in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
                positions.append(tuple(n[i] + a * u[i] + b * v[i] for i in range(3)))
            indices += [first, first + 1, first + 2, first, first + 2, first + 3]
    return positions, indices


def torus(rings=24, sides=12, major=1.0, minor=0.3):
    positions = []
    for i in range(rings):
        a = 2 * math.pi * i / rings
        for j in range(sides):
            b = 2 * math.pi * j / sides
            r = major + minor * math.cos(b)
            positions.append((r * math.cos(a), minor * math.sin(b), -r * math.sin(a)))
    indices = []
    for i in range(rings):
        for j in range(sides):
            p = i * sides + j
            q = ((i + 1) % rings) * sides + j
            p1 = i * sides + (j + 1) % sides
            q1 = ((i + 1) % rings) * sides + (j + 1) % sides
            indices += [p, q, q1, p, q1, p1]
    return positions, indices


def uv_sphere(segments=16, rings=8):
    positions = [(0, 1, 0)]
    for r in range(1, rings):
        t = math.pi * r / rings
        for s in range(segments):
            p = 2 * math.pi * s / segments
            positions.append((math.sin(t) * math.cos(p), math.cos(t), -math.sin(t) * math.sin(p)))
    positions.append((0, -1, 0))
    bottom = len(positions) - 1
    ring = lambda r, s: 1 + (r - 1) * segments + s % segments
    indices = []
    for s in range(segments):
        indices += [0, ring(1, s), ring(1, s + 1)]
    for r in range(1, rings - 1):
        for s in range(segments):
            indices += [ring(r, s), ring(r + 1, s), ring(r + 1, s + 1),
                        ring(r, s), ring(r + 1, s + 1), ring(r, s + 1)]
    for s in range(segments):
        indices += [bottom, ring(rings - 1, s + 1), ring(rings - 1, s)]
    return positions, indices


def third_party():
    """Valid files of the kind other programs write: each converts, with the
    losses it has reported."""
    camera = {"type": "perspective", "perspective": {"yfov": 0.6, "znear": 0.1}}
    light_ext = lambda i: {"KHR_lights_punctual": {"light": i}}

    # A torus is no primitive; the sphere beside it is.
    tp, ti = torus()
    sp, si = uv_sphere()
    data, spans = buffer_of(floats([c for p in tp for c in p]), ushorts(ti),
                            floats([c for p in sp for c in p]), ushorts(si))
    doc = {
        "asset": {"version": "2.0"},
        "scenes": [{"nodes": [0, 1, 2]}],
        "nodes": [{"name": "Donut", "mesh": 0},
                  {"name": "Ball", "mesh": 1, "translation": [3, 0, 0], "scale": [2, 2, 2]},
                  {"name": "Eye", "camera": 0, "translation": [0, 1, 10]}],
        "cameras": [camera],
        "meshes": [{"name": "Torus", "primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]},
                   {"name": "UVSphere", "primitives": [
                       {"attributes": {"POSITION": 2}, "indices": 3}]}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": len(tp), "type": "VEC3"},
            {"bufferView": 1, "componentType": 5123, "count": len(ti), "type": "SCALAR"},
            {"bufferView": 2, "componentType": 5126, "count": len(sp), "type": "VEC3"},
            {"bufferView": 3, "componentType": 5123, "count": len(si), "type": "SCALAR"}],
        "bufferViews": [{"buffer": 0, "byteOffset": o, "byteLength": n} for o, n in spans],
        "buffers": [{"byteLength": len(data), "uri": "torus-and-sphere.bin"}],
    }
    write("gltf/torus-and-sphere.gltf", text(doc))
    write("gltf/torus-and-sphere.bin", data)

    # Spot and directional lights are approximated; a second camera is
    # ignored; a node hierarchy with TRS and matrix transforms.
    cp, ci = cube()
    doc = mesh_gltf(cp, ci, nodes=[
        {"name": "Rig", "translation": [1, 2, 3], "rotation": [0, 0.3826834, 0, 0.9238795],
         "scale": [2, 1, 1], "children": [1, 2]},
        {"name": "Box", "mesh": 0, "matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0.5, 0, 1]},
        {"name": "Lamp", "translation": [0, 4, 0], "extensions": light_ext(0)},
        {"name": "Spot", "translation": [2, 4, 0], "extensions": light_ext(1)},
        {"name": "Sun", "rotation": [-0.7071068, 0, 0, 0.7071068], "extensions": light_ext(2)},
        {"name": "Camera", "camera": 0, "translation": [0, 2, 12]},
        {"name": "Other camera", "camera": 0, "translation": [5, 2, 12]},
    ], extra={
        "extensionsUsed": ["KHR_lights_punctual"],
        "extensions": {"KHR_lights_punctual": {"lights": [
            {"type": "point", "color": [1, 0.5, 0.25], "intensity": 4},
            {"type": "spot", "intensity": 2, "spot": {"outerConeAngle": 0.5}},
            {"type": "directional", "intensity": 1.5}]}},
        "cameras": [camera],
        "materials": [{"name": "Painted", "pbrMetallicRoughness": {
            "baseColorFactor": [0.8, 0.4, 0.2, 1], "metallicFactor": 0, "roughnessFactor": 0.5}}],
    })
    doc["scenes"] = [{"nodes": [0, 3, 4, 5, 6]}]
    doc["meshes"][0]["primitives"][0]["material"] = 0
    write("gltf/hierarchy-lights-cameras.gltf", text(doc))

    # No camera and no scene: every root node is read, and CAMERA is made.
    # The image names a file outside the folder, but images are never read.
    doc = mesh_gltf(cp, ci, extra={
        "images": [{"uri": "../../../../etc/passwd"}],
        "textures": [{"source": 0}],
        "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}]})
    del doc["scene"], doc["scenes"]
    doc["meshes"][0]["primitives"][0]["material"] = 0
    write("gltf/no-camera-image-outside.gltf", text(doc))


def edited_elsewhere():
    """A file sfconvert wrote, whose cube was then moved in another program:
    the extras no longer match, so the node is read as it is."""
    cp, ci = cube()
    identity = [[1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0],
                [0.0, 0.0, 0.0, 1.0]]
    doc = mesh_gltf(cp, ci, nodes=[
        {"name": "CUBE 1", "translation": [0, 1, 0], "mesh": 0,
         "extras": {"sf": {"record": "CUBE", "matrix": identity}}},
        {"name": "CAMERA", "camera": 0, "matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 5, 1],
         "extras": {"sf": {"record": "CAMERA", "colour": [0.0, 0.0, 0.0],
                           "matrix": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 5], [0, 0, 0, 1]]}}}],
        extra={"cameras": [{"type": "perspective",
                            "perspective": {"yfov": 1.0471975511965976, "znear": 0.01}}]})
    doc["scenes"] = [{"nodes": [0, 1]}]
    write("gltf/edited-elsewhere.gltf", text(doc))


def hostile():
    """Malformed and malicious files: each is rejected with a clear error."""
    h = "gltf-hostile/"
    # JSON.
    write(h + "truncated-json.gltf", '{\n  "asset": {"version": "2.0"},\n  "nodes": [\n')
    write(h + "deep-nesting.gltf",
          '{"asset": {"version": "2.0"}, "extras": ' + "[" * 100000 + "]" * 100000 + "}\n")
    write(h + "version-1.gltf", text({"asset": {"version": "1.0"}}))
    write(h + "no-asset.gltf", text({"nodes": [{"name": "n"}]}))
    # Files it must not read.
    for name, uri in (("absolute-uri", "/etc/passwd"), ("parent-uri", "../../../../etc/passwd"),
                      ("encoded-parent-uri", "%2e%2e/%2e%2e/%2e%2e/etc/passwd"),
                      ("remote-uri", "https://example.com/model.bin"),
                      ("file-scheme-uri", "file:///etc/passwd"),
                      ("missing-buffer-file", "no-such-file.bin"),
                      ("symlink-out-of-folder", "outside.bin")):
        write(h + name + ".gltf", text(mesh_gltf(TRIANGLE, [0, 1, 2], uri=uri)))
    link = ROOT / h / "outside.bin"
    if link.is_symlink() or link.exists():
        link.unlink()
    os.symlink("/etc/passwd", link)
    write(h + "required-draco.gltf", text(mesh_gltf(TRIANGLE, [0, 1, 2], extra={
        "extensionsUsed": ["KHR_draco_mesh_compression"],
        "extensionsRequired": ["KHR_draco_mesh_compression"]})))
    # Structure.
    write(h + "node-cycle.gltf", text(mesh_gltf(TRIANGLE, [0, 1, 2], nodes=[
        {"name": "a", "children": [1]}, {"name": "b", "children": [0]}])))
    write(h + "node-two-parents.gltf", text(dict(mesh_gltf(TRIANGLE, [0, 1, 2], nodes=[
        {"name": "a", "children": [2]}, {"name": "b", "children": [2]}, {"name": "c"}]),
        scenes=[{"nodes": [0, 1]}])))
    write(h + "scene-node-out-of-range.gltf", text(dict(mesh_gltf(TRIANGLE, [0, 1, 2]),
                                                        scenes=[{"nodes": [7]}])))
    write(h + "mesh-out-of-range.gltf", text(mesh_gltf(TRIANGLE, [0, 1, 2], nodes=[
        {"name": "n", "mesh": 3}])))
    doc = mesh_gltf(TRIANGLE, [0, 1, 2])
    doc["accessors"][0]["bufferView"] = 9
    write(h + "accessor-view-out-of-range.gltf", text(doc))
    # Data.
    doc = mesh_gltf(TRIANGLE, [0, 1, 2])
    doc["accessors"][0]["count"] = 1000
    write(h + "accessor-past-view.gltf", text(doc))
    doc = mesh_gltf(TRIANGLE, [0, 1, 2])
    doc["bufferViews"][1]["byteLength"] = 4000
    write(h + "view-past-buffer.gltf", text(doc))
    doc = mesh_gltf(TRIANGLE, [0, 1, 2])
    doc["accessors"][0]["count"] = 4000000000
    write(h + "huge-count.gltf", text(doc))
    write(h + "index-out-of-range.gltf", text(mesh_gltf(TRIANGLE, [0, 1, 60000])))
    write(h + "nan-position.gltf", text(mesh_gltf([(0, 0, 0), (1, float("nan"), 0), (0, 1, 0)],
                                                  [0, 1, 2])))
    doc = mesh_gltf(TRIANGLE, [0, 1, 2])
    doc["accessors"][0]["componentType"] = 5123
    write(h + "position-not-float.gltf", text(doc))
    doc = mesh_gltf(TRIANGLE, [0, 1, 2])
    doc["bufferViews"][0]["byteStride"] = 4
    write(h + "stride-too-small.gltf", text(doc))
    doc = mesh_gltf(TRIANGLE, [0, 1, 2])
    doc["buffers"][0]["byteLength"] += 64
    write(h + "base64-shorter-than-byte-length.gltf", text(doc))
    cp, ci = cube()
    doc = mesh_gltf(cp, ci, nodes=[{"name": "flat", "mesh": 0, "scale": [1, 0, 1]}])
    write(h + "zero-scale-node.gltf", text(doc))
    # GLB containers.
    good = json.dumps(mesh_gltf(TRIANGLE, [0, 1, 2])).encode()
    write(h + "glb-header-cut.glb", b"glTF\x02\x00")
    write(h + "glb-version-1.glb", glb(good, version=1))
    write(h + "glb-length-mismatch.glb", glb(good, length=1 << 20))
    chunk = glb(good)
    write(h + "glb-chunk-too-long.glb", chunk[:12] + struct.pack("<I", 0x7FFFFFF0) + chunk[16:])
    write(h + "glb-first-chunk-not-json.glb", glb(good, json_type=b"BIN\0"))
    write(h + "glb-bad-json.glb", glb(b'{"asset": {"version": "2.0"}, "nodes": [}'))
    doc = mesh_gltf(TRIANGLE, [0, 1, 2])
    del doc["buffers"][0]["uri"]
    data = base64.b64decode(mesh_gltf(TRIANGLE, [0, 1, 2])["buffers"][0]["uri"].split(",")[1])
    doc["buffers"][0]["byteLength"] = len(data) + 1000
    write(h + "glb-bin-shorter-than-buffer.glb", glb(json.dumps(doc).encode(), data))


def scene_gltf():
    """A valid glTF of a cube, a camera and a point light, for the files
    below that change one value of it."""
    cp, ci = cube()
    doc = mesh_gltf(cp, ci, nodes=[
        {"name": "Box", "mesh": 0},
        {"name": "Eye", "camera": 0, "translation": [0, 1, 10]},
        {"name": "Lamp", "translation": [5, 5, 5],
         "extensions": {"KHR_lights_punctual": {"light": 0}}}])
    doc["scenes"] = [{"nodes": [0, 1, 2]}]
    doc["cameras"] = [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1}}]
    doc["extensionsUsed"] = ["KHR_lights_punctual"]
    doc["extensions"] = {"KHR_lights_punctual": {"lights": [
        {"type": "point", "color": [1, 1, 1], "intensity": 2}]}}
    return doc


def changed(doc, path, value):
    """A copy of doc with the value at path (a list of keys and indices)
    set, or removed when value is DELETE."""
    doc = json.loads(json.dumps(doc))
    at = doc
    for key in path[:-1]:
        at = at[key]
    if value is DELETE:
        del at[path[-1]]
    else:
        at[path[-1]] = value
    return doc


DELETE = object()


def hardening():
    """Indices of the wrong type or range, meshes without primitives, and
    values that glTF bounds (docs/GLTF.md, "Hostile files"): errors at the
    JSON pointer of the value, in testdata/gltf-hostile/; what a scene file
    cannot hold is a loss, in testdata/gltf/."""
    h = "gltf-hostile/"
    base = scene_gltf()
    light = ["extensions", "KHR_lights_punctual", "lights", 0]
    errors = {
        "index-node-mesh-negative": (["nodes", 0, "mesh"], -1),
        "index-node-mesh-fraction": (["nodes", 0, "mesh"], 0.5),
        "index-node-mesh-string": (["nodes", 0, "mesh"], "0"),
        "index-node-mesh-null": (["nodes", 0, "mesh"], None),
        "index-node-mesh-2-pow-32": (["nodes", 0, "mesh"], 4294967296),
        "index-scene-nodes-string": (["scenes", 0, "nodes", 1], "1"),
        "index-scene-nodes-negative": (["scenes", 0, "nodes", 2], -3),
        "index-children-fraction": (["nodes", 1, "children"], [2.5]),
        "index-position-negative": (["meshes", 0, "primitives", 0, "attributes", "POSITION"], -1),
        "index-indices-null": (["meshes", 0, "primitives", 0, "indices"], None),
        "index-light-string": (["nodes", 2, "extensions", "KHR_lights_punctual", "light"], "0"),
        "index-material-beyond-2-pow-32": (["meshes", 0, "primitives", 0, "material"],
                                           2 ** 32 + 1),
        "mesh-primitives-empty": (["meshes", 0, "primitives"], []),
        "mesh-primitives-missing": (["meshes", 0, "primitives"], DELETE),
        "camera-yfov-zero": (["cameras", 0, "perspective", "yfov"], 0),
        "camera-yfov-negative": (["cameras", 0, "perspective", "yfov"], -0.5),
        "camera-aspect-ratio-zero": (["cameras", 0, "perspective", "aspectRatio"], 0),
        "light-intensity-negative": (light + ["intensity"], -2),
        "light-range-zero": (light + ["range"], 0),
        "light-colour-times-intensity-overflows": (light + ["color"], [2, 1, 1]),
        "material-emission-above-one": (["materials"], [{"emissiveFactor": [2, 0, 0]}]),
    }
    for name, (path, value) in errors.items():
        doc = changed(base, path, value)
        if name == "light-colour-times-intensity-overflows":
            doc = changed(doc, light + ["intensity"], 1e308)
        if name == "material-emission-above-one":
            doc = changed(doc, ["meshes", 0, "primitives", 0, "material"], 0)
        write(h + name + ".gltf", text(doc))
    # In a GLB the JSON chunk has no lines: the pointer alone says where.
    write(h + "glb-index-node-mesh-string.glb",
          glb(json.dumps(changed(base, ["nodes", 0, "mesh"], "0")).encode()))
    # Finite scales whose product is not.
    doc = changed(base, ["nodes", 0, "scale"], [1e200, 1e200, 1e200])
    doc["nodes"].append({"name": "Big", "scale": [1e200, 1e200, 1e200], "children": [0]})
    doc["scenes"][0]["nodes"] = [3, 1, 2]
    write(h + "node-scale-composed-overflows.gltf", text(doc))
    # Losses: valid files whose values a scene file cannot hold.
    lossy = changed(base, ["cameras", 0, "perspective", "aspectRatio"], 1.5)
    lossy = changed(lossy, light + ["range"], 20)
    lossy = changed(lossy, ["materials"], [{"name": "glow", "emissiveFactor": [1, 0.5, 0]}])
    lossy = changed(lossy, ["meshes", 0, "primitives", 0, "material"], 0)
    write("gltf/emission-aspect-ratio-range.gltf", text(lossy))
    write("gltf/camera-yfov-above-pi.gltf",
          text(changed(base, ["cameras", 0, "perspective", "yfov"], 3.5)))
    write("gltf/camera-yfov-tiny.gltf",
          text(changed(base, ["cameras", 0, "perspective", "yfov"], 1e-9)))
    own_edited()


def own_edited():
    """Our own file (sfconvert testdata/valid/all-primitives.sf, kept as
    gltf/own-all-primitives.gltf) with the SPHERE's node pointed at the
    CUBE's mesh: its extras still say SPHERE, and are stale."""
    own = ROOT / "gltf" / "own-all-primitives.gltf"
    if not own.exists():
        return
    doc = json.loads(own.read_text())
    names = [n.get("name", "") for n in doc["nodes"]]
    sphere = next(i for i, n in enumerate(names) if n.startswith("SPHERE"))
    cube_node = next(i for i, n in enumerate(names) if n.startswith("CUBE"))
    doc["nodes"][sphere]["mesh"] = doc["nodes"][cube_node]["mesh"]
    write("gltf/own-sphere-on-cube-mesh.gltf", text(doc))


def node_transforms():
    """A node's matrix, translation, rotation or scale of the wrong type or
    shape, a matrix beside TRS, a rotation that is not a unit quaternion:
    errors at the node's property, never a node silently at the origin."""
    h = "gltf-hostile/"
    base = scene_gltf()
    box = ["nodes", 0]
    cases = {
        "node-translation-string": {"translation": ["1", 0, 0]},
        "node-translation-object": {"translation": {"x": 5}},
        "node-translation-two": {"translation": [1, 2]},
        "node-matrix-boolean": {"matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, True]},
        "node-matrix-fifteen": {"matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0]},
        "node-matrix-and-translation": {"matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0,
                                                   0, 0, 0, 1], "translation": [3, 0, 0]},
        "node-rotation-zero": {"rotation": [0, 0, 0, 0]},
        "node-rotation-length-two": {"rotation": [0, 0, 0, 2]},
        "node-rotation-null": {"rotation": None},
        "node-scale-null-element": {"scale": [1, None, 1]},
        "node-scale-nested": {"scale": [[1], 1, 1]},
    }
    for name, values in cases.items():
        doc = base
        for key, value in values.items():
            doc = changed(doc, box + [key], value)
        write(h + name + ".gltf", text(doc))
    write(h + "glb-node-rotation-zero.glb",
          glb(json.dumps(changed(base, box + ["rotation"], [0, 0, 0, 0])).encode()))


def main():
    third_party()
    edited_elsewhere()
    hostile()
    hardening()
    node_transforms()


if __name__ == "__main__":
    main()
