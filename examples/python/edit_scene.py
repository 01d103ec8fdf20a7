#!/usr/bin/env python3
"""Reads a scene, edits it and writes it back: what a script does to a
scene someone else made.

    python3 edit_scene.py [OUTPUT_FOLDER] [SCENE]

SCENE (by default examples/blue-cube.txt) is read in whatever format it is;
every object is listed with its kind, place and material; the cube is
painted orange and lifted by one unit; the result is written as an
instruction file (the lifted object's transform list is written anew from
its matrix) and as glTF for other programs.
"""

import os
import sys

import scenefile

HERE = os.path.dirname(os.path.abspath(__file__))


def main() -> None:
    folder = sys.argv[1] if len(sys.argv) > 1 else "."
    source = sys.argv[2] if len(sys.argv) > 2 else os.path.join(HERE, "..", "blue-cube.txt")
    os.makedirs(folder, exist_ok=True)
    try:
        scene = scenefile.read(source)
    except scenefile.SceneError as error:
        # The first error as the tools print it; every one is in .diagnostics.
        sys.exit(f"{error}")
    print(f"{source}: {scene.format}, eye at {scene.camera.eye}")
    for i, obj in enumerate(scene.objects):
        ops = " ".join(op.kind.value for op in obj.transforms or ())
        print(f"  {i}: {obj.kind.value:8} at {tuple(obj.matrix[:3, 3])}, colour {obj.colour}"
              f"{', ' + ops if ops else ''}")

    cubes = [obj for obj in scene.objects if obj.kind is scenefile.CUBE]
    for cube in cubes:
        cube.colour = (1.0, 0.55, 0.1)
        cube.matrix[1, 3] += 1.0  # lifted: the transform list no longer describes it
        assert cube.transforms is None
    losses = scenefile.write(scene, os.path.join(folder, "edited.txt"))
    assert not losses
    edited = scenefile.read(os.path.join(folder, "edited.txt"))
    for before, after in zip(scene.objects, edited.objects):
        assert abs(before.matrix - after.matrix).max() < 1e-12
    print(f"edited.txt: {len(cubes)} cubes lifted, written with "
          f"{[op.kind.value for op in edited.objects[-1].transforms or ()]}")

    losses = scenefile.write(scene, os.path.join(folder, "edited.glb"))
    for d in losses:
        print(f"  {d.severity.value}: {d.message} [{d.code}]")
    assert scenefile.read(os.path.join(folder, "edited.glb")) == scene, "glTF holds it all"


if __name__ == "__main__":
    main()
