"""What would cure a diagnostic, said as this package's keywords.

The library names a setting that would cure a diagnostic as data (a
``Remedy``) and leaves ``{0}``, ``{1}``, ... in the hint where it goes, so
that each front end says it in its own terms: the tools as their flags
(``--max-file-size``), this package as the keyword that sets it
(``max_file_size=...``), the Blender add-on as its option.
"""

from __future__ import annotations

from typing import Callable, Sequence

from . import _core

# Each setting (by its stable name) as the keyword of read(), check(),
# write(), convert() or render() that sets it.
_KEYWORDS = {
    "max-file-size": "max_file_size", "max-objects": "max_objects",
    "max-gltf-nodes": "max_nodes", "transposed-matrices": "transpose_matrices",
    "skip-unsupported": "skip_unsupported", "approximate": "approximate",
    "field-of-view": "fov", "width": "width", "height": "height", "depth": "depth",
}


class Remedy:
    """A setting that would cure a diagnostic, and the value that would do.

    ``setting`` is the library's stable name ("max-file-size"), ``value``
    the value as text ("true" for an option to turn on; "" where the advice
    is only which setting to change).
    """

    __slots__ = ("setting", "value")

    def __init__(self, setting: str, value: str = "") -> None:
        self.setting, self.value = setting, value

    @property
    def keyword(self) -> str:
        """The keyword argument that sets it, or "" for none ("output-path": a
        rendered image is yours to save)."""
        return _KEYWORDS.get(self.setting, "")

    def __str__(self) -> str:
        """As a keyword argument: ``max_file_size=188``, ``approximate=True``."""
        if not self.keyword:
            return "the path the image is saved to" if self.setting == "output-path" else ""
        if self.value == "true":
            return f"{self.keyword}=True"
        return f"{self.keyword}={self.value}" if self.value else self.keyword

    def __repr__(self) -> str:
        return f"Remedy({self.setting!r}, {self.value!r})"

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Remedy):
            return NotImplemented
        return (self.setting, self.value) == (other.setting, other.value)

    def __hash__(self) -> int:
        return hash((self.setting, self.value))


def hint_in(template: str, remedies: Sequence[Remedy], words: Callable[[Remedy], str]) -> str:
    """``template`` with ``{N}`` replaced by ``words(remedies[N])``."""
    return _core.hint_text(template, [words(r) for r in remedies])
