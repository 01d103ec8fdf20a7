"""The scene model and the diagnostics as Python values.

The classes mirror the C++ model of include/scenefile/scene.h and
diagnostic.h. They are plain Python objects that own their data: a matrix is
a numpy float64 array of shape (4, 4), indexed [row, column] as the files
write it, so that ``m[:3, 3]`` is the translation; a colour is a tuple of
three floats. Equality compares values, as in C++: where a record came from
(its line) does not count.

An object's transform list and an instruction camera's LOOK_AT describe its
matrix only while they agree with it: the matrix is the truth. Assigning a
new matrix (or changing it in place) makes ``transforms`` and ``look_at``
None, as the C++ model asks of whoever changes a matrix, and the writers
then describe the matrix anew.
"""

from __future__ import annotations

import enum
from typing import (Any, Callable, Dict, Iterable, List, Optional, Sequence, Tuple, Union,
                    overload)

import numpy as np
import numpy.typing as npt

from . import _checks, _core
from ._remedy import Remedy, hint_in

Colour = Tuple[float, float, float]
Vector = Tuple[float, float, float]
Matrix = npt.NDArray[np.float64]
# What a colour, a vector or a matrix may be given as.
VectorLike = Union[Sequence[float], npt.ArrayLike]
MatrixLike = npt.ArrayLike
Span = Tuple[int, int, int]
_NO_SPAN: Span = (0, 0, 0)


class ObjectKind(str, enum.Enum):
    """The four primitives of FORMATS.md, each in its local space."""

    PLANE = "PLANE"  #: the plane y = 0, seen from both sides
    SPHERE = "SPHERE"  #: radius 1 about the origin
    CYLINDER = "CYLINDER"  #: radius 1 about Y, from y = -1 to 1, capped
    CUBE = "CUBE"  #: the box [-1, 1] on each axis

    def __str__(self) -> str:
        return self.value


class TransformKind(str, enum.Enum):
    """One operation of an instruction file's TRANSFORMATION section."""

    SCALE = "SCALE"
    TRANSLATE = "TRANSLATE"
    ROTATE_X = "ROTATE_X"
    ROTATE_Y = "ROTATE_Y"
    ROTATE_Z = "ROTATE_Z"

    def __str__(self) -> str:
        return self.value


class Severity(str, enum.Enum):
    """How bad a diagnostic is."""

    NOTE = "note"
    WARNING = "warning"
    ERROR = "error"

    def __str__(self) -> str:
        return self.value


# The model holds values as data, as the C++ model does: a number that is
# not finite is kept for validate() to point at (value-not-finite), which
# write() and render() run; only its type is checked when it is set.
def _number(value: Any, what: str) -> float:
    return _checks.real(value, what, finite=False)


def _vector(value: Any, what: str) -> Vector:
    return _checks.vector(value, what, finite=False)


def _matrix(value: Any, what: str) -> Matrix:
    try:
        m = np.array(value, dtype=np.float64)
    except (TypeError, ValueError):
        raise TypeError(f"{what} must be a 4 x 4 array of numbers") from None
    if m.shape != (4, 4):
        raise ValueError(f"{what} must be 4 x 4, not of shape {m.shape}")
    return m


def _kind(value: Any, enum_type: Any, what: str) -> Any:
    try:
        return enum_type(value)
    except ValueError:
        names = ", ".join(k.value for k in enum_type)
        hint = _core.suggest_spelling(str(value), [k.value for k in enum_type])
        did_you_mean = f"; did you mean {hint}?" if hint else ""
        raise ValueError(f"{value!r} is no {what}: {names}{did_you_mean}") from None


def _span(value: Any) -> Span:
    line, column, length = value
    return (int(line), int(column), int(length))


def _same(a: Optional[Matrix], b: Optional[Matrix]) -> bool:
    return a is not None and b is not None and bool(np.array_equal(a, b))


class _Number:
    """A float attribute of a Material, checked as a number when set."""

    def __set_name__(self, owner: type, name: str) -> None:
        self._public, self._private = name, "_" + name

    @overload
    def __get__(self, obj: None, owner: type) -> _Number: ...

    @overload
    def __get__(self, obj: object, owner: type) -> float: ...

    def __get__(self, obj: Optional[object], owner: type) -> Union[_Number, float]:
        return self if obj is None else float(getattr(obj, self._private))

    def __set__(self, obj: object, value: float) -> None:
        setattr(obj, self._private, _number(value, self._public))


