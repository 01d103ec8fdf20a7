#include "python/src/scene_data.h"

#include <array>
#include <string>

#include "scenefile/transform.h"

namespace scenefile_python {

namespace {

constexpr std::array<scene::TransformKind, 5> kTransformKinds = {
    scene::TransformKind::Scale, scene::TransformKind::Translate, scene::TransformKind::RotateX,
    scene::TransformKind::RotateY, scene::TransformKind::RotateZ};

py::tuple spanToTuple(const scene::SourceSpan& span) {
  return py::make_tuple(span.line, span.column, span.length);
}

// A span is where a record came from; a scene built in Python has none.
scene::SourceSpan spanFrom(const py::dict& record) {
  scene::SourceSpan span;
  if (!record.contains("span") || record["span"].is_none()) return span;
  py::tuple t = py::cast<py::tuple>(record["span"]);
  if (t.size() != 3) throw py::value_error("a span is (line, column, length)");
  span.line = py::cast<std::uint32_t>(t[0]);
  span.column = py::cast<std::uint32_t>(t[1]);
  span.length = py::cast<std::uint32_t>(t[2]);
  return span;
}

py::dict materialToData(const scene::Material& m) {
  py::dict d;
  d["colour"] = vectorToTuple(m.colour);
  for (scene::MaterialProperty p : scene::kMaterialProperties) {
    std::string key(scene::materialPropertyName(p));
    for (char& c : key) c = static_cast<char>(c - 'A' + 'a');
    d[py::str(key)] = scene::materialValue(m, p);
  }
  return d;
}

scene::Material materialFromData(const py::dict& d) {
  scene::Material m;
  m.colour = vectorFromSequence(d["colour"], "a material's colour");
  for (scene::MaterialProperty p : scene::kMaterialProperties) {
    std::string key(scene::materialPropertyName(p));
    for (char& c : key) c = static_cast<char>(c - 'A' + 'a');
    scene::materialValue(m, p) = py::cast<double>(d[py::str(key)]);
  }
  return m;
}

py::list transformsToData(const std::vector<scene::TransformOp>& ops) {
  py::list list;
  for (const scene::TransformOp& op : ops) {
    list.append(py::make_tuple(py::str(std::string(scene::transformKindName(op.kind))),
                               vectorToTuple(op.value), spanToTuple(op.span)));
  }
  return list;
}

py::dict objectToData(const scene::Object& o) {
  py::dict d;
  d["kind"] = py::str(std::string(scene::objectKindName(o.kind)));
  d["matrix"] = matrixToArray(o.matrix);
  d["material"] = materialToData(o.material);
  d["transforms"] = o.transforms ? py::object(transformsToData(*o.transforms)) : py::none();
  d["span"] = spanToTuple(o.span);
  return d;
}

scene::Object objectFromData(const py::dict& d) {
  scene::Object o;
  std::string kind = py::cast<std::string>(d["kind"]);
  std::optional<scene::ObjectKind> known = scene::objectKindFromName(kind);
  if (!known) throw py::value_error("'" + kind + "' is no object kind");
  o.kind = *known;
  o.matrix = matrixFromArray(d["matrix"], "an object's matrix");
  o.material = materialFromData(py::cast<py::dict>(d["material"]));
  if (d.contains("transforms") && !d["transforms"].is_none()) {
    std::vector<scene::TransformOp> ops;
    for (py::handle item : py::cast<py::list>(d["transforms"])) {
      ops.push_back(transformFromData(item));
    }
    o.transforms = std::move(ops);
  }
  o.span = spanFrom(d);
  return o;
}

}  // namespace

scene::TransformOp transformFromData(const py::handle& item) {
  py::tuple t = py::cast<py::tuple>(item);
  if (t.size() != 2 && t.size() != 3) {
    throw py::value_error("a transform is (kind, (x, y, z)) or (kind, (x, y, z), span)");
  }
  std::string name = py::cast<std::string>(t[0]);
  scene::TransformOp op;
  bool known = false;
  for (scene::TransformKind kind : kTransformKinds) {
    if (scene::transformKindName(kind) == name) {
      op.kind = kind;
      known = true;
    }
  }
  if (!known) throw py::value_error("'" + name + "' is no transform kind");
  op.value = vectorFromSequence(t[1], "a transform's value");
  if (t.size() == 3 && !t[2].is_none()) {
    py::dict withSpan;
    withSpan["span"] = t[2];
    op.span = spanFrom(withSpan);
  }
  return op;
}

py::str decodeText(const std::string& text, const char* errors) {
  PyObject* decoded =
      PyUnicode_DecodeUTF8(text.data(), static_cast<Py_ssize_t>(text.size()), errors);
  if (!decoded) throw py::error_already_set();
  return py::reinterpret_steal<py::str>(decoded);
}

std::string encodeText(const py::handle& value, const char* what) {
  if (!py::isinstance<py::str>(value)) throw py::type_error(std::string(what) + " is not a str");
  PyObject* encoded = PyUnicode_AsEncodedString(value.ptr(), "utf-8", "surrogateescape");
  if (!encoded) throw py::error_already_set();
  py::bytes bytes = py::reinterpret_steal<py::bytes>(encoded);
  return std::string(bytes);
}

py::array_t<double> matrixToArray(const glm::dmat4& m) {
  py::array_t<double> array({4, 4});
  auto out = array.mutable_unchecked<2>();
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) out(r, c) = m[c][r];
  }
  return array;
}

glm::dmat4 matrixFromArray(const py::handle& value, const char* what) {
  auto array = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(value);
  if (!array) throw py::type_error(std::string(what) + " is not an array of numbers");
  if (array.ndim() != 2 || array.shape(0) != 4 || array.shape(1) != 4) {
    throw py::value_error(std::string(what) + " is not 4 x 4");
  }
  auto in = array.unchecked<2>();
  glm::dmat4 m;
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) m[c][r] = in(r, c);
  }
  return m;
}

