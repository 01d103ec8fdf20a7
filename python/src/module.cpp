// scenefile._core: the extension module under the Python package scenefile.
// It speaks plain data (scene_data.h); the package's Python layer
// (scenefile/__init__.py) turns that into the classes users see, checks the
// arguments and raises SceneError. Only the public API (include/scenefile)
// and the renderer are used here (tests/layout/check_public_api.sh).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cerrno>
#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "python/src/file_writes.h"
#include "python/src/render_image.h"
#include "python/src/scene_data.h"
#include "renderer/default_scene.h"
#include "scenefile/convert.h"
#include "scenefile/format.h"
#include "scenefile/mesh.h"
#include "scenefile/mesh_fit.h"
#include "scenefile/read.h"
#include "scenefile/read_file.h"
#include "scenefile/render.h"
#include "scenefile/spelling.h"
#include "scenefile/transform.h"
#include "scenefile/validation.h"

namespace scenefile_python {

namespace {

// A key of an options dict, when it is there and not None.
template <typename T>
std::optional<T> option(const py::dict& options, const char* key) {
  if (!options.contains(key) || options[key].is_none()) return std::nullopt;
  return py::cast<T>(options[key]);
}

const scene::FormatInfo& formatNamed(const std::string& name) {
  const scene::FormatInfo* info = scene::findFormatByName(name);
  if (!info) throw py::value_error("'" + name + "' is no format: " + scene::formatNames());
  return *info;
}

scene::ReadOptions readOptionsFrom(const py::dict& o) {
  scene::ReadOptions options;
  if (auto v = option<std::size_t>(o, "error_limit")) options.errorLimit = *v;
  if (auto v = option<bool>(o, "no_loss")) options.noLoss = *v;
  if (auto v = option<std::uint64_t>(o, "max_file_size")) options.maxFileSize = *v;
  if (auto v = option<std::size_t>(o, "max_objects")) options.maxObjects = *v;
  if (auto v = option<std::size_t>(o, "max_vertices")) {
    options.gltf.maxVertices = *v;
    options.obj.maxVertices = *v;
  }
  if (auto v = option<std::size_t>(o, "max_nodes")) options.gltf.maxNodes = *v;
  if (auto v = option<bool>(o, "transpose_matrices")) options.sceneFile.transposedMatrices = *v;
  if (auto v = option<bool>(o, "skip_unsupported")) options.pov.skipUnsupported = *v;
  auto width = option<int>(o, "width");
  auto height = option<int>(o, "height");
  if (width && height) {
    options.pov.imageWidth = *width;
    options.pov.imageHeight = *height;
  }
  return options;
}

scene::ConversionOptions conversionOptionsFrom(const py::dict& o) {
  scene::ConversionOptions options;
  if (auto v = option<bool>(o, "no_loss")) options.noLoss = *v;
  if (auto v = option<bool>(o, "approximate")) options.instructions.approximate = *v;
  if (o.contains("output_file") && !o["output_file"].is_none()) {
    options.instructions.outputFile = encodeText(o["output_file"], "output_file");
  }
  std::optional<double> fov = option<double>(o, "fov");
  int width = option<int>(o, "width").value_or(0);
  int height = option<int>(o, "height").value_or(0);
  options.gltf.yfovDegrees = fov;
  options.gltf.width = width;
  options.gltf.height = height;
  if (auto v = option<int>(o, "tessellation")) options.gltf.segments = options.obj.segments = *v;
  if (auto v = option<std::string>(o, "external_buffer")) options.gltf.externalBuffer = *v;
  if (auto v = option<std::string>(o, "material_library")) options.obj.materialLibrary = *v;
  if (auto v = option<std::string>(o, "generator")) options.gltf.generator = *v;
  if (auto v = option<bool>(o, "no_lights")) options.gltf.lights = !*v;
  if (auto v = option<bool>(o, "no_extras")) options.gltf.extras = !*v;
  if (auto v = option<std::string>(o, "light_falloff")) {
    if (*v != "inverse-square" && *v != "none") {
      throw py::value_error("light_falloff must be 'inverse-square' or 'none', not '" + *v + "'");
    }
    options.gltf.lightFalloff =
        *v == "none" ? scene::GltfLightFalloff::None : scene::GltfLightFalloff::InverseSquare;
  }
  options.pov.verticalFovDegrees = fov;
  if (width > 0 && height > 0) {
    options.pov.width = width;
    options.pov.height = height;
  } else if (width > 0 || height > 0) {
    // One side given: the other keeps sfrender's 4:3, as sfconvert does.
    options.pov.width = width > 0 ? width : std::max(1, height * 4 / 3);
    options.pov.height = height > 0 ? height : std::max(1, width * 3 / 4);
  }
  if (auto v = option<bool>(o, "flat")) options.pov.flat = *v;
  if (auto v = option<int>(o, "depth")) options.pov.maxDepth = *v;
  return options;
}

std::string_view bytesView(const py::bytes& data) {
  return {PyBytes_AS_STRING(data.ptr()), static_cast<std::size_t>(PyBytes_GET_SIZE(data.ptr()))};
}

// The scene in `text`, named `file`, read as the format named `format` or
// as detected: (SceneData | None, diagnostics, format name | None).
py::tuple parseText(std::string_view text, const std::string& file, const scene::FormatInfo* as,
                    const scene::ReadOptions& read) {
  scene::ReadResult result;
  std::optional<scene::Format> detected;
  {
    // The text is the caller's and stays put: safe to read unlocked.
    py::gil_scoped_release release;
    detected = as ? std::optional<scene::Format>(as->format) : scene::detectFormat(text, file);
    result = as ? scene::parseSceneAs(as->format, text, file, read)
                : scene::parseScene(text, file, read);
  }
  py::object formatName = py::none();
  if (detected) formatName = py::str(std::string(scene::formatInfo(*detected).name));
  py::object sceneData = result.ok() ? py::object(sceneToData(result.scene)) : py::none();
  return py::make_tuple(sceneData, diagnosticsToData(result.diagnostics), formatName);
}

// parse(data, name, format, options) -> (SceneData | None, diagnostics, format name | None)
py::tuple parse(const py::bytes& data, const py::str& name,
                const std::optional<std::string>& format, const py::dict& options) {
  const scene::FormatInfo* as = format ? &formatNamed(*format) : nullptr;
  return parseText(bytesView(data), encodeText(name, "the file name"), as,
                   readOptionsFrom(options));
}

// read_file(path, name, format, options)
//   -> (SceneData | None, diagnostics, format name | None, errno)
// The file at `path` (bytes, os.fsencode) read as the tools read theirs
// (scenefile/read_file.h), its diagnostics naming it `name`; errno is the
// system's error when it could not be read, else 0, and then there is no
// diagnostic: Python raises OSError instead.
py::tuple readFile(const py::bytes& path, const py::str& name,
                   const std::optional<std::string>& format, const py::dict& options) {
  const scene::FormatInfo* as = format ? &formatNamed(*format) : nullptr;
  scene::ReadOptions read = readOptionsFrom(options);
  std::filesystem::path where(std::string(bytesView(path)));
  std::string file = encodeText(name, "the file name");
  scene::SourceText source;
  {
    py::gil_scoped_release release;
    source = scene::readSourceFile(where, read, file);
  }
  if (!source.readError.empty()) {
    int code = source.readErrorCode ? source.readErrorCode.value() : EIO;
    return py::make_tuple(py::none(), py::list(), py::none(), code);
  }
  if (!source.text) {
    return py::make_tuple(py::none(), diagnosticsToData(source.diagnostics), py::none(), 0);
  }
  py::tuple parsed = parseText(*source.text, file, as, read);
  return py::make_tuple(parsed[0], parsed[1], parsed[2], 0);
}

py::list checkFileSize(std::uint64_t size, const py::str& name, const py::dict& options) {
  scene::DiagnosticList out(encodeText(name, "the file name"));
  scene::checkFileSize(size, readOptionsFrom(options), out);
  return diagnosticsToData(out);
}

py::list validate(const py::handle& data, const py::str& name) {
  scene::Scene s = sceneFromData(data);
  std::string file = encodeText(name, "the file name");
  scene::DiagnosticList out(file);
  {
    py::gil_scoped_release release;
    // Every number finite first: the value rules assume it.
    if (scene::checkSceneFinite(s, out)) out.append(scene::validateScene(s, file));
  }
  return diagnosticsToData(out);
}

// convert(data, format, options, name) -> (main | None, sidecar, diagnostics)
py::tuple convert(const py::handle& data, const std::string& format, const py::dict& options,
                  const py::str& name) {
  scene::Scene s = sceneFromData(data);
  const scene::FormatInfo& info = formatNamed(format);
  scene::ConversionOptions conversion = conversionOptionsFrom(options);
  scene::DiagnosticList out(encodeText(name, "the file name"));
  std::optional<scene::ConvertedFiles> files;
  {
    py::gil_scoped_release release;
    files = scene::convertSceneToFiles(s, info.format, conversion, out);
  }
  if (!files) return py::make_tuple(py::none(), py::bytes(), diagnosticsToData(out));
  return py::make_tuple(py::bytes(files->main), py::bytes(files->sidecar), diagnosticsToData(out));
}

py::array_t<double> composeTransform(const py::iterable& ops) {
  std::vector<scene::TransformOp> list;
  for (py::handle item : ops) list.push_back(transformFromData(item));
  return matrixToArray(scene::composeTransform(list));
}

// The first error among `found`, as a ValueError.
void raiseFirstError(const scene::DiagnosticList& found) {
  for (const scene::Diagnostic& d : found.items()) {
    if (d.severity == scene::Severity::Error) throw py::value_error(d.message);
  }
}

// decompose_transform(matrix) -> (ops, exact): the instruction file's form,
// for a matrix an object may have (validation.h's rules); the form of any
// other would not be finite.
py::tuple decomposeTransform(const py::handle& matrix) {
  glm::dmat4 m = matrixFromArray(matrix, "the matrix");
  scene::DiagnosticList problems;
  scene::checkMatrixLastRow(m, scene::RecordSpans::uniform({}), problems);
  scene::checkObjectMatrix(m, "the", {}, problems);
  raiseFirstError(problems);
  scene::TransformDecomposition d = scene::decomposeTransform(m);
  for (const scene::TransformOp& op : d.ops) {
    if (!std::isfinite(op.value.x) || !std::isfinite(op.value.y) || !std::isfinite(op.value.z)) {
      throw py::value_error("the matrix has no decomposition in finite numbers");
    }
  }
  py::list ops;
  for (const scene::TransformOp& op : d.ops) {
    ops.append(py::make_tuple(py::str(std::string(scene::transformKindName(op.kind))),
                              vectorToTuple(op.value)));
  }
  return py::make_tuple(ops, d.exact());
}

// check_output_file_name(name) -> the reason an instruction file cannot
// hold it as its OUTPUT_FILE, or None: the readers' own rule.
std::optional<std::string> checkOutputFileName(const py::str& name) {
  scene::DiagnosticList problems;
  scene::checkOutputFileName(encodeText(name, "output_file"), {}, problems);
  if (problems.items().empty()) return std::nullopt;
  const scene::Diagnostic& d = problems.items().front();
  return d.message + " (" + d.hint + ")";
}

// output_file_name_for(path) -> the OUTPUT_FILE an instruction file written
// there gets when its scene has none, as sfconvert names it.
py::str outputFileNameFor(const py::str& path) {
  return decodeText(scene::outputFileNameFor(encodeText(path, "the path")), "surrogateescape");
}

// check_view(fov, aspect_ratio) -> why a view with these is out of range, or
// None: the one rule for a view, which validate() holds a scene's view to.
std::optional<std::string> checkView(double fov, std::optional<double> aspectRatio) {
  scene::View view;
  view.verticalFovDegrees = fov;
  view.aspectRatio = aspectRatio;
  scene::DiagnosticList problems;
  scene::checkView(view, {}, problems);
  if (problems.items().empty()) return std::nullopt;
  return problems.items().front().message;
}

py::array_t<double> cameraFromLookAt(const py::handle& location, const py::handle& lookAt) {
  glm::dvec3 eye = vectorFromSequence(location, "the location");
  glm::dvec3 target = vectorFromSequence(lookAt, "look_at");
  if (eye == target) throw py::value_error("the location and look_at are the same point");
  return matrixToArray(scene::cameraFromLookAt(eye, target));
}

// fit_primitive(positions (n, 3), indices (m,), tolerance)
//   -> (kind | None, shape | None, error, reason)
py::tuple fitPrimitive(
    const py::array_t<double, py::array::c_style | py::array::forcecast>& positions,
    const py::array_t<std::uint32_t, py::array::c_style | py::array::forcecast>& indices,
    double tolerance) {
  if (positions.ndim() != 2 || positions.shape(1) != 3) {
    throw py::value_error("the positions are not an array of shape (n, 3)");
  }
  std::vector<glm::dvec3> points(static_cast<std::size_t>(positions.shape(0)));
  auto p = positions.unchecked<2>();
  for (std::size_t i = 0; i < points.size(); ++i) {
    auto row = static_cast<py::ssize_t>(i);
    points[i] = {p(row, 0), p(row, 1), p(row, 2)};
  }
  std::vector<std::uint32_t> list(indices.data(), indices.data() + indices.size());
  scene::FitResult result;
  {
    py::gil_scoped_release release;
    result = scene::fitPrimitive(points, list, tolerance);
  }
  if (!result.fit) return py::make_tuple(py::none(), py::none(), py::none(), result.reason);
  return py::make_tuple(py::str(std::string(scene::objectKindName(result.fit->kind))),
                        matrixToArray(result.fit->shape), result.fit->error, result.reason);
}

// primitive_mesh(kind, segments, plane_half_size)
//   -> (positions (n, 3) float32, normals (n, 3) float32, triangles (m, 3) uint32)
py::tuple primitiveMesh(const std::string& kind, int segments, float planeHalfSize) {
  std::optional<scene::ObjectKind> known = scene::objectKindFromName(kind);
  if (!known) throw py::value_error("'" + kind + "' is no object kind");
  if (segments < scene::kMinSegments || segments > scene::kMaxSegments) {
    throw py::value_error("segments must lie between " + std::to_string(scene::kMinSegments) +
                          " and " + std::to_string(scene::kMaxSegments));
  }
  scene::TriangleMesh mesh = scene::primitiveMesh(*known, segments, planeHalfSize);
  auto n = static_cast<py::ssize_t>(mesh.positions.size());
  py::array_t<float> positions({n, py::ssize_t{3}});
  py::array_t<float> normals({n, py::ssize_t{3}});
  for (py::ssize_t i = 0; i < n; ++i) {
    for (py::ssize_t c = 0; c < 3; ++c) {
      positions.mutable_at(i, c) = mesh.positions[static_cast<std::size_t>(i)][static_cast<int>(c)];
      normals.mutable_at(i, c) = mesh.normals[static_cast<std::size_t>(i)][static_cast<int>(c)];
    }
  }
  auto triangles = static_cast<py::ssize_t>(mesh.indices.size() / 3);
  py::array_t<std::uint32_t> indices({triangles, py::ssize_t{3}});
  std::copy(mesh.indices.begin(), mesh.indices.end(), indices.mutable_data());
  return py::make_tuple(positions, normals, indices);
}

py::list formatRows() {
  py::list rows;
  for (const scene::FormatInfo& info : scene::formats()) {
    py::dict row;
    row["name"] = std::string(info.name);
    row["singular"] = std::string(info.singular);
    py::list extensions;
    for (std::string_view e : info.extensions) extensions.append(std::string(e));
    row["extensions"] = extensions;
    row["binary"] = info.binary;
    py::dict holds;
    holds["materials"] = info.holds.materials;
    holds["transform_lists"] = info.holds.transformLists;
    holds["output_file"] = info.holds.outputFile;
    holds["view"] = info.holds.view;
    row["holds"] = holds;
    rows.append(row);
  }
  return rows;
}

std::optional<std::string> formatByExtension(const std::string& fileName) {
  const scene::FormatInfo* info = scene::findFormatByExtension(fileName);
  if (!info) return std::nullopt;
  return std::string(info->name);
}

std::optional<std::string> suggestSpelling(const std::string& word,
                                           const std::vector<std::string>& candidates) {
  std::vector<std::string_view> views(candidates.begin(), candidates.end());
  std::optional<std::string_view> found = scene::suggestSpelling(word, views);
  if (!found) return std::nullopt;
  return std::string(*found);
}

// hint_text(hint, words) -> the hint with each "{N}" replaced by words[N]:
// the library's one rule for saying a diagnostic's remedies.
std::string hintText(const std::string& hint, const std::vector<std::string>& words) {
  std::vector<scene::Remedy> remedies(words.size());
  return scene::hintText(hint, remedies, [&](const scene::Remedy& remedy) {
    return words[static_cast<std::size_t>(&remedy - remedies.data())];
  });
}

py::array_t<float> render(const py::handle& data, int width, int height, int spp, int depth,
                          double fov, int threads, std::uint64_t seed) {
  scene::RenderSettings settings;
  settings.width = width;
  settings.height = height;
  settings.samplesPerPixel = spp;
  settings.maxDepth = depth;
  settings.verticalFovDegrees = fov;
  settings.threads = threads;
  settings.seed = seed;
  return renderToArray(sceneFromData(data), settings);
}

}  // namespace

}  // namespace scenefile_python