class Material:
    """The Phong material of FORMATS.md; scene files carry only the colour."""

    _NAMES = ("ambient", "diffuse", "specular", "shininess", "reflectivity", "transparency", "ri")
    __slots__ = ("_colour",) + tuple("_" + n for n in _NAMES)
    _DEFAULTS = (0.1, 0.9, 0.9, 200.0, 0.0, 0.0, 1.0)

    ambient = _Number()  #: AMBIENT, in [0, 1]
    diffuse = _Number()  #: DIFFUSE, in [0, 1]
    specular = _Number()  #: SPECULAR, in [0, 1]
    shininess = _Number()  #: SHININESS, above 0
    reflectivity = _Number()  #: REFLECTIVITY, in [0, 1]
    transparency = _Number()  #: TRANSPARENCY, in [0, 1]
    ri = _Number()  #: RI, the refractive index, above 0

    def __init__(self, colour: VectorLike = (1.0, 1.0, 1.0), ambient: float = 0.1,
                 diffuse: float = 0.9, specular: float = 0.9, shininess: float = 200.0,
                 reflectivity: float = 0.0, transparency: float = 0.0, ri: float = 1.0) -> None:
        self._colour = _vector(colour, "colour")
        self.ambient, self.diffuse, self.specular = ambient, diffuse, specular
        self.shininess, self.reflectivity = shininess, reflectivity
        self.transparency, self.ri = transparency, ri

    @property
    def colour(self) -> Colour:
        """Red, green, blue: non-negative, above 1 allowed with a warning."""
        return self._colour

    @colour.setter
    def colour(self, value: VectorLike) -> None:
        self._colour = _vector(value, "colour")

    @property
    def _values(self) -> Tuple[float, ...]:
        return tuple(getattr(self, n) for n in self._NAMES)

    def is_default(self) -> bool:
        """Whether every value but the colour is the default (what a scene file holds)."""
        return self._values == self._DEFAULTS

    def copy(self) -> Material:
        return Material(self._colour, *self._values)

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Material):
            return NotImplemented
        return self._colour == other._colour and self._values == other._values

    def __repr__(self) -> str:
        values = ", ".join(f"{n}={v!r}" for n, v in zip(self._NAMES, self._values))
        return f"Material(colour={self._colour!r}, {values})"

    def _to_data(self) -> Dict[str, Any]:
        data: Dict[str, Any] = dict(zip(self._NAMES, self._values))
        data["colour"] = self._colour
        return data

    @classmethod
    def _from_data(cls, data: Dict[str, Any]) -> Material:
        return cls(data["colour"], *(data[n] for n in cls._NAMES))