py::tuple vectorToTuple(const glm::dvec3& v) {
  return py::make_tuple(v.x, v.y, v.z);
}

glm::dvec3 vectorFromSequence(const py::handle& value, const char* what) {
  py::sequence s = py::cast<py::sequence>(value);
  if (s.size() != 3) throw py::value_error(std::string(what) + " is not three numbers");
  return {py::cast<double>(s[0]), py::cast<double>(s[1]), py::cast<double>(s[2])};
}

py::dict sceneToData(const scene::Scene& s) {
  py::dict camera;
  camera["matrix"] = matrixToArray(s.camera.matrix);
  camera["colour"] = vectorToTuple(s.camera.colour);
  camera["look_at"] = s.camera.lookAt ? py::object(vectorToTuple(*s.camera.lookAt)) : py::none();
  camera["span"] = spanToTuple(s.camera.span);
  py::list lights;
  for (const scene::Light& l : s.lights) {
    py::dict light;
    light["matrix"] = matrixToArray(l.matrix);
    light["colour"] = vectorToTuple(l.colour);
    light["span"] = spanToTuple(l.span);
    lights.append(light);
  }
  py::list objects;
  for (const scene::Object& o : s.objects) objects.append(objectToData(o));
  py::dict d;
  d["camera"] = camera;
  d["lights"] = lights;
  d["objects"] = objects;
  d["output_file"] =
      s.outputFile ? py::object(decodeText(*s.outputFile, "surrogateescape")) : py::none();
  d["output_file_span"] = spanToTuple(s.outputFileSpan);
  if (s.view) {
    py::dict view;
    view["fov"] = s.view->verticalFovDegrees;
    view["aspect_ratio"] =
        s.view->aspectRatio ? py::object(py::float_(*s.view->aspectRatio)) : py::none();
    view["span"] = spanToTuple(s.view->span);
    d["view"] = view;
  } else {
    d["view"] = py::none();
  }
  return d;
}

scene::Scene sceneFromData(const py::handle& data) {
  py::dict d = py::cast<py::dict>(data);
  scene::Scene s;
  py::dict camera = py::cast<py::dict>(d["camera"]);
  s.camera.matrix = matrixFromArray(camera["matrix"], "the camera's matrix");
  s.camera.colour = vectorFromSequence(camera["colour"], "the camera's colour");
  if (camera.contains("look_at") && !camera["look_at"].is_none()) {
    s.camera.lookAt = vectorFromSequence(camera["look_at"], "the camera's look_at");
  }
  s.camera.span = spanFrom(camera);
  for (py::handle item : py::cast<py::list>(d["lights"])) {
    py::dict light = py::cast<py::dict>(item);
    scene::Light& l = s.lights.emplace_back();
    l.matrix = matrixFromArray(light["matrix"], "a light's matrix");
    l.colour = vectorFromSequence(light["colour"], "a light's colour");
    l.span = spanFrom(light);
  }
  for (py::handle item : py::cast<py::list>(d["objects"])) {
    s.objects.push_back(objectFromData(py::cast<py::dict>(item)));
  }
  if (d.contains("output_file") && !d["output_file"].is_none()) {
    s.outputFile = encodeText(d["output_file"], "the output file");
    if (d.contains("output_file_span")) {
      py::dict withSpan;
      withSpan["span"] = d["output_file_span"];
      s.outputFileSpan = spanFrom(withSpan);
    }
  }
  if (d.contains("view") && !d["view"].is_none()) {
    py::dict view = py::cast<py::dict>(d["view"]);
    scene::View v;
    v.verticalFovDegrees = py::cast<double>(view["fov"]);
    if (view.contains("aspect_ratio") && !view["aspect_ratio"].is_none()) {
      v.aspectRatio = py::cast<double>(view["aspect_ratio"]);
    }
    v.span = spanFrom(view);
    s.view = v;
  }
  return s;
}

py::list diagnosticsToData(const scene::DiagnosticList& list) {
  py::list out;
  for (const scene::Diagnostic& diagnostic : list.items()) {
    py::dict d;
    d["severity"] = py::str(std::string(scene::severityName(diagnostic.severity)));
    d["code"] = py::str(std::string(scene::codeName(diagnostic.code)));
    d["file"] = decodeText(diagnostic.file, "surrogateescape");
    d["span"] = spanToTuple(diagnostic.span);
    // A message quotes the input, which may be any bytes: shown, not kept.
    d["message"] = decodeText(diagnostic.message, "backslashreplace");
    // "{0}" in the hint stands for remedies[0], which the package names by
    // its keyword (scenefile._model.Remedy).
    d["hint"] = decodeText(diagnostic.hint, "backslashreplace");
    py::list remedies;
    for (const scene::Remedy& remedy : diagnostic.remedies) {
      remedies.append(py::make_tuple(py::str(std::string(scene::settingName(remedy.setting))),
                                     decodeText(remedy.value, "backslashreplace")));
    }
    d["remedies"] = remedies;
    py::list notes;
    for (const scene::DiagnosticNote& note : diagnostic.notes) {
      notes.append(
          py::make_tuple(spanToTuple(note.span), decodeText(note.message, "backslashreplace")));
    }
    d["notes"] = notes;
    if (diagnostic.fixIt) {
      d["fix_it"] = py::make_tuple(spanToTuple(diagnostic.fixIt->span),
                                   decodeText(diagnostic.fixIt->replacement, "surrogateescape"));
    } else {
      d["fix_it"] = py::none();
    }
    out.append(d);
  }
  return out;
}

}  // namespace scenefile_python
