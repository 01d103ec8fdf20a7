"""scenefile: read, check, write, convert and render ray-tracing scenes.

The Python face of libscene, the library under the tools sfcheck, sfconvert
and sfrender: the same readers, writers, diagnostics and renderer, so that
what a script does is what the tools do. docs/PYTHON.md is the manual.

    import scenefile
    scene = scenefile.read("examples/blue-cube.txt")
    scene.objects[0].colour = (1.0, 0.5, 0.0)
    losses = scenefile.write(scene, "orange-cube.sf")   # AMBIENT, ... are lost
    image = scenefile.render(scene, width=320, height=240)   # (240, 320, 3) float32
"""

from __future__ import annotations

import os
from typing import Any, Dict, List, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

from . import _checks, _core
from ._model import (Camera, Colour, Diagnostic, FixIt, Light, Material, Matrix, Note, Object,
                     ObjectKind, Scene, Severity, TransformKind, TransformOp, Vector, View,
                     _diagnostics, _kind, _matrix, compose_transform)
from ._remedy import Remedy

__version__: str = _core.__version__

PLANE = ObjectKind.PLANE
SPHERE = ObjectKind.SPHERE
CYLINDER = ObjectKind.CYLINDER
CUBE = ObjectKind.CUBE
#: The largest deviation fit_primitive accepts, relative to the shape's size.
FIT_TOLERANCE: float = _core.FIT_TOLERANCE

__all__ = [
    "CUBE", "CYLINDER", "Camera", "Colour", "Diagnostic", "FIT_TOLERANCE", "FixIt", "Light",
    "Material", "Matrix", "MeshFit", "Note", "Object", "ObjectKind", "PLANE", "SPHERE", "Remedy",
    "Scene", "SceneError", "Severity", "TransformKind", "TransformOp", "Vector", "View", "check",
    "compose_transform", "convert", "decompose_transform", "default_scene", "fit_primitive",
    "formats", "loads", "primitive_mesh", "read", "render", "validate", "write",
]

PathLike = Union[str, "os.PathLike[str]"]

# The keyword arguments each function takes beyond its own, by what they
# are for: reading (the tools' limits and reading flags) and writing
# (sfconvert's flags), each with its type and, for numbers, the range the
# tools' flags take.
_BIG = (1 << 63) - 1
_READ_OPTIONS: Dict[str, Tuple[type, float, float]] = {
    "max_file_size": (int, 1, _BIG), "max_objects": (int, 1, _BIG),
    "max_vertices": (int, 1, _BIG), "max_nodes": (int, 1, _BIG), "error_limit": (int, 1, _BIG),
    "no_loss": (bool, 0, 1), "transpose_matrices": (bool, 0, 1),
    "skip_unsupported": (bool, 0, 1),
}
_SIDE = _core.MAX_IMAGE_SIDE
_WRITE_OPTIONS: Dict[str, Tuple[type, float, float]] = {
    "no_loss": (bool, 0, 1), "approximate": (bool, 0, 1), "output_file": (str, 0, 0),
    "fov": (View, 0, 0), "width": (int, 1, _SIDE), "height": (int, 1, _SIDE),
    "tessellation": (int, 3, 1024), "external_buffers": (bool, 0, 1), "flat": (bool, 0, 1),
    "depth": (int, 0, 1000), "no_lights": (bool, 0, 1), "no_extras": (bool, 0, 1),
    "light_falloff": (str, 0, 0),
}


class SceneError(Exception):
    """A scene could not be read, checked as valid, or written as asked.

    ``diagnostics`` holds every diagnostic (errors first found first, with
    the warnings and notes among them); ``str()`` is the first error in the
    tools' form, ``file:line:column: error: message [code]``.
    """

    def __init__(self, diagnostics: Sequence[Diagnostic]) -> None:
        self.diagnostics: List[Diagnostic] = list(diagnostics)
        errors = self.errors
        first = str(errors[0]) if errors else "the scene is invalid"
        more = f" (and {len(errors) - 1} more errors)" if len(errors) > 1 else ""
        super().__init__(first + more)

    @property
    def errors(self) -> List[Diagnostic]:
        """The errors among ``diagnostics``."""
        return [d for d in self.diagnostics if d.severity == Severity.ERROR]