class TransformOp:
    """One SCALE, TRANSLATE or ROTATE_* operation; immutable.

    ``value`` is (x, y, z) for SCALE and TRANSLATE, and (angle, 0, 0) for a
    rotation, the angle in radians (also ``angle``), as in the C++ model.
    """

    __slots__ = ("_kind", "_value", "_span")

    def __init__(self, kind: Union[TransformKind, str], value: Union[float, VectorLike]) -> None:
        self._kind: TransformKind = _kind(kind, TransformKind, "transform kind")
        if self._kind in (TransformKind.SCALE, TransformKind.TRANSLATE):
            self._value = _vector(value, f"{self._kind.value}'s value")
        elif isinstance(value, (int, float, np.integer, np.floating)):
            self._value = (_number(value, f"{self._kind.value}'s angle"), 0.0, 0.0)
        else:
            v = _vector(value, f"{self._kind.value}'s value")
            if v[1] != 0.0 or v[2] != 0.0:
                raise ValueError(f"{self._kind.value} takes one angle, not {v}")
            self._value = v
        self._span = _NO_SPAN

    @classmethod
    def scale(cls, x: float, y: Optional[float] = None, z: Optional[float] = None) -> TransformOp:
        """SCALE x y z; one factor scales every axis."""
        return cls(TransformKind.SCALE, (x, x if y is None else y, x if z is None else z))

    @classmethod
    def translate(cls, x: float, y: float, z: float) -> TransformOp:
        return cls(TransformKind.TRANSLATE, (x, y, z))

    @classmethod
    def rotate_x(cls, radians: float) -> TransformOp:
        return cls(TransformKind.ROTATE_X, radians)

    @classmethod
    def rotate_y(cls, radians: float) -> TransformOp:
        return cls(TransformKind.ROTATE_Y, radians)

    @classmethod
    def rotate_z(cls, radians: float) -> TransformOp:
        return cls(TransformKind.ROTATE_Z, radians)

    @property
    def kind(self) -> TransformKind:
        return self._kind

    @property
    def value(self) -> Vector:
        return self._value

    @property
    def angle(self) -> float:
        """A rotation's angle in radians; ValueError for SCALE and TRANSLATE."""
        if self._kind in (TransformKind.SCALE, TransformKind.TRANSLATE):
            raise ValueError(f"{self._kind.value} has no angle")
        return self._value[0]

    @property
    def matrix(self) -> Matrix:
        """The operation's 4 x 4 matrix, as FORMATS.md defines it."""
        return _core.compose_transform([self._to_data()])

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, TransformOp):
            return NotImplemented
        return self._kind == other._kind and self._value == other._value

    def __hash__(self) -> int:
        return hash((self._kind, self._value))

    def __repr__(self) -> str:
        if self._kind in (TransformKind.SCALE, TransformKind.TRANSLATE):
            return f"TransformOp.{self._kind.value.lower()}{self._value!r}"
        return f"TransformOp.{self._kind.value.lower()}({self._value[0]!r})"

    def _to_data(self) -> Tuple[Any, ...]:
        return (self._kind.value, self._value, self._span)

    @classmethod
    def _from_data(cls, data: Tuple[Any, ...]) -> TransformOp:
        op = cls(data[0], data[1])
        if len(data) > 2:
            op._span = _span(data[2])
        return op


def compose_transform(ops: Iterable[TransformOp]) -> Matrix:
    """M = Ok * ... * O2 * O1 for operations O1..Ok in file order."""
    try:
        items = list(ops)
    except TypeError:
        raise TypeError(f"ops must be TransformOps, not {type(ops).__name__}") from None
    return _core.compose_transform(
        [_checks.instance(op, "each of ops", TransformOp)._to_data() for op in items])


class View:
    """What a POV-Ray or glTF camera shows beyond its matrix."""

    __slots__ = ("_fov", "_aspect_ratio", "_span")

    def __init__(self, fov: float = 60.0, aspect_ratio: Optional[float] = None) -> None:
        self.fov = fov
        self.aspect_ratio = aspect_ratio
        self._span = _NO_SPAN

    @property
    def fov(self) -> float:
        """The vertical field of view in degrees: validate() takes 0.001 to 179.999."""
        return self._fov

    @fov.setter
    def fov(self, value: float) -> None:
        self._fov = _number(value, "fov")

    @property
    def aspect_ratio(self) -> Optional[float]:
        """The image's width over its height, where the file says: validate()
        takes 1/32768 to 32768."""
        return self._aspect_ratio

    @aspect_ratio.setter
    def aspect_ratio(self, value: Optional[float]) -> None:
        self._aspect_ratio = None if value is None else _number(value, "aspect_ratio")

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, View):
            return NotImplemented
        return self._fov == other._fov and self._aspect_ratio == other._aspect_ratio

    def __repr__(self) -> str:
        return f"View(fov={self._fov!r}, aspect_ratio={self._aspect_ratio!r})"


