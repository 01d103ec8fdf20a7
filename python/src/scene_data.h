// The scene and its diagnostics as plain Python data (dicts, tuples, numpy
// arrays), the form in which the extension module and the package's Python
// classes (scenefile/_model.py) hand them to each other: the C++ side never
// touches those classes, and they hold no C++ object that could dangle.
// _core.pyi documents the layout.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <string>

#include "scenefile/diagnostic.h"
#include "scenefile/scene.h"

namespace scenefile_python {

namespace py = pybind11;

// UTF-8 text as a str, bytes that are not UTF-8 handled by `errors`
// ("surrogateescape" for names that must come back as they were,
// "backslashreplace" for messages).
py::str decodeText(const std::string& text, const char* errors);
// A str as UTF-8, its surrogate escapes back to the bytes they stand for.
std::string encodeText(const py::handle& value, const char* what);

// A numpy float64 (4, 4) array, indexed [row, column] as the files write it.
py::array_t<double> matrixToArray(const glm::dmat4& m);
// Any (4, 4) array of numbers; a TypeError or ValueError for anything else.
glm::dmat4 matrixFromArray(const py::handle& value, const char* what);

py::tuple vectorToTuple(const glm::dvec3& v);
// Three numbers; a TypeError or ValueError for anything else.
glm::dvec3 vectorFromSequence(const py::handle& value, const char* what);

// One operation of a transform list: (kind name, (x, y, z)[, span]).
scene::TransformOp transformFromData(const py::handle& item);

// The dict of _core.pyi's SceneData.
py::dict sceneToData(const scene::Scene& scene);
// The scene a SceneData dict describes; a TypeError, ValueError or KeyError
// names what is wrong with it.
scene::Scene sceneFromData(const py::handle& data);

// Each diagnostic as the dict of _core.pyi's DiagnosticData.
py::list diagnosticsToData(const scene::DiagnosticList& list);

}  // namespace scenefile_python
