# Blender's Cycles renders sfconvert's glTF export of each scene, and the
# picture's mean brightness must lie within a tolerance of sfrender's picture
# of the same scene, at the same size and field of view (docs/GLTF.md,
# "Lights": the glTF lights are matched to the scene's at a reference
# distance, for a reference surface).
#
# "Mean brightness" is the mean of every channel of every pixel of the 8-bit
# images as each program writes them: sfrender's numbers clamped and rounded
# (its PPM), Cycles' linear light through the Standard view transform (the
# sRGB curve) into a PNG, with no dithering. Both are display values.
#
# blender -b --factory-startup --python-exit-code 1 --python THIS -- \
#     SFCONVERT SFRENDER WORKDIR WIDTH HEIGHT SAMPLES TOLERANCE SCENE...
# A SCENE written "default=FILE.txt" stands for sfrender's built-in scene,
# which sfrender renders with no input; FILE.txt must be that scene (it is
# rendered too, and must give the same bytes), and is what sfconvert exports.
import os
import re
import subprocess
import sys
import time

import bpy
import numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cycles_settings import cycles_as_sfrender  # noqa: E402

# Debian 12's Blender 3.4 importer still says numpy.bool, which numpy 1.24
# removed; the builtin is what it means.
numpy.bool = bool

args = sys.argv[sys.argv.index("--") + 1:]
sfconvert, sfrender, work = args[0], args[1], args[2]
width, height, samples = int(args[3]), int(args[4]), int(args[5])
tolerance = float(args[6])
scenes = args[7:]
os.makedirs(work, exist_ok=True)
FOV = "60"  # sfrender's default; scene and instruction files carry no view


def run(command):
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"{' '.join(command)} failed with {done.returncode}:\n{done.stderr}")
    return done


def read_ppm(path):
    data = open(path, "rb").read()
    # The header's four tokens, then one whitespace byte: the pixels that
    # follow may themselves be bytes of whitespace.
    header = re.match(rb"P6\s+(\d+)\s+(\d+)\s+255\s", data)
    if not header:
        sys.exit(f"{path}: not an 8-bit binary PPM")
    w, h = int(header.group(1)), int(header.group(2))
    pixels = data[header.end():header.end() + w * h * 3]
    return numpy.frombuffer(pixels, dtype=numpy.uint8).reshape(h, w, 3)


def sfrender_image(source, name):
    """sfrender's picture of the scene file `source` (None: the default scene)."""
    ppm = os.path.join(work, name + ".sfrender.ppm")
    command = [sfrender] + ([source] if source else []) + [
        "-o", ppm, "--width", str(width), "--height", str(height), "--fov", FOV, "--quiet"]
    run(command)
    return read_ppm(ppm)


def setup_render(scene, png):
    cycles_as_sfrender(bpy, scene, width, height, samples, png)


def cycles_image(glb, name):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.ops.import_scene.gltf(filepath=glb)
    scene = bpy.context.scene
    cameras = [o for o in scene.objects if o.type == "CAMERA"]
    if len(cameras) != 1:
        sys.exit(f"{glb}: Blender imported {len(cameras)} cameras, not one")
    scene.camera = cameras[0]
    png = os.path.join(work, name + ".cycles.png")
    setup_render(scene, png)
    bpy.ops.render.render(write_still=True)
    image = bpy.data.images.load(png)
    # A byte image's pixels are its bytes over 255, as written.
    pixels = numpy.array(image.pixels[:]).reshape(height, width, image.channels)[:, :, :3]
    bpy.data.images.remove(image)
    return numpy.rint(pixels * 255.0)


failures = []
rows = []
started = time.time()
for spec in scenes:
    if spec.startswith("default="):
        source, name = spec[len("default="):], "default-scene"
        reference = sfrender_image(None, name)
        if not numpy.array_equal(reference, sfrender_image(source, name + ".txt")):
            sys.exit(f"{source} is not sfrender's default scene: their pictures differ")
    else:
        source, name = spec, os.path.basename(spec)
        reference = sfrender_image(source, name)
    glb = os.path.join(work, name + ".glb")
    run([sfconvert, source, glb, "--width", str(width), "--height", str(height), "--fov", FOV])
    t = time.time()
    cycles = cycles_image(glb, name)
    seconds = time.time() - t
    ours, theirs = float(reference.mean()), float(cycles.mean())
    ratio = theirs / ours if ours > 0 else float("inf")
    within = abs(ratio - 1.0) <= tolerance
    rows.append((name, ours, theirs, ratio, within))
    print(f"brightness {name}: sfrender {ours:.1f}, Cycles {theirs:.1f} (of 255), "
          f"ratio {ratio:.3f}{'' if within else ' OUTSIDE'} ({seconds:.1f} s to render)")
    if not within:
        failures.append(f"{name}: Cycles {theirs:.1f} against sfrender's {ours:.1f}, "
                        f"ratio {ratio:.3f}, beyond 1 +- {tolerance}")

with open(os.path.join(work, "brightness.tsv"), "w") as table:
    table.write("scene\tsfrender\tcycles\tratio\n")
    for name, ours, theirs, ratio, _ in rows:
        table.write(f"{name}\t{ours:.2f}\t{theirs:.2f}\t{ratio:.4f}\n")
print(f"{len(rows)} scenes at {width}x{height}, {samples} samples, "
      f"in {time.time() - started:.1f} s")
if failures:
    sys.exit("\n".join(failures))
print(f"blender brightness: every export within {tolerance:.0%} of sfrender's picture")