class Camera:
    """The pinhole camera: the eye at m[:3, 3], forward -m[:3, 2], up m[:3, 1]."""

    __slots__ = ("_matrix", "_colour", "_look_at", "_look_at_matrix", "_span")

    def __init__(self, matrix: Optional[MatrixLike] = None,
                 colour: VectorLike = (0.0, 0.0, 0.0)) -> None:
        self._matrix = np.identity(4) if matrix is None else _matrix(matrix, "the camera's matrix")
        self._colour = _vector(colour, "the camera's colour")
        self._look_at: Optional[Vector] = None
        self._look_at_matrix: Optional[Matrix] = None
        self._span = _NO_SPAN

    @classmethod
    def looking_at(cls, location: VectorLike, look_at: VectorLike) -> Camera:
        """An instruction file's camera: the eye at location, looking at look_at, up from +Y."""
        # Arguments of a computation, not data: finite, or the matrix is not.
        eye, target = _checks.vector(location, "location"), _checks.vector(look_at, "look_at")
        camera = cls()
        camera._matrix = _core.camera_from_look_at(eye, target)
        camera._look_at = target
        camera._look_at_matrix = camera._matrix.copy()
        return camera

    @property
    def matrix(self) -> Matrix:
        """Camera to world, 4 x 4."""
        return self._matrix

    @matrix.setter
    def matrix(self, value: MatrixLike) -> None:
        self._matrix = _matrix(value, "the camera's matrix")

    @property
    def colour(self) -> Colour:
        """A scene file's CAMERA colour, which nothing uses; kept to write it back."""
        return self._colour

    @colour.setter
    def colour(self, value: VectorLike) -> None:
        self._colour = _vector(value, "the camera's colour")

    @property
    def look_at(self) -> Optional[Vector]:
        """An instruction camera's LOOK_AT point, while the matrix is the one it gave."""
        return self._look_at if _same(self._matrix, self._look_at_matrix) else None

    @look_at.setter
    def look_at(self, value: Optional[VectorLike]) -> None:
        if value is None:
            self._look_at = self._look_at_matrix = None
            return
        camera = Camera.looking_at(self.eye, value)
        self._matrix, self._look_at = camera._matrix, camera._look_at
        self._look_at_matrix = camera._look_at_matrix

    @property
    def eye(self) -> Vector:
        return _vector(self._matrix[:3, 3], "eye")

    @property
    def forward(self) -> Vector:
        return _vector(-self._matrix[:3, 2], "forward")

    @property
    def up(self) -> Vector:
        return _vector(self._matrix[:3, 1], "up")

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Camera):
            return NotImplemented
        return (bool(np.array_equal(self._matrix, other._matrix)) and self._colour == other._colour
                and self.look_at == other.look_at)

    def __repr__(self) -> str:
        look_at = f", look_at={self.look_at!r}" if self.look_at is not None else ""
        return f"Camera(eye={self.eye!r}, forward={self.forward!r}{look_at})"

    def _to_data(self) -> Dict[str, Any]:
        return {"matrix": self._matrix, "colour": self._colour, "look_at": self.look_at,
                "span": self._span}

    @classmethod
    def _from_data(cls, data: Dict[str, Any]) -> Camera:
        camera = cls(data["matrix"], data["colour"])
        if data.get("look_at") is not None:
            camera._look_at = _vector(data["look_at"], "look_at")
            camera._look_at_matrix = camera._matrix.copy()
        camera._span = _span(data.get("span", _NO_SPAN))
        return camera


class Light:
    """A point light at m[:3, 3]; the rest of the matrix is kept, unused."""

    __slots__ = ("_matrix", "_colour", "_span")

    def __init__(self, position: Optional[VectorLike] = None, colour: VectorLike = (1.0, 1.0, 1.0),
                 matrix: Optional[MatrixLike] = None) -> None:
        self._matrix = np.identity(4) if matrix is None else _matrix(matrix, "a light's matrix")
        if position is not None:
            self._matrix[:3, 3] = _vector(position, "a light's position")
        self._colour = _vector(colour, "a light's colour")
        self._span = _NO_SPAN

    @property
    def matrix(self) -> Matrix:
        return self._matrix

    @matrix.setter
    def matrix(self, value: MatrixLike) -> None:
        self._matrix = _matrix(value, "a light's matrix")

    @property
    def position(self) -> Vector:
        return _vector(self._matrix[:3, 3], "position")

    @position.setter
    def position(self, value: VectorLike) -> None:
        self._matrix = self._matrix.copy()
        self._matrix[:3, 3] = _vector(value, "a light's position")

    @property
    def colour(self) -> Colour:
        """Intensity per channel: non-negative, may exceed 1."""
        return self._colour

    @colour.setter
    def colour(self, value: VectorLike) -> None:
        self._colour = _vector(value, "a light's colour")

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Light):
            return NotImplemented
        return bool(np.array_equal(self._matrix, other._matrix)) and self._colour == other._colour

    def __repr__(self) -> str:
        return f"Light(position={self.position!r}, colour={self._colour!r})"

    def _to_data(self) -> Dict[str, Any]:
        return {"matrix": self._matrix, "colour": self._colour, "span": self._span}

    @classmethod
    def _from_data(cls, data: Dict[str, Any]) -> Light:
        light = cls(colour=data["colour"], matrix=data["matrix"])
        light._span = _span(data.get("span", _NO_SPAN))
        return light


