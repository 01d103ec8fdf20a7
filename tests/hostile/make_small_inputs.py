#!/usr/bin/env python3
"""Writes the committed part of testdata/hostile/: small hostile inputs in
the four formats sfcheck reads. Deterministic; run from anywhere. The big
inputs are not written here but at test time by make_big_inputs.sh.

Each input's expected diagnostics (NAME.expect beside it) were written after
reading what sfcheck says about it: a new input here needs its .expect too.
"""
import base64
import importlib.util
import json
import random
import struct
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent.parent / "testdata" / "hostile"

# The glTF test-data generator's cube and JSON text, the same as testdata/gltf/
# is made of (its file name has a '-', so it is loaded by path).
_spec = importlib.util.spec_from_file_location(
    "make_gltf_testdata", ROOT.parent.parent / "scripts" / "make-gltf-testdata.py"
)
_gltf_testdata = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(_gltf_testdata)
cube = _gltf_testdata.cube
gltf_text = _gltf_testdata.text


def write(relative, data):
    path = ROOT / relative
    path.parent.mkdir(parents=True, exist_ok=True)
    if isinstance(data, str):
        data = data.encode("latin-1")
    path.write_bytes(data)


IDENTITY = "1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n"
CAMERA = "CAMERA\n0 0 0\n1 0 0 0\n0 1 0 1\n0 0 1 8\n0 0 0 1\n"
LIGHT = "LIGHT\n1 1 1\n1 0 0 5\n0 1 0 5\n0 0 1 5\n0 0 0 1\n"


def sphere(colour="1 0 0", matrix=IDENTITY):
    return "SPHERE\n" + colour + "\n" + matrix


def scene(*records):
    return CAMERA + LIGHT + "".join(records)


HEAD = (
    "OUTPUT_FILE out.ppm\nSTART CAMERA\n  LOCATION 0 1 8\n  LOOK_AT 0 0 0\nEND CAMERA\n"
    "START LIGHT\n  LOCATION 5 5 5\n  COLOUR 1 1 1\nEND LIGHT\n"
)


def instructions(*objects):
    return HEAD + "".join(objects)


def obj(kind="SPHERE", material="    COLOUR 1 0 0\n", transformation="    TRANSLATE 0 0 0\n"):
    return (
        "START OBJECT " + kind + "\n  START MATERIAL\n" + material + "  END MATERIAL\n"
        "  START TRANSFORMATION\n" + transformation + "  END TRANSFORMATION\nEND OBJECT\n"
    )