def _options(given: Dict[str, Any], known: Dict[str, Tuple[type, float, float]],
             function: str) -> Dict[str, Any]:
    """The keyword arguments checked by name, type and range, as the tools check their flags."""
    out: Dict[str, Any] = {}
    for name, value in given.items():
        if name not in known:
            hint = _core.suggest_spelling(name, sorted(known))
            did_you_mean = f"; did you mean {hint!r}?" if hint else ""
            raise TypeError(f"{function}() got an unexpected keyword argument {name!r}"
                            f"{did_you_mean}")
        if value is None:
            continue
        kind, lowest, highest = known[name]
        if kind is View:
            value = _fov(value)
        elif kind is bool:
            value = _checks.flag(value, name)
        elif kind is int:
            value = _checks.whole(value, name, int(lowest), int(highest))
        elif kind is float:
            value = _checks.real(value, name, lowest, highest, excluded=(True, True))
        else:
            value = _checks.instance(value, name, kind)
        out[name] = value
    return out


def _fov(value: Any) -> float:
    """A field of view given as an argument, held to the one rule for a view."""
    fov = _checks.real(value, "fov")
    problem = _core.check_view(fov, None)
    if problem is not None:
        raise ValueError(f"fov: {problem}")
    return fov


def _format_name(format: Optional[str]) -> Optional[str]:
    if format is None:
        return None
    _checks.instance(format, "format", str)
    names = [row["name"] for row in _core.formats()]
    name = str(format).lower()
    if name not in names:
        hint = _core.suggest_spelling(str(format), names)
        did_you_mean = f"; did you mean {hint!r}?" if hint else ""
        raise ValueError(f"{format!r} is no format: {', '.join(names)}{did_you_mean}")
    return name


def _raise_on_errors(diagnostics: List[Diagnostic]) -> None:
    if any(d.severity == Severity.ERROR for d in diagnostics):
        raise SceneError(diagnostics)


def loads(data: Union[str, bytes], name: str = "<string>", format: Optional[str] = None,
          **limits: Any) -> Scene:
    """The scene in ``data`` (text or bytes), as read() reads a file named ``name``."""
    options = _options(limits, _READ_OPTIONS, "loads")
    _checks.instance(data, "data", (str, bytes))
    _checks.instance(name, "name", str)
    if isinstance(data, str):
        data = data.encode("utf-8", "surrogateescape")
    size_diagnostics = _diagnostics(_core.check_file_size(len(data), name, options))
    _raise_on_errors(size_diagnostics)
    return _parse(bytes(data), name, format, options)


def _parse(data: bytes, name: str, format: Optional[str], options: Dict[str, Any]) -> Scene:
    """The scene in ``data``, named ``name``, or SceneError with every diagnostic."""
    scene_data, diagnostics, detected = _core.parse(data, name, _format_name(format), options)
    return _scene(scene_data, _diagnostics(diagnostics), name, detected)


def _scene(scene_data: Optional[Dict[str, Any]], found: List[Diagnostic], name: str,
           detected: Optional[str]) -> Scene:
    """The scene read, or SceneError with every diagnostic."""
    _raise_on_errors(found)
    assert scene_data is not None, "no scene, yet no error"
    scene = Scene._from_data(scene_data)
    scene.source, scene.format, scene.diagnostics = name, detected, found
    return scene


def _path(value: Any, name: str) -> str:
    """A path argument as a str: a str, or an os.PathLike (pathlib.Path)."""
    try:
        path = os.fspath(value)
    except TypeError:
        raise TypeError(f"{name} must be a path (a str or an os.PathLike), not "
                        f"{type(value).__name__}") from None
    return path if isinstance(path, str) else os.fsdecode(path)