class Object:
    """One primitive placed by its local-to-world matrix, with its material.

    Give the matrix, or an instruction file's transform list (which then
    makes the matrix); both, and they must agree.
    """

    __slots__ = ("_kind", "_matrix", "_material", "_transforms", "_transforms_matrix", "_span")

    def __init__(self, kind: Union[ObjectKind, str], matrix: Optional[MatrixLike] = None, *,
                 colour: Optional[VectorLike] = None, material: Optional[Material] = None,
                 transforms: Optional[Iterable[TransformOp]] = None) -> None:
        self._kind: ObjectKind = _kind(kind, ObjectKind, "object kind")
        self._material = Material() if material is None else _material(material)
        if colour is not None:
            self._material.colour = _vector(colour, "colour")
        self._transforms: Optional[Tuple[TransformOp, ...]] = None
        self._transforms_matrix: Optional[Matrix] = None
        self._matrix = np.identity(4) if matrix is None else _matrix(matrix, "an object's matrix")
        self._span = _NO_SPAN
        if transforms is not None:
            given = self._matrix
            self._set_transforms(transforms)
            if matrix is not None and not np.array_equal(given, self._matrix):
                raise ValueError("the matrix is not the one the transforms make")

    @property
    def kind(self) -> ObjectKind:
        return self._kind

    @kind.setter
    def kind(self, value: Union[ObjectKind, str]) -> None:
        self._kind = _kind(value, ObjectKind, "object kind")

    @property
    def matrix(self) -> Matrix:
        """Local to world, 4 x 4, [row, column]."""
        return self._matrix

    @matrix.setter
    def matrix(self, value: MatrixLike) -> None:
        self._matrix = _matrix(value, "an object's matrix")

    @property
    def material(self) -> Material:
        return self._material

    @material.setter
    def material(self, value: Material) -> None:
        self._material = _material(value)

    @property
    def colour(self) -> Colour:
        """The material's colour."""
        return self._material.colour

    @colour.setter
    def colour(self, value: VectorLike) -> None:
        self._material.colour = _vector(value, "colour")

    @property
    def transforms(self) -> Optional[Tuple[TransformOp, ...]]:
        """The operations of an instruction file, while the matrix is what they make."""
        return self._transforms if _same(self._matrix, self._transforms_matrix) else None

    @transforms.setter
    def transforms(self, value: Optional[Iterable[TransformOp]]) -> None:
        self._set_transforms(value)

    def _set_transforms(self, value: Optional[Iterable[TransformOp]]) -> None:
        if value is None:
            self._transforms = self._transforms_matrix = None
            return
        ops = tuple(value)
        for op in ops:
            if not isinstance(op, TransformOp):
                raise TypeError(f"a transform must be a TransformOp, not {type(op).__name__}")
        self._matrix = compose_transform(ops)
        self._transforms, self._transforms_matrix = ops, self._matrix.copy()

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Object):
            return NotImplemented
        return (self._kind == other._kind and self._material == other._material
                and bool(np.array_equal(self._matrix, other._matrix))
                and self.transforms == other.transforms)

    def __repr__(self) -> str:
        return (f"Object({self._kind.value}, translation={_vector(self._matrix[:3, 3], 't')!r}, "
                f"colour={self.colour!r})")

    def _to_data(self) -> Dict[str, Any]:
        transforms = self.transforms
        return {"kind": self._kind.value, "matrix": self._matrix,
                "material": self._material._to_data(),
                "transforms": None if transforms is None else [op._to_data() for op in transforms],
                "span": self._span}

    @classmethod
    def _from_data(cls, data: Dict[str, Any]) -> Object:
        obj = cls(data["kind"], data["matrix"], material=Material._from_data(data["material"]))
        if data.get("transforms") is not None:
            obj._transforms = tuple(TransformOp._from_data(t) for t in data["transforms"])
            obj._transforms_matrix = obj._matrix.copy()
        obj._span = _span(data.get("span", _NO_SPAN))
        return obj