def make_sf():
    rng = random.Random(8)
    # Binary garbage, NUL bytes, invalid UTF-8.
    write("sf/random-bytes-64k.sf", bytes(rng.randrange(256) for _ in range(65536)))
    write("sf/nul-bytes-only.sf", b"\0" * 4096)
    write("sf/nul-inside-number.sf", scene(sphere("1 0\0 0")))
    write("sf/invalid-utf8-after-record-name.sf", scene("SPHERE\xff\xfe\n1 0 0\n" + IDENTITY))
    write("sf/overlong-utf8-slash.sf", scene(sphere("1 0 \xc0\xaf")))
    write("sf/utf16-bom.sf", b"\xff\xfe" + scene(sphere()).encode("utf-16-le"))
    write(
        "sf/terminal-escape-in-record-name.sf",
        scene("\x1b[2J\x1b]0;owned\x07SPHERE\n1 0 0\n" + IDENTITY),
    )
    # Numbers: 100,000 digits, exponents past any double, NaN and infinity
    # spelled every way.
    write("sf/number-100000-digits.sf", scene(sphere("1 1 " + "7" * 100000)))
    write("sf/number-100000-digit-fraction.sf", scene(sphere("1 1 0." + "0" * 99999 + "1")))
    write(
        "sf/exponent-20-digits.sf",
        scene(sphere("1 1e99999999999999999999 1e-99999999999999999999")),
    )
    write(
        "sf/nan-and-inf-spellings.sf",
        scene(
            sphere("NaN -nan inf"), sphere("Infinity -INF nan(0x1)"), sphere("1.#INF 1.#QNAN 0x1p3")
        ),
    )
    # Scales at the bottom of the doubles, entries at the top: the reader
    # must see the overflow or the singularity, not pass on inf or NaN.
    write(
        "sf/subnormal-scale-1e-320.sf",
        scene(sphere(matrix="1e-320 0 0 0\n0 1e-320 0 0\n0 0 1e-320 0\n0 0 0 1\n")),
    )
    write(
        "sf/entries-1e308-determinant-overflows.sf",
        scene(sphere(matrix="1e308 0 0 0\n0 1e308 0 0\n0 0 1e308 0\n0 0 0 1\n")),
    )
    write(
        "sf/subnormal-times-huge.sf",
        scene(sphere(matrix="1e-310 0 0 0\n0 1e308 0 0\n0 0 4.9e-324 0\n0 0 0 1\n")),
    )
    # Two rows equal once 1 + 1e-17 is rounded to a double: singular only in
    # floating point.
    write(
        "sf/singular-only-in-floating-point.sf",
        scene(sphere(matrix="1 1 0 0\n1 1.00000000000000001 0 0\n0 0 1 0\n0 0 0 1\n")),
    )
    write(
        "sf/camera-zero-matrix.sf",
        "CAMERA\n0 0 0\n0 0 0 0\n0 0 0 0\n0 0 0 0\n0 0 0 1\n" + LIGHT + sphere(),
    )
    write(
        "sf/camera-entries-1e308.sf",
        "CAMERA\n0 0 0\n1e308 0 0 0\n0 1e308 0 0\n0 0 1e308 0\n0 0 0 1\n" + LIGHT + sphere(),
    )
    # Line endings and white space.
    write("sf/cr-only-line-endings.sf", scene(sphere("1 0 -1")).replace("\n", "\r"))
    write(
        "sf/crlf-error-on-last-line.sf",
        scene(sphere(matrix=IDENTITY[:-7] + "0 0 0 2\n")).replace("\n", "\r\n"),
    )
    write("sf/utf8-bom-twice.sf", "\xef\xbb\xbf\xef\xbb\xbf" + scene(sphere()))
    write("sf/tabs-vertical-tabs-form-feeds.sf", scene(sphere("1\t0\x0b0\x0c")))
    # Overlong tokens and repeated records.
    write("sf/newlines-only-100000.sf", "\n" * 100000)


