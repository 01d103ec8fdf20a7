"""The extension module under scenefile: plain data in, plain data out.

Internal: scenefile/__init__.py and scenefile/_model.py turn these into the
classes users see. The data layout:

SceneData: {"camera": {"matrix", "colour", "look_at", "span"},
            "lights": [{"matrix", "colour", "span"}],
            "objects": [{"kind", "matrix", "material", "transforms", "span"}],
            "output_file", "output_file_span", "view": {"fov", "aspect_ratio", "span"} | None}
  matrix: float64 (4, 4) [row, column]; colour, look_at: (x, y, z);
  material: {"colour", "ambient", "diffuse", "specular", "shininess",
             "reflectivity", "transparency", "ri"};
  transforms: [(kind name, (x, y, z), span)] | None; span: (line, column, length).
DiagnosticData: {"severity", "code", "file", "span", "message", "hint",
                 "notes": [(span, message)], "fix_it": (span, replacement) | None}
"""

from typing import Any, Dict, List, Optional, Sequence, Tuple

import numpy as np
import numpy.typing as npt

SceneData = Dict[str, Any]
DiagnosticData = Dict[str, Any]
Matrix = npt.NDArray[np.float64]

__version__: str
FIT_TOLERANCE: float
DEFAULT_SEGMENTS: int
MIN_SEGMENTS: int
MAX_IMAGE_SIDE: int
MAX_SEGMENTS: int

def parse(data: bytes, name: str, format: Optional[str],
          options: Dict[str, Any]) -> Tuple[Optional[SceneData], List[DiagnosticData],
                                            Optional[str]]: ...
def check_file_size(size: int, name: str, options: Dict[str, Any]) -> List[DiagnosticData]: ...
def validate(scene: SceneData, name: str) -> List[DiagnosticData]: ...
def convert(scene: SceneData, format: str, options: Dict[str, Any],
            name: str) -> Tuple[Optional[bytes], bytes, List[DiagnosticData]]: ...
def render(scene: SceneData, width: int, height: int, spp: int, depth: int, fov: float,
           threads: int, seed: int) -> npt.NDArray[np.float32]: ...
def default_scene() -> SceneData: ...
def compose_transform(ops: Sequence[Tuple[Any, ...]]) -> Matrix: ...
def decompose_transform(matrix: npt.ArrayLike) -> Tuple[List[Tuple[str, Tuple[float, float, float]]],
                                                        bool]: ...
def check_output_file_name(name: str) -> Optional[str]: ...
def check_view(fov: float, aspect_ratio: Optional[float]) -> Optional[str]: ...
def write_files(files: List[Tuple[bytes, bytes]]) -> Optional[Tuple[bytes, str]]: ...
def output_clash(inputs: List[bytes], outputs: List[Tuple[bytes, bytes, str]]) -> Optional[str]: ...
def camera_from_look_at(location: Sequence[float], look_at: Sequence[float]) -> Matrix: ...
def fit_primitive(positions: npt.NDArray[np.float64], indices: npt.NDArray[np.uint32],
                  tolerance: float) -> Tuple[Optional[str], Optional[Matrix], Optional[float],
                                             str]: ...
def primitive_mesh(kind: str, segments: int,
                   plane_half_size: float) -> Tuple[npt.NDArray[np.float32],
                                                    npt.NDArray[np.float32],
                                                    npt.NDArray[np.uint32]]: ...
def formats() -> List[Dict[str, Any]]: ...
def format_by_extension(file_name: str) -> Optional[str]: ...
def suggest_spelling(word: str, candidates: List[str]) -> Optional[str]: ...