def _material(value: Any) -> Material:
    if not isinstance(value, Material):
        raise TypeError(f"a material must be a Material, not {type(value).__name__}")
    return value


def _place(line: Any, column: Any, length: Any) -> Tuple[int, int, int]:
    """A place in a file: line, column and length, whole numbers from 0 (0: unknown)."""
    most = (1 << 63) - 1
    return (_checks.whole(line, "line", 0, most), _checks.whole(column, "column", 0, most),
            _checks.whole(length, "length", 0, most))


class Note:
    """A secondary place that explains a diagnostic ("block opened here")."""

    __slots__ = ("line", "column", "length", "message")

    def __init__(self, line: int, column: int, length: int, message: str) -> None:
        self.line, self.column, self.length = _place(line, column, length)
        self.message = message

    def __repr__(self) -> str:
        return f"Note(line={self.line}, column={self.column}, message={self.message!r})"


class FixIt:
    """A replacement that fixes the problem: the text at (line, column, length)."""

    __slots__ = ("line", "column", "length", "replacement")

    def __init__(self, line: int, column: int, length: int, replacement: str) -> None:
        self.line, self.column, self.length = _place(line, column, length)
        self.replacement = replacement

    def __repr__(self) -> str:
        return f"FixIt(line={self.line}, column={self.column}, replacement={self.replacement!r})"


class Diagnostic:
    """A problem found in an input, with a stable code (docs/DIAGNOSTICS.md).

    ``str()`` gives the tools' one-line form: ``file:line:column: error:
    message [code]`` (without line and column where the place is unknown).
    Lines and columns count from 1; columns count bytes; 0 is unknown.
    ``remedies`` are the settings that would cure it; ``hint`` names them as
    this package's keywords, and ``hint_in`` in other words.
    """

    __slots__ = ("severity", "code", "file", "line", "column", "length", "message", "_hint",
                 "notes", "fix_it", "remedies")

    def __init__(self, severity: Union[Severity, str], code: str, file: str, line: int,
                 column: int, message: str, hint: str = "", length: int = 0,
                 notes: Sequence[Note] = (), fix_it: Optional[FixIt] = None,
                 remedies: Sequence[Remedy] = ()) -> None:
        self.severity = Severity(severity)
        self.line, self.column, self.length = _place(line, column, length)
        self.code, self.file, self.message, self._hint = code, file, message, hint
        self.notes: List[Note] = list(notes)
        self.fix_it = fix_it
        self.remedies: List[Remedy] = list(remedies)

    @property
    def hint(self) -> str:
        """One line of advice, or "": ``raise the limit with max_file_size=188 ...``."""
        return self.hint_in(str)

    def hint_in(self, words: Callable[[Remedy], str]) -> str:
        """The hint with each remedy said as ``words(remedy)``: a front end's own terms."""
        return hint_in(self._hint, self.remedies, words) if self.remedies else self._hint

    @property
    def location(self) -> str:
        where = self.file or "<input>"
        return f"{where}:{self.line}:{self.column}:" if self.line else f"{where}:"

    def __str__(self) -> str:
        return f"{self.location} {self.severity.value}: {self.message} [{self.code}]"

    def __repr__(self) -> str:
        return f"<Diagnostic {self}>"

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Diagnostic):
            return NotImplemented
        return all(getattr(self, n) == getattr(other, n)
                   for n in ("severity", "code", "file", "line", "column", "length", "message",
                             "hint"))

    @classmethod
    def _from_data(cls, data: Dict[str, Any]) -> Diagnostic:
        line, column, length = data["span"]
        notes = [Note(s[0], s[1], s[2], message) for s, message in data["notes"]]
        fix_it = None
        if data["fix_it"] is not None:
            (fl, fc, flen), replacement = data["fix_it"]
            fix_it = FixIt(fl, fc, flen, replacement)
        remedies = [Remedy(setting, value) for setting, value in data["remedies"]]
        return cls(data["severity"], data["code"], data["file"], line, column, data["message"],
                   data["hint"], length, notes, fix_it, remedies)