PYBIND11_MODULE(_core, m) {
  namespace sp = scenefile_python;
  namespace py = pybind11;
  m.doc() = "the C++ side of the scenefile package: plain data in, plain data out (_core.pyi)";
  m.attr("__version__") = SCENEFILE_VERSION;
  m.def("parse", &sp::parse, py::arg("data"), py::arg("name"), py::arg("format"),
        py::arg("options"));
  m.def("read_file", &sp::readFile, py::arg("path"), py::arg("name"), py::arg("format"),
        py::arg("options"));
  m.def("check_file_size", &sp::checkFileSize, py::arg("size"), py::arg("name"),
        py::arg("options"));
  m.def("validate", &sp::validate, py::arg("scene"), py::arg("name"));
  m.def("convert", &sp::convert, py::arg("scene"), py::arg("format"), py::arg("options"),
        py::arg("name"));
  m.def("render", &sp::render, py::arg("scene"), py::arg("width"), py::arg("height"),
        py::arg("spp"), py::arg("depth"), py::arg("fov"), py::arg("threads"), py::arg("seed"));
  m.def("default_scene", [] { return sp::sceneToData(render::defaultScene()); });
  m.def("compose_transform", &sp::composeTransform, py::arg("ops"));
  m.def("decompose_transform", &sp::decomposeTransform, py::arg("matrix"));
  m.def("check_output_file_name", &sp::checkOutputFileName, py::arg("name"));
  m.def("output_file_name_for", &sp::outputFileNameFor, py::arg("path"));
  m.def("check_view", &sp::checkView, py::arg("fov"), py::arg("aspect_ratio"));
  m.def("write_files", &sp::writeFiles, py::arg("files"));
  m.def("output_clash", &sp::outputClash, py::arg("inputs"), py::arg("outputs"));
  m.def("camera_from_look_at", &sp::cameraFromLookAt, py::arg("location"), py::arg("look_at"));
  m.def("fit_primitive", &sp::fitPrimitive, py::arg("positions"), py::arg("indices"),
        py::arg("tolerance"));
  m.def("primitive_mesh", &sp::primitiveMesh, py::arg("kind"), py::arg("segments"),
        py::arg("plane_half_size"));
  m.def("formats", &sp::formatRows);
  m.def("format_by_extension", &sp::formatByExtension, py::arg("file_name"));
  m.def("suggest_spelling", &sp::suggestSpelling, py::arg("word"), py::arg("candidates"));
  m.def("hint_text", &sp::hintText, py::arg("hint"), py::arg("words"));
  m.attr("FIT_TOLERANCE") = scene::kFitTolerance;
  m.attr("DEFAULT_SEGMENTS") = scene::kDefaultSegments;
  m.attr("MIN_SEGMENTS") = scene::kMinSegments;
  m.attr("MAX_IMAGE_SIDE") = scene::kMaxImageSide;
  m.attr("MAX_SEGMENTS") = scene::kMaxSegments;
}