def _read_file(path: PathLike, format: Optional[str], options: Dict[str, Any]
               ) -> Tuple[str, Optional[Dict[str, Any]], List[Diagnostic], Optional[str]]:
    """The file read by the library, as the tools read theirs: its name as
    diagnostics give it, its scene data (None when refused), the diagnostics
    and the format detected. OSError when it cannot be read."""
    name = _path(path, "path")
    scene_data, diagnostics, detected, failure = _core.read_file(
        os.fsencode(name), name, _format_name(format), options)
    if failure:
        raise OSError(failure, os.strerror(failure), name)
    return name, scene_data, _diagnostics(diagnostics), detected


def _read(path: PathLike, format: Optional[str], options: Dict[str, Any]) -> Scene:
    name, scene_data, found, detected = _read_file(path, format, options)
    return _scene(scene_data, found, name, detected)


def read(path: PathLike, format: Optional[str] = None, **limits: Any) -> Scene:
    """The scene in the file at ``path``, in any format the tools read.

    The format is recognised from the content unless ``format`` names one
    ("sf", "instructions", "gltf", "glb", "pov", "obj"). ``limits`` are the
    tools' reading flags: max_file_size, max_objects, max_vertices,
    max_nodes, error_limit, no_loss, transpose_matrices, skip_unsupported.

    Raises SceneError (with every diagnostic) when the file is invalid, and
    OSError (FileNotFoundError, ...) when it cannot be read. The warnings
    and notes are in the scene's ``diagnostics``.
    """
    return _read(path, format, _options(limits, _READ_OPTIONS, "read"))


def check(path: PathLike, **limits: Any) -> List[Diagnostic]:
    """Every diagnostic of the file at ``path``, as sfcheck finds them.

    Errors, warnings and notes, in the order found; an empty list is a valid
    file. sfcheck also warns about an OUTPUT_FILE that would leave its folder
    or is not an image: that is the tool's policy, not the library's, and
    not here. OSError when the file cannot be read.
    """
    return _read_file(path, None, _options(limits, _READ_OPTIONS, "check"))[2]


def validate(scene: Scene) -> List[Diagnostic]:
    """Every rule of FORMATS.md on a scene built or edited in Python.

    The diagnostics point at records (their lines, for a scene read from a
    file); an error here is one write() and render() would refuse.
    """
    _checks.instance(scene, "scene", Scene)
    return _diagnostics(_core.validate(scene._to_data(), scene.source or ""))


def _format_for(path: str, format: Optional[str]) -> str:
    if format is not None:
        return _format_name(format)  # type: ignore[return-value]
    found = _core.format_by_extension(path)
    if found is None:
        names = ", ".join(row["name"] for row in _core.formats())
        raise ValueError(f"cannot tell the format of {path!r} from its extension; "
                         f"name it with format=: {names}")
    return found


def _output_paths(target: str, format: str, external_buffers: bool) -> Tuple[str, str]:
    """The file written, and its sidecar ("" for none), as sfconvert places
    them: a .gltf's buffer (external_buffers) or an .obj's MTL file, beside
    the file at the end of a link, named after it."""
    if external_buffers and format != "gltf":
        raise ValueError("external_buffers needs a .gltf output (format 'gltf')")
    if not external_buffers and format != "obj":
        return target, ""
    written = os.path.realpath(target) if os.path.islink(target) else target
    name = os.path.splitext(os.path.basename(written))[0] + (".mtl" if format == "obj" else ".bin")
    sidecar = os.path.join(os.path.dirname(written), name)
    if os.path.basename(written) == name:
        what, output = ("MTL", "NAME.obj") if format == "obj" else ("buffer", "NAME.gltf")
        raise ValueError(f"the {what} file {sidecar!r} is the output itself; name the output "
                         f"{output}")
    return target, sidecar


def _output_clash(inputs: Sequence[str], made_from: str, target: str, sidecar: str,
                  format: str) -> Optional[str]:
    """The tools' check, by file identity, that no output is an input and no
    two outputs are one file: None, or the clash in their words."""
    role = "its MTL file" if format == "obj" else "its buffer"
    outputs = [(os.fsencode(sidecar), os.fsencode(made_from), role)] if sidecar else []
    outputs.append((os.fsencode(target), os.fsencode(made_from), ""))
    return _core.output_clash([os.fsencode(path) for path in inputs], outputs)