def _diagnostics(data: Iterable[Dict[str, Any]]) -> List[Diagnostic]:
    return [Diagnostic._from_data(d) for d in data]


class Scene:
    """A whole scene: the camera, the lights and the objects, each in order.

    A scene read from a file also says where it came from (``source``, its
    ``format``) and what the reader noted (``diagnostics``: its warnings and
    notes); those are not part of its value.
    """

    __slots__ = ("camera", "lights", "objects", "_output_file", "_output_file_span", "view",
                 "source", "format", "diagnostics")

    def __init__(self, camera: Optional[Camera] = None, lights: Optional[Iterable[Light]] = None,
                 objects: Optional[Iterable[Object]] = None, output_file: Optional[str] = None,
                 view: Optional[View] = None) -> None:
        self.camera: Camera = Camera() if camera is None else camera
        self.lights: List[Light] = [] if lights is None else list(lights)
        self.objects: List[Object] = [] if objects is None else list(objects)
        self.output_file = output_file
        self._output_file_span = _NO_SPAN
        self.view: Optional[View] = view
        self.source: Optional[str] = None
        self.format: Optional[str] = None
        self.diagnostics: List[Diagnostic] = []

    @property
    def output_file(self) -> Optional[str]:
        """An instruction file's OUTPUT_FILE, exactly as written."""
        return self._output_file

    @output_file.setter
    def output_file(self, value: Optional[str]) -> None:
        if value is not None and not isinstance(value, str):
            raise TypeError(f"output_file must be a str, not {type(value).__name__}")
        self._output_file = value

    @property
    def warnings(self) -> List[Diagnostic]:
        """The warnings among ``diagnostics``."""
        return [d for d in self.diagnostics if d.severity == Severity.WARNING]

    def copy(self) -> Scene:
        """A deep copy: editing it leaves this scene as it is."""
        other = Scene._from_data(self._to_data())
        other.source, other.format, other.diagnostics = self.source, self.format, list(
            self.diagnostics)
        return other

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Scene):
            return NotImplemented
        return (self.camera == other.camera and self.lights == other.lights
                and self.objects == other.objects and self._output_file == other._output_file
                and self.view == other.view)

    def __repr__(self) -> str:
        source = f", from {self.source!r}" if self.source else ""
        return f"<Scene: {len(self.objects)} objects, {len(self.lights)} lights{source}>"

    def _to_data(self) -> Dict[str, Any]:
        if not isinstance(self.camera, Camera):
            raise TypeError(f"the camera must be a Camera, not {type(self.camera).__name__}")
        checks: Tuple[Tuple[str, Sequence[object], type], ...] = (
            ("light", self.lights, Light), ("object", self.objects, Object))
        for what, items, cls in checks:
            for i, item in enumerate(items):
                if not isinstance(item, cls):
                    raise TypeError(f"{what}s[{i}] is a {type(item).__name__}, not a {cls.__name__}")
        view = None
        if self.view is not None:
            view = {"fov": self.view.fov, "aspect_ratio": self.view.aspect_ratio,
                    "span": self.view._span}
        return {"camera": self.camera._to_data(), "lights": [x._to_data() for x in self.lights],
                "objects": [x._to_data() for x in self.objects], "output_file": self._output_file,
                "output_file_span": self._output_file_span, "view": view}

    @classmethod
    def _from_data(cls, data: Dict[str, Any]) -> Scene:
        scene = cls(Camera._from_data(data["camera"]),
                    [Light._from_data(x) for x in data["lights"]],
                    [Object._from_data(x) for x in data["objects"]], data["output_file"])
        scene._output_file_span = _span(data.get("output_file_span", _NO_SPAN))
        if data.get("view") is not None:
            view = data["view"]
            scene.view = View(view["fov"], view["aspect_ratio"])
            scene.view._span = _span(view.get("span", _NO_SPAN))
        return scene