def make_instructions():
    write("instructions/nul-inside-keyword.txt", instructions(obj(material="    COL\0OUR 1 0 0\n")))
    write(
        "instructions/invalid-utf8-output-file.txt",
        instructions(obj()).replace("out.ppm", "\xff\xfe\xc3\x28.ppm"),
    )
    write(
        "instructions/output-file-etc-passwd.txt",
        instructions(obj("TORUS")).replace("out.ppm", "/etc/passwd"),
    )
    write(
        "instructions/output-file-parent-folders.txt",
        instructions(obj("TORUS")).replace("out.ppm", "../../../../tmp/x.ppm"),
    )
    write(
        "instructions/output-file-dev-zero.txt",
        instructions(obj("TORUS")).replace("out.ppm", "/dev/zero"),
    )
    write(
        "instructions/scale-1e308-twice-overflows.txt",
        instructions(
            obj(transformation="    SCALE 1e308 1e308 1e308\n    SCALE 1e308 1e308 1e308\n")
        ),
    )
    write(
        "instructions/scale-subnormal-1e-320.txt",
        instructions(obj(transformation="    SCALE 1e-320 1e-320 1e-320\n")),
    )
    write(
        "instructions/scale-underflows-in-product.txt",
        instructions(
            obj(transformation="    SCALE 1e-200 1e-200 1e-200\n    SCALE 1e-200 1e-200 1e-200\n")
        ),
    )
    write(
        "instructions/rotate-huge-and-infinite-angles.txt",
        instructions(
            obj(transformation="    ROTATE_X 1e308\n    ROTATE_Y -inf\n    ROTATE_Z 1e400\n")
        ),
    )
    write(
        "instructions/number-100000-digits.txt",
        instructions(obj(transformation="    TRANSLATE 1 1 " + "9" * 100000 + "\n")),
    )
    write(
        "instructions/nan-inf-hex-spellings.txt",
        instructions(
            obj(
                material="    COLOUR NaN inf 0x1p-1\n",
                transformation="    TRANSLATE -Infinity 1e+ .e1\n",
            )
        ),
    )
    write(
        "instructions/cr-only-line-endings.txt", instructions(obj(kind="TORUS")).replace("\n", "\r")
    )
    write(
        "instructions/bom-then-crlf-error.txt",
        "\xef\xbb\xbf" + instructions(obj(material="    COLOUR 1 0\n")).replace("\n", "\r\n"),
    )
    write(
        "instructions/camera-location-equals-look-at-huge.txt",
        "OUTPUT_FILE a.ppm\nSTART CAMERA\n  LOCATION 1e308 1e308 1e308\n"
        "  LOOK_AT -1e308 -1e308 -1e308\nEND CAMERA\n" + obj(),
    )
    write(
        "instructions/camera-look-at-1e200-away.txt",
        "OUTPUT_FILE a.ppm\nSTART CAMERA\n  LOCATION 0 0 0\n  LOOK_AT 1e200 1e200 0\nEND CAMERA\n"
        + obj(),
    )
    write(
        "instructions/camera-look-at-subnormal-offset.txt",
        "OUTPUT_FILE a.ppm\nSTART CAMERA\n  LOCATION 0 0 0\n  LOOK_AT 1e-320 0 0\nEND CAMERA\n"
        + obj(),
    )
    write(
        "instructions/terminal-escape-in-keyword.txt",
        instructions(obj(material="    \x1b[31mCOLOUR\x1b[0m 1 0 0\n")),
    )