def _output_file(scene: Scene, path: str, format: str, options: Dict[str, Any]) -> Optional[str]:
    """The OUTPUT_FILE the writer is given: ``output_file``, held to the
    readers' rule, or as sfconvert names the image, after the instruction
    file, what a name cannot hold made '_' (the library's rule both)."""
    given: Optional[str] = options.get("output_file")
    if given is None:
        if format != "instructions" or scene.output_file is not None:
            return None
        return _core.output_file_name_for(path)
    problem = _core.check_output_file_name(given)
    if problem is not None:
        raise ValueError(f"output_file {given!r} cannot be an OUTPUT_FILE: {problem}")
    return given


def _converted(scene: Scene, path: str, sidecar: str, format: str, options: Dict[str, Any]
               ) -> Tuple[bytes, bytes, List[Diagnostic]]:
    """The bytes of the scene in ``format``, for ``path``, its sidecar's and the losses,
    which name the file read, or for a scene built in Python the file written."""
    source = scene.source or path
    problems = _diagnostics(_core.validate(scene._to_data(), source))
    _raise_on_errors(problems)
    core_options = dict(options)
    core_options["generator"] = f"scenefile {__version__} (Python)"
    core_options.pop("external_buffers", None)
    core_options["output_file"] = _output_file(scene, path, format, options)
    if sidecar:
        key = "material_library" if format == "obj" else "external_buffer"
        core_options[key] = os.path.basename(sidecar)
    main, beside, diagnostics = _core.convert(scene._to_data(), format, core_options, source)
    losses = _diagnostics(diagnostics)
    if main is None:
        raise SceneError(losses)
    return main, beside, losses


def _write_files(files: Sequence[Tuple[str, bytes]]) -> None:
    """The files written by the tools' own code: through links, never over a
    folder, a device or a pipe, whole or not at all."""
    failed = _core.write_files([(os.fsencode(path), data) for path, data in files])
    if failed is not None:
        path, reason = failed
        raise OSError(f"cannot write {os.fsdecode(path)!r}: {reason}")


def write(scene: Scene, path: PathLike, format: Optional[str] = None, no_loss: bool = False,
          **options: Any) -> List[Diagnostic]:
    """Writes ``scene`` to ``path``; returns the losses.

    The format follows the extension (.sf, .txt for an instruction file,
    .gltf, .glb, .pov, .obj with its NAME.mtl beside it) unless ``format``
    names one. What the format cannot hold is reported as a warning in the
    list returned, or with ``no_loss`` raises SceneError and writes nothing.
    ``options`` are sfconvert's: approximate, output_file, fov, width,
    height, tessellation (glTF's and OBJ's), external_buffers (a .gltf's
    buffer in NAME.bin beside it), no_lights, no_extras, light_falloff
    ("inverse-square" or "none"), flat, depth.
    An invalid scene raises SceneError (validate() gives its warnings too).
    The file is written as the tools write theirs: whole or not at all,
    through a symbolic link to the file it leads to, keeping the mode of a
    file it replaces; a folder, a device or a pipe is refused (OSError).
    """
    _checks.instance(scene, "scene", Scene)
    target = _path(path, "path")
    checked = _options(dict(options, no_loss=no_loss), _WRITE_OPTIONS, "write")
    fmt = _format_for(target, format)
    _, sidecar = _output_paths(target, fmt, checked.get("external_buffers", False))
    clash = _output_clash([], scene.source or "the scene", target, sidecar, fmt)
    if clash is not None:
        raise ValueError(clash)
    main, sidecar_bytes, losses = _converted(scene, target, sidecar, fmt, checked)
    # In this order: a .gltf's buffer or an .obj's MTL file before the file
    # that names it.
    _write_files([(sidecar, sidecar_bytes), (target, main)] if sidecar else [(target, main)])
    return losses


