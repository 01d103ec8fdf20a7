"""scenefile.render: sfrender's numbers, exactly; the GIL released; Ctrl+C."""

import os
import subprocess
import sys
import textwrap
import threading
import time

import numpy as np
import pytest

import scenefile
from conftest import EXAMPLES, SOURCE, TESTDATA, run

# (scene or None for the default scene, sfrender's flags, render()'s arguments)
CASES = [
    (None, [], {}),
    (os.path.join(EXAMPLES, "blue-cube.txt"), ["--spp", "4", "--seed", "3"],
     {"spp": 4, "seed": 3}),
    (os.path.join(SOURCE, "bench", "scenes", "glass-mirror.txt"), ["--depth", "7", "--fov", "50"],
     {"depth": 7, "fov": 50.0}),
    # A POV-Ray scene at its own field of view: fov=None, as sfrender without --fov.
    (os.path.join(TESTDATA, "view", "wide-angle.pov"), [], {"fov": None}),
]
WIDTH, HEIGHT = 64, 48


def ppm(path):
    """The pixels of a binary PPM of 8 bits."""
    data = open(path, "rb").read()
    magic, width, height, levels, pixels = data.split(maxsplit=4)
    assert (magic, int(levels)) == (b"P6", 255)
    return np.frombuffer(pixels, np.uint8).reshape(int(height), int(width), 3)


def levels(image):
    """round(clamp(v, 0, 1) * 255) as sfrender stores 8 bits: the float
    product, rounded half away from zero (std::lround)."""
    product = np.clip(image, 0.0, 1.0).astype(np.float32) * np.float32(255.0)
    return np.floor(product.astype(np.float64) + 0.5).astype(np.uint8)


def srgb_decoding(image):
    """What sfrender writes in a float EXR: the sRGB decoding of each number,
    in doubles and rounded to a float, as image/image_file.cpp does."""
    v = image.astype(np.float64)
    m = np.abs(v)
    linear = np.where(m <= 0.04045, m / 12.92, np.power((m + 0.055) / 1.055, 2.4))
    return np.copysign(np.minimum(linear, np.finfo(np.float32).max), v).astype(np.float32)


def scene_of(path):
    return scenefile.default_scene() if path is None else scenefile.read(path)


@pytest.mark.parametrize("path, flags, arguments", CASES,
                         ids=lambda c: os.path.basename(c) if isinstance(c, str) else None)
def test_the_numbers_are_sfrenders(sfrender, tmp_path, path, flags, arguments):
    image = scenefile.render(scene_of(path), width=WIDTH, height=HEIGHT, **arguments)
    assert image.shape == (HEIGHT, WIDTH, 3) and image.dtype == np.float32
    assert image.flags.c_contiguous
    source = [path] if path else []
    size = ["--width", str(WIDTH), "--height", str(HEIGHT), "--quiet"]
    run(sfrender, *source, *size, *flags, "-o", tmp_path / "image.ppm")
    assert np.array_equal(levels(image), ppm(tmp_path / "image.ppm"))
    assert image.max() > 0.1, "a picture, not black"
    oiio = pytest.importorskip("OpenImageIO")
    run(sfrender, *source, *size, *flags, "-o", tmp_path / "image.exr", "--bits", "32")
    exr = oiio.ImageInput.open(str(tmp_path / "image.exr"))
    stored = exr.read_image("float")
    exr.close()
    assert stored.shape == image.shape
    assert np.array_equal(srgb_decoding(image), stored), "the float EXR, bit for bit"


def test_every_thread_count_gives_the_same_image():
    scene = scenefile.default_scene()
    one = scenefile.render(scene, width=40, height=30, spp=2, threads=1)
    assert np.array_equal(one, scenefile.render(scene, width=40, height=30, spp=2, threads=3))


def test_the_gil_is_released_while_it_renders():
    # Another Python thread keeps counting while a render of about half a
    # second runs; holding the GIL, the render would leave it at 0.
    counted = [0]
    stop = threading.Event()

    def count():
        while not stop.is_set():
            counted[0] += 1

    counter = threading.Thread(target=count)
    counter.start()
    try:
        started = time.monotonic()
        scenefile.render(scenefile.default_scene(), width=320, height=240, spp=8, threads=1)
        seconds = time.monotonic() - started
        during = counted[0]
    finally:
        stop.set()
        counter.join()
    assert seconds > 0.05
    assert during > 1000, f"the other thread counted {during} in {seconds:.2f} s"


def python(script, **limits):
    """A fresh python running `script` with the package of the build."""
    return subprocess.run([sys.executable, "-c", textwrap.dedent(script)], capture_output=True,
                          text=True, timeout=60, env=os.environ)


def test_ctrl_c_stops_a_render_promptly():
    # SIGINT half a second into a render of minutes: KeyboardInterrupt, soon.
    result = python("""
        import os, signal, threading, time
        import scenefile
        scene = scenefile.default_scene()
        threading.Timer(0.5, os.kill, (os.getpid(), signal.SIGINT)).start()
        started = time.monotonic()
        try:
            scenefile.render(scene, width=4000, height=3000, spp=64, threads=2)
            print("finished")
        except KeyboardInterrupt:
            print(f"interrupted {time.monotonic() - started:.3f}")
    """)
    assert result.returncode == 0, result.stderr
    word, seconds = result.stdout.split()
    assert word == "interrupted"
    assert 0.4 < float(seconds) < 3.0, result.stdout


def test_a_render_that_cannot_fit_is_refused():
    result = python("""
        import resource
        import scenefile
        scene = scenefile.default_scene()
        resource.setrlimit(resource.RLIMIT_AS, (4 << 30, resource.RLIM_INFINITY))
        try:
            scenefile.render(scene, width=32768, height=32768)
        except MemoryError as e:
            print("MemoryError:", e)
    """)
    assert result.stdout.startswith("MemoryError: "), result.stdout + result.stderr
    assert "memory" in result.stdout


def test_settings_are_checked():
    scene = scenefile.default_scene()
    for bad in ({"width": 0}, {"height": 40000}, {"spp": 0}, {"depth": -1}, {"fov": 180},
                {"fov": 0.0}, {"threads": -1}, {"seed": -1}):
        with pytest.raises(ValueError):
            scenefile.render(scene, **bad)
    with pytest.raises(TypeError):
        scenefile.render(scene, width=64.0)


def test_an_invalid_scene_is_refused():
    scene = scenefile.default_scene()
    scene.objects[0].matrix = np.zeros((4, 4))
    with pytest.raises(scenefile.SceneError) as caught:
        scenefile.render(scene, width=8, height=8)
    assert caught.value.errors[0].code == "matrix-last-row"