def gltf_doc(
    uri=None,
    positions=((0, 0, 0), (1, 0, 0), (0, 1, 0)),
    indices=(0, 1, 2),
    count=None,
    index_count=None,
    byte_length=None,
    extra_accessor=None,
    nodes=None,
):
    flat = [c for p in positions for c in p]
    data = struct.pack("<%df" % len(flat), *flat) + struct.pack("<%dH" % len(indices), *indices)
    data += b"\0" * ((4 - len(data) % 4) % 4)
    position_bytes = 12 * len(positions)
    accessors = [
        {
            "bufferView": 0,
            "componentType": 5126,
            "count": len(positions) if count is None else count,
            "type": "VEC3",
            "min": [min(p[i] for p in positions) for i in range(3)],
            "max": [max(p[i] for p in positions) for i in range(3)],
        },
        {
            "bufferView": 1,
            "componentType": 5123,
            "count": len(indices) if index_count is None else index_count,
            "type": "SCALAR",
        },
    ]
    if extra_accessor:
        accessors[1].update(extra_accessor)
    return {
        "asset": {"version": "2.0", "generator": "make_small_inputs.py"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": nodes or [{"name": "shape", "mesh": 0}],
        "meshes": [
            {"name": "shape", "primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}
        ],
        "accessors": accessors,
        "bufferViews": [
            {"buffer": 0, "byteOffset": 0, "byteLength": position_bytes},
            {"buffer": 0, "byteOffset": position_bytes, "byteLength": 2 * len(indices)},
        ],
        "buffers": [
            {
                "byteLength": len(data) if byte_length is None else byte_length,
                "uri": uri
                or "data:application/octet-stream;base64," + base64.b64encode(data).decode(),
            }
        ],
    }


def glb(json_bytes, bin_bytes=b"", json_length=None, bin_length=None, total=None):
    json_bytes += b" " * ((4 - len(json_bytes) % 4) % 4)
    body = (
        struct.pack("<I", len(json_bytes) if json_length is None else json_length)
        + b"JSON"
        + json_bytes
    )
    if bin_bytes or bin_length is not None:
        body += (
            struct.pack("<I", len(bin_bytes) if bin_length is None else bin_length)
            + b"BIN\0"
            + bin_bytes
        )
    return b"glTF" + struct.pack("<II", 2, 12 + len(body) if total is None else total) + body


def make_gltf():
    w = lambda name, doc: write("gltf/" + name, gltf_text(doc))
    w(
        "index-4294967295.gltf",
        dict(
            gltf_doc(),
            accessors=[
                gltf_doc()["accessors"][0],
                {"bufferView": 1, "componentType": 5125, "count": 3, "type": "SCALAR"},
            ],
            bufferViews=[
                {"buffer": 0, "byteOffset": 0, "byteLength": 36},
                {"buffer": 0, "byteOffset": 36, "byteLength": 12},
            ],
            buffers=[
                {
                    "byteLength": 48,
                    "uri": "data:application/octet-stream;base64,"
                    + base64.b64encode(
                        struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0)
                        + struct.pack("<3I", 0, 1, 4294967295)
                    ).decode(),
                }
            ],
        ),
    )
    w("accessor-count-billion.gltf", gltf_doc(count=1000000000))
    w("accessor-count-negative.gltf", gltf_doc(count=-3))
    w("accessor-count-1e308.gltf", gltf_doc(count=1e308))
    w("index-count-lies.gltf", gltf_doc(index_count=3000))
    w("buffer-uri-dev-zero.gltf", gltf_doc(uri="/dev/zero", byte_length=48))
    w(
        "buffer-uri-etc-passwd-parent.gltf",
        gltf_doc(uri="../../../../../../etc/passwd", byte_length=48),
    )
    w("buffer-uri-percent-encoded-dev-zero.gltf", gltf_doc(uri="%2Fdev%2Fzero", byte_length=48))
    w("buffer-uri-proc-self-mem.gltf", gltf_doc(uri="/proc/self/mem", byte_length=48))
    w(
        "data-uri-bad-base64.gltf",
        gltf_doc(uri="data:application/octet-stream;base64,AAAA!!!!====AAAA", byte_length=48),
    )
    w("data-uri-byte-length-2-pow-53.gltf", gltf_doc(byte_length=9007199254740992))
    w(
        "buffer-view-offset-2-pow-64.gltf",
        dict(
            gltf_doc(),
            bufferViews=[
                {"buffer": 0, "byteOffset": 18446744073709551615, "byteLength": 36},
                {"buffer": 0, "byteOffset": 36, "byteLength": 6},
            ],
        ),
    )
    w(
        "buffer-view-offset-wraps.gltf",
        dict(
            gltf_doc(),
            bufferViews=[
                {"buffer": 0, "byteOffset": 18446744073709551600, "byteLength": 52},
                {"buffer": 0, "byteOffset": 36, "byteLength": 6},
            ],
        ),
    )
    w("component-type-bogus.gltf", gltf_doc(extra_accessor={"componentType": 7}))
    w(
        "node-matrix-1e308.gltf",
        gltf_doc(
            positions=cube()[0],
            indices=cube()[1],
            nodes=[
                {
                    "name": "shape",
                    "mesh": 0,
                    "matrix": [1e308, 0, 0, 0, 0, 1e308, 0, 0, 0, 0, 1e308, 0, 0, 0, 0, 1],
                }
            ],
        ),
    )
    w(
        "node-scale-subnormal.gltf",
        gltf_doc(
            positions=cube()[0],
            indices=cube()[1],
            nodes=[{"name": "shape", "mesh": 0, "scale": [1e-320, 1e-320, 1e-320]}],
        ),
    )
    w("node-children-self.gltf", gltf_doc(nodes=[{"name": "shape", "mesh": 0, "children": [0]}]))
    # Names are echoed in messages: escape sequences must not reach the
    # terminal, and a name of 20,000 characters must not fill it.
    w(
        "node-name-terminal-escape.gltf",
        gltf_doc(
            nodes=[{"name": "\x1b]0;owned\x07\x1b[2J\x1b[31mevil\x7f", "mesh": 0, "children": [0]}]
        ),
    )
    w(
        "node-name-20000-euro-signs.gltf",
        gltf_doc(nodes=[{"name": "\u20ac" * 20000, "mesh": 0, "children": [0]}]),
    )
    write("gltf/json-number-1e400.gltf", gltf_text(gltf_doc(count=12345)).replace("12345", "1e400"))
    write(
        "gltf/json-invalid-utf8-name.gltf",
        gltf_text(gltf_doc()).replace('"shape"', '"sh\xff\xfeape"', 1),
    )
    write(
        "gltf/json-duplicate-keys.gltf",
        '{"asset": {"version": "2.0"}, "asset": {"version": "1.0"}, "scenes": []}\n',
    )
    write(
        "gltf/json-array-nesting-100000.gltf",
        '{"asset": {"version": "2.0"}, "extras": ' + "[" * 100000 + "]" * 100000 + "}\n",
    )
    doc = json.dumps(gltf_doc(uri=None)).encode()
    flat = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0) + struct.pack("<3H", 0, 1, 2) + b"\0\0"
    bin_doc = gltf_doc()
    del bin_doc["buffers"][0]["uri"]
    bin_json = json.dumps(bin_doc).encode()
    write("gltf/glb-bin-length-4294967295.glb", glb(bin_json, flat, bin_length=0xFFFFFFFF))
    write("gltf/glb-json-length-4294967295.glb", glb(bin_json, flat, json_length=0xFFFFFFFF))
    write("gltf/glb-total-length-zero.glb", glb(bin_json, flat, total=0))
    write("gltf/glb-total-length-4294967295.glb", glb(bin_json, flat, total=0xFFFFFFFF))
    write("gltf/glb-json-length-zero.glb", glb(bin_json, flat, json_length=0))
    write(
        "gltf/glb-magic-then-garbage.glb",
        b"glTF" + bytes(random.Random(3).randrange(256) for _ in range(4096)),
    )
    write(
        "gltf/glb-bin-uri-dev-zero.glb",
        glb(json.dumps(gltf_doc(uri="/dev/zero", byte_length=48)).encode(), flat),
    )
    del doc