def convert(src: PathLike, dst: PathLike, format: Optional[str] = None,
            **options: Any) -> List[Diagnostic]:
    """sfconvert SRC DST: reads any format, writes the one of ``dst``'s extension.

    ``format`` names the output's format instead (sfconvert's --to);
    ``options`` take read()'s limits and write()'s options, ``no_loss``
    applying to both, and ``width`` and ``height`` also giving a POV-Ray
    input's image size, as sfconvert takes them. Returns what reading noted
    and what writing lost. Never writes over ``src``: an output (``dst``,
    or its buffer or MTL file) that is the input file, by any name or link, is a
    ValueError, before anything is read or written.
    """
    source, target = _path(src, "src"), _path(dst, "dst")
    checked = _options(options, dict(_READ_OPTIONS, **_WRITE_OPTIONS), "convert")
    read_options = {k: v for k, v in checked.items() if k in _READ_OPTIONS}
    if "width" in checked and "height" in checked:
        read_options["width"], read_options["height"] = checked["width"], checked["height"]
    write_options = {k: v for k, v in checked.items() if k in _WRITE_OPTIONS}
    fmt = _format_for(target, format)
    _, sidecar = _output_paths(target, fmt, checked.get("external_buffers", False))
    clash = _output_clash([source], source, target, sidecar, fmt)
    if clash is not None:
        raise ValueError(f"an output is the input file: {clash}; convert never writes over its "
                         "input")
    scene = _read(source, None, read_options)
    losses = write(scene, target, fmt, **write_options)
    return scene.diagnostics + losses


def render(scene: Scene, width: int = 640, height: int = 480, spp: int = 1, depth: int = 5,
           fov: Optional[float] = 60.0, threads: int = 0, seed: int = 0) -> npt.NDArray[np.float32]:
    """The image sfrender computes, as a float32 array of shape (height, width, 3).

    Rows from the top, red, green, blue: the numbers sfrender writes before
    it rounds them to an image's levels (``round(clamp(v, 0, 1) * 255)`` is
    its 8-bit PNG or PPM). ``fov`` is the vertical field of view in degrees,
    60 by default, as in sfrender; None takes the scene's own (a glTF or
    POV-Ray camera's), else 60, as sfrender without --fov.
    ``threads`` 0 uses every core. The GIL is released while it renders, and
    Ctrl+C (KeyboardInterrupt) stops it. An invalid scene raises SceneError,
    a render that does not fit in free memory MemoryError.
    """
    _checks.instance(scene, "scene", Scene)
    settings = {"width": (width, 1, _SIDE), "height": (height, 1, _SIDE), "spp": (spp, 1, 65536),
                "depth": (depth, 0, 1000), "threads": (threads, 0, 1024),
                "seed": (seed, 0, (1 << 63) - 1)}
    whole = {name: _checks.whole(value, name, lowest, highest)
             for name, (value, lowest, highest) in settings.items()}
    given = None if fov is None else _fov(fov)
    data = scene._to_data()
    _raise_on_errors(_diagnostics(_core.validate(data, scene.source or "")))
    if given is None:
        # As sfrender: the scene's own view, which validate() held to the
        # range of an fov given.
        given = scene.view.fov if scene.view is not None else 60.0
    return _core.render(data, whole["width"], whole["height"], whole["spp"], whole["depth"], given,
                        whole["threads"], whole["seed"])


def default_scene() -> Scene:
    """The scene sfrender draws when it is given none."""
    return Scene._from_data(_core.default_scene())


def decompose_transform(matrix: npt.ArrayLike) -> Tuple[List[TransformOp], bool]:
    """The operations an instruction file writes for ``matrix`` (SCALE,
    ROTATE_X, ROTATE_Y, ROTATE_Z, TRANSLATE, those that do nothing left out),
    and whether they give it back exactly (False for a matrix with shear,
    whose nearest rotation and scale they are). ``matrix`` must be one an
    object may have (validate()'s rules): finite, its fourth row 0 0 0 1, and
    invertible; ValueError otherwise."""
    m = _matrix(matrix, "matrix")
    if not np.isfinite(m).all():
        raise ValueError("matrix must hold finite numbers only")
    ops, exact = _core.decompose_transform(m)
    return [TransformOp(kind, value) for kind, value in ops], bool(exact)


