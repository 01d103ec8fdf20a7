#!/usr/bin/env python3
"""Builds a scene by program, writes it in both line formats, and renders it.

    python3 procedural_scene.py [OUTPUT_FOLDER]

A spiral of spheres in the colours of a hue circle climbs around a mirror
cylinder on a floor, under two lights. The scene is written as an
instruction file (spiral.txt, with every material value and the transform
list of each object) and as a scene file (spiral.sf, which keeps the
colours and matrices only: the losses are printed), and rendered to
spiral.ppm, rounded to bytes as sfrender does. `sfrender spiral.txt` draws
the same picture.
"""

import colorsys
import math
import os
import sys

import numpy as np

import scenefile
from scenefile import Camera, Light, Material, Object, Scene, TransformOp


def spiral(count: int = 24) -> Scene:
    scene = Scene(Camera.looking_at(location=(0.0, 4.0, 11.0), look_at=(0.0, 1.6, 0.0)))
    scene.output_file = "spiral.ppm"
    scene.lights.append(Light(position=(6.0, 9.0, 8.0), colour=(0.9, 0.9, 0.9)))
    scene.lights.append(Light(position=(-7.0, 5.0, 3.0), colour=(0.3, 0.3, 0.35)))
    scene.objects.append(Object(scenefile.PLANE, colour=(0.75, 0.75, 0.7), transforms=[]))
    mirror = Material(colour=(0.9, 0.9, 0.9), reflectivity=0.8, diffuse=0.2)
    scene.objects.append(Object(scenefile.CYLINDER, material=mirror, transforms=[
        TransformOp.scale(0.6, 1.5, 0.6), TransformOp.translate(0.0, 1.5, 0.0)]))
    for i in range(count):
        turn = i / count
        angle = 2.5 * 2 * math.pi * turn
        radius = 0.18 + 0.12 * turn
        colour = colorsys.hsv_to_rgb(turn, 0.8, 0.95)
        scene.objects.append(Object(scenefile.SPHERE, material=Material(colour, shininess=60.0),
                                    transforms=[
                                        TransformOp.scale(radius),
                                        TransformOp.translate(2.4, radius + 3.0 * turn, 0.0),
                                        TransformOp.rotate_y(angle)]))
    return scene


def write_ppm(image: "np.typing.NDArray[np.float32]", path: str) -> None:
    """An 8-bit binary PPM of the image, each channel round(clamp(v, 0, 1) * 255)."""
    levels = np.floor(np.clip(image, 0.0, 1.0).astype(np.float32) * np.float32(255) + 0.5)
    height, width, _ = image.shape
    with open(path, "wb") as f:
        f.write(b"P6\n%d %d\n255\n" % (width, height))
        f.write(levels.astype(np.uint8).tobytes())


def main() -> None:
    folder = sys.argv[1] if len(sys.argv) > 1 else "."
    os.makedirs(folder, exist_ok=True)
    scene = spiral()
    problems = scenefile.validate(scene)
    for d in problems:
        print(d)
    assert not problems, "the scene built here is valid"

    scenefile.write(scene, os.path.join(folder, "spiral.txt"))
    # A scene file keeps each object's colour and matrix: the rest is lost.
    losses = scenefile.write(scene, os.path.join(folder, "spiral.sf"))
    print(f"spiral.sf: {len(losses)} losses, the first: {losses[0].message}")
    back = scenefile.read(os.path.join(folder, "spiral.txt"))
    assert back == scene, "the instruction file holds the scene exactly"

    image = scenefile.render(scene, width=320, height=240, spp=4)
    write_ppm(image, os.path.join(folder, "spiral.ppm"))
    lit = float((image.max(axis=2) > 0.05).mean())
    print(f"spiral.ppm: {image.shape[1]}x{image.shape[0]}, {100 * lit:.0f}% of the pixels lit")
    assert lit > 0.5, "the floor and the spiral fill the picture"


if __name__ == "__main__":
    main()