def make_pov():
    cam = "camera { location <0, 1, -5> look_at 0 }\nlight_source { <5, 5, -5> color rgb 1 }\n"
    write("pov/include-etc-passwd.pov", '#include "/etc/passwd"\n' + cam + "sphere { 0, 1 }\n")
    write("pov/include-parent-etc-passwd.pov", '#include "../../../../../../etc/passwd"\n' + cam)
    write("pov/include-dev-zero.pov", '#include "/dev/zero"\n' + cam)
    # A name that would drive the terminal and is not UTF-8: shown as \xNN.
    write(
        "pov/include-name-terminal-escape.pov",
        b'#include "a\x1b[31mb\xff\xc3\xa9.inc"\ncamera { location <0, 1, -5> look_at 0 }\n',
    )
    write(
        "pov/include-concat-built-name.pov",
        '#declare F = concat("/etc/", "passwd")\n#include F\n' + cam,
    )
    write("pov/fopen-dev-zero.pov", cam + '#fopen In "/dev/zero" read\n#read (In, X)\n')
    write(
        "pov/recursive-macro.pov",
        cam + "#macro Boom(N)\n  sphere { 0, 1 }\n  Boom(N + 1)\n#end\nBoom(0)\n",
    )
    write(
        "pov/mutually-recursive-macros.pov",
        cam + "#macro Ping(N)\n  Pong(N)\n#end\n#macro Pong(N)\n  Ping(N)\n#end\nPing(0)\n",
    )
    write("pov/while-true.pov", cam + "#while (1)\n#end\n")
    write(
        "pov/while-counter-runs-away.pov",
        cam + "#declare I = 1;\n#while (I > 0)\n  #declare I = I + 1;\n#end\n",
    )
    write(
        "pov/while-spawns-spheres.pov",
        cam + "#declare I = 0;\n#while (I < 1e9)\n  sphere { <I, 0, 0>, 0.5 }\n"
        "  #declare I = I + 1;\n#end\n",
    )
    write("pov/for-billion.pov", cam + "#for (I, 0, 1e9)\n  sphere { <I, 0, 0>, 0.5 }\n#end\n")
    write("pov/braces-nested-100000.pov", cam + "union {\n" + "{" * 100000 + "}" * 100000 + "\n}\n")
    write(
        "pov/union-nested-10000.pov",
        cam + "union { " * 10000 + "sphere { 0, 1 }" + " }" * 10000 + "\n",
    )
    write(
        "pov/declare-chain-10000.pov",
        cam
        + "#declare A0 = 10;\n"
        + "".join("#declare A%d = A%d * A%d;\n" % (i + 1, i, i) for i in range(10000))
        + "sphere { 0, A10000 }\n",
    )
    write(
        "pov/string-doubling.pov",
        cam + '#declare S = "ab";\n#declare I = 0;\n#while (I < 64)\n  #declare S = concat(S, S);\n'
        "  #declare I = I + 1;\n#end\n",
    )
    write("pov/number-1e400.pov", cam + "sphere { <1e400, 0, 0>, 1 }\n")
    write("pov/number-100000-digits.pov", cam + "sphere { <" + "9" * 100000 + ", 0, 0>, 1 }\n")
    write("pov/nul-bytes.pov", cam + "sphere { 0,\0 1 }\n")
    write(
        "pov/invalid-utf8-string.pov",
        cam + '#declare S = "\xff\xfe\xc0\xaf";\nsphere { 0, 1 }\n#error S\n',
    )
    write("pov/unterminated-comment.pov", cam + "sphere { 0, 1 }\n/* never closed\n" + "x " * 1000)
    write("pov/unterminated-string.pov", cam + '#declare S = "never closed\nsphere { 0, 1 }\n')
    write("pov/nested-comments-10000.pov", cam + "/*" * 10000 + "*/" * 9999 + "\nsphere { 0, 1 }\n")
    write(
        "pov/matrix-1e308.pov",
        cam + "sphere { 0, 1 matrix <1e308, 0, 0, 0, 1e308, 0, 0, 0, 1e308, 0, 0, 0> }\n",
    )
    write("pov/scale-subnormal.pov", cam + "sphere { 0, 1 scale 1e-320 }\n")
    light = "light_source { <5, 5, -5> color rgb 1 }\nsphere { 0, 1 }\n"
    write(
        "pov/camera-look-at-1e308-away.pov",
        "camera { location <1e308, 1e308, 1e308> look_at <-1e308, -1e308, -1e308> }\n" + light,
    )
    write(
        "pov/camera-direction-1e200.pov",
        "camera { location 0 direction <1e200, 0, 1e200> }\n" + light,
    )
    # Patterns read as their mean colour: POV-Ray's limit on a colour_map,
    # colours near the largest double (the mean stays finite, and negative)
    # and a value that is not finite.
    write(
        "pov/colour-map-257-entries.pov",
        cam
        + "sphere { 0, 1 pigment { gradient x colour_map {\n"
        + "".join("  [%g rgb %g]\n" % (i / 256, i / 256) for i in range(257))
        + "} } }\n",
    )
    write(
        "pov/colour-map-colours-1e308.pov",
        cam
        + "sphere { 0, 1 pigment { marble colour_map { [0 rgb -1.7e308] [1 rgb -1.7e308] } } }\n",
    )
    write(
        "pov/colour-map-value-not-finite.pov",
        cam + "sphere { 0, 1 pigment { bozo colour_map { [1e308 * 10 rgb 1] } } }\n",
    )


make_sf()
make_instructions()
make_gltf()
make_pov()