class MeshFit:
    """What fit_primitive recognised: ``kind`` (None when nothing fits), the
    ``matrix`` that takes the unit primitive onto the mesh, the largest
    deviation ``error`` (relative to the shape's size), and ``reason``,
    which says why nothing fits."""

    __slots__ = ("kind", "matrix", "error", "reason")

    def __init__(self, kind: Optional[ObjectKind], matrix: Optional[Matrix],
                 error: Optional[float], reason: str) -> None:
        self.kind, self.matrix, self.error, self.reason = kind, matrix, error, reason

    def __bool__(self) -> bool:
        return self.kind is not None

    def __repr__(self) -> str:
        if self.kind is None:
            return f"MeshFit(None, reason={self.reason!r})"
        return f"MeshFit({self.kind.value}, error={self.error!r})"


def fit_primitive(positions: npt.ArrayLike, triangles: npt.ArrayLike,
                  tolerance: float = FIT_TOLERANCE) -> MeshFit:
    """Recognises one of the four primitives in a triangle mesh.

    ``positions`` is an (n, 3) array, ``triangles`` three vertex indices a
    triangle (an (m, 3) array, or flat), counter-clockwise seen from
    outside. The rules are the glTF reader's (docs/GLTF.md, "Other
    programs' meshes"): a flat rectangle or disc is a PLANE facing its
    winding's normal, then a box, a capped cylinder, a sphere. ``tolerance``
    is the largest deviation accepted, relative to the shape's size (above 0).
    """
    checked = _checks.real(tolerance, "tolerance", 0.0, excluded=(True, False))
    indices = np.asarray(triangles)
    if indices.size and (not np.issubdtype(indices.dtype, np.integer) or indices.min() < 0):
        raise ValueError("the triangles must be vertex indices: whole numbers from 0")
    if indices.size and indices.max() > np.iinfo(np.uint32).max:
        raise ValueError("a vertex index is past 2^32")
    try:
        points = np.asarray(positions, dtype=np.float64)
    except (TypeError, ValueError):
        raise TypeError("positions must be an (n, 3) array of numbers") from None
    if points.size % 3 or (points.ndim > 1 and points.shape[-1] != 3):
        raise ValueError(f"positions must be an (n, 3) array, not of shape {points.shape}")
    kind, matrix, error, reason = _core.fit_primitive(
        points.reshape(-1, 3), indices.astype(np.uint32).reshape(-1), checked)
    return MeshFit(None if kind is None else ObjectKind(kind), matrix, error, reason)


def primitive_mesh(kind: Union[ObjectKind, str], segments: int = 32,
                   plane_half_size: float = 1.0) -> Tuple[npt.NDArray[np.float32],
                                                          npt.NDArray[np.float32],
                                                          npt.NDArray[np.uint32]]:
    """The triangle mesh that stands for ``kind`` (the one the glTF writer and
    sfbuild draw), in the primitive's local space: positions (n, 3), unit
    normals (n, 3) and triangles (m, 3), counter-clockwise seen from outside;
    a PLANE is the square [-plane_half_size, plane_half_size]^2 of y = 0."""
    name = _kind(kind, ObjectKind, "object kind").value
    count = _checks.whole(segments, "segments", _core.MIN_SEGMENTS, _core.MAX_SEGMENTS)
    # Within a float32, the mesh's type, and not rounded to 0 there.
    float32 = np.finfo(np.float32)
    half = _checks.real(plane_half_size, "plane_half_size", float(float32.tiny),
                        float(float32.max))
    return _core.primitive_mesh(name, count, half)


def formats() -> List[Dict[str, Any]]:
    """The formats, in the registry's order: name, singular, extensions,
    binary, and what each holds (materials, transform_lists, output_file,
    view)."""
    return _core.formats()
