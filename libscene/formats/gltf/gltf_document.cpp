#include "libscene/formats/gltf/gltf_document.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <optional>
#include <set>
#include <utility>

#include "libscene/formats/gltf/gltf_json_scan.h"
#include "libscene/formats/gltf/gltf_labels.h"
#include "libscene/formats/gltf/gltf_mapping.h"
#include "libscene/text/number.h"
#include "libscene/text/text_lines.h"

namespace scene::gltf {

namespace {

using Json = nlohmann::json;

// The arrays of glTF objects at the top level of a glTF.
const char* const kObjectArrays[] = {
    "accessors", "animations", "buffers",  "bufferViews", "cameras", "images",   "materials",
    "meshes",    "nodes",      "samplers", "scenes",      "skins",   "textures",
};

// The extensions the reader reads, with the keys of each that it reads;
// every other extension, and every other key, is dropped before tinygltf.
const std::map<std::string, std::set<std::string>> kReadExtensions = {
    {"KHR_lights_punctual", {"light", "lights"}},
    {"KHR_materials_ior", {"ior"}},
    {"KHR_materials_transmission", {"transmissionFactor"}},
    {"KHR_materials_specular", {"specularFactor"}},
    {"KHR_materials_emissive_strength", {"emissiveStrength"}},
    {"EXT_mesh_gpu_instancing", {"attributes"}},
};

// The keys of our own extras (gltf_writer.cpp) that the reader reads, of
// nodes and of materials.
const std::set<std::string> kOwnExtrasKeys = {
    "record",  "colour",   "matrix",    "lookAt",       "transforms",   "view", "ambient",
    "diffuse", "specular", "shininess", "reflectivity", "transparency", "ri",   "referenceDistance",
    "object",  "objects",
};

// A JSON pointer's reference token: '~' and '/' escaped (RFC 6901).
std::string token(std::string_view name) {
  std::string out;
  for (char c : name) {
    if (c == '~') {
      out += "~0";
    } else if (c == '/') {
      out += "~1";
    } else {
      out += c;
    }
  }
  return out;
}

std::string describe(const Json& v) {
  if (v.is_null()) return "null";
  if (v.is_string()) return "a string";
  if (v.is_boolean()) return v.get<bool>() ? "true" : "false";
  if (v.is_object()) return "an object";
  if (v.is_array()) return "an array";
  return v.dump();
}

class Checker {
 public:
  Checker(const Json& doc, Severity loss) : doc_(doc), loss_(loss) {}

  std::vector<DocumentProblem> run() {
    for (const char* name : kObjectArrays) {
      auto it = doc_.find(name);
      if (it == doc_.end()) continue;
      std::string at = "/" + std::string(name);
      if (!it->is_array()) {
        problem(DiagnosticCode::GltfInvalid, at, at + " is " + describe(*it) + ", not an array");
        continue;
      }
      for (std::size_t i = 0; i < it->size(); ++i) {
        if (!(*it)[i].is_object()) {
          std::string element = at + "/" + std::to_string(i);
          problem(DiagnosticCode::GltfInvalid, element,
                  element + " is " + describe((*it)[i]) + ", not an object");
        }
      }
    }
    if (doc_.contains("scene")) index(doc_["scene"], "/scene", "scene", "scenes");
    each("scenes", [&](const Json& s, const std::string& at) {
      indexArray(s, "nodes", at, "node", "nodes");
    });
    std::size_t lights = lightCount();
    each("nodes", [&](const Json& n, const std::string& at) {
      indexArray(n, "children", at, "node", "nodes");
      optional(n, "mesh", at, "mesh", "meshes");
      optional(n, "camera", at, "camera", "cameras");
      optional(n, "skin", at, "skin", "skins");
      nodeTransform(n, at);
      const Json* light = member(n, "extensions", "KHR_lights_punctual");
      if (light && light->is_object()) {
        std::string where = at + "/extensions/KHR_lights_punctual";
        required(*light, "light", where, "light", lights);
      }
      const Json* instancing = member(n, "extensions", "EXT_mesh_gpu_instancing");
      if (instancing && instancing->is_object() && instancing->contains("attributes")) {
        accessorMap((*instancing)["attributes"],
                    at + "/extensions/EXT_mesh_gpu_instancing/attributes");
      }
    });
    each("meshes", [&](const Json& m, const std::string& at) { mesh(m, at); });
    each("accessors", [&](const Json& a, const std::string& at) {
      optional(a, "bufferView", at, "buffer view", "bufferViews");
    });
    each("bufferViews", [&](const Json& v, const std::string& at) {
      required(v, "buffer", at, "buffer", size("buffers"));
    });
    each("textures", [&](const Json& t, const std::string& at) {
      optional(t, "source", at, "image", "images");
      optional(t, "sampler", at, "sampler", "samplers");
    });
    each("materials", [&](const Json& m, const std::string& at) { material(m, at); });
    each("cameras", [&](const Json& c, const std::string& at) { camera(c, at); });
    lightValues();
    return std::move(problems_);
  }

 private:
  std::size_t size(const char* array) const {
    auto it = doc_.find(array);
    return it != doc_.end() && it->is_array() ? it->size() : 0;
  }

  std::size_t lightCount() const {
    const Json* lights = member(doc_, "extensions", "KHR_lights_punctual");
    if (!lights || !lights->is_object()) return 0;
    auto it = lights->find("lights");
    return it != lights->end() && it->is_array() ? it->size() : 0;
  }

  static const Json* member(const Json& j, const char* a, const char* b) {
    if (!j.is_object()) return nullptr;
    auto it = j.find(a);
    if (it == j.end() || !it->is_object()) return nullptr;
    auto jt = it->find(b);
    return jt == it->end() ? nullptr : &*jt;
  }

  template <typename F>
  void each(const char* array, F f) {
    auto it = doc_.find(array);
    if (it == doc_.end() || !it->is_array()) return;
    for (std::size_t i = 0; i < it->size() && problems_.size() < kMaxProblems; ++i) {
      if ((*it)[i].is_object()) f((*it)[i], "/" + std::string(array) + "/" + std::to_string(i));
    }
  }

  void problem(DiagnosticCode code, const std::string& pointer, std::string message,
               Severity severity = Severity::Error) {
    if (problems_.size() < kMaxProblems) {
      problems_.push_back({severity, code, pointer, std::move(message), {}, {}});
    }
  }

  // A number that glTF holds in (low, ...) or [low, ...) and, when `high`
  // is given, below or up to it: else an error, as the file is invalid.
  std::optional<double> bounded(const Json& o, const char* key, const std::string& at, double low,
                                bool lowIncluded, const char* rule) {
    auto it = o.find(key);
    if (it == o.end()) return std::nullopt;
    std::string where = at + "/" + key;
    double v = it->is_number() ? it->get<double>() : std::nan("");
    if (!it->is_number() || !(lowIncluded ? v >= low : v > low)) {
      problem(DiagnosticCode::GltfInvalid, where,
              where + " is " + describe(*it) + "; glTF requires " + rule);
      return std::nullopt;
    }
    return v;
  }

  // `v` at `at` must index one of `count` objects of the kind `what`.
  void index(const Json& v, const std::string& at, const char* what, std::size_t count) {
    if (v.is_number_unsigned() || (v.is_number_integer() && v.get<std::int64_t>() >= 0)) {
      std::uint64_t i = v.get<std::uint64_t>();
      if (i < count) return;
      problem(DiagnosticCode::GltfIndexOutOfRange, at,
              at + " points at " + what + " " + std::to_string(i) + ", but the file has " +
                  std::to_string(count));
      return;
    }
    problem(
        v.is_number_integer() ? DiagnosticCode::GltfIndexOutOfRange : DiagnosticCode::GltfInvalid,
        at, at + " is " + describe(v) + ", not an index (a whole number from 0)");
  }
  void index(const Json& v, const std::string& at, const char* what, const char* array) {
    index(v, at, what, size(array));
  }

  void optional(const Json& o, const char* key, const std::string& at, const char* what,
                const char* array) {
    auto it = o.find(key);
    if (it != o.end()) index(*it, at + "/" + key, what, size(array));
  }

  void required(const Json& o, const char* key, const std::string& at, const char* what,
                std::size_t count) {
    auto it = o.find(key);
    if (it == o.end()) {
      problem(DiagnosticCode::GltfInvalid, at, at + " has no " + key + ", which glTF requires");
      return;
    }
    index(*it, at + "/" + key, what, count);
  }

  void indexArray(const Json& o, const char* key, const std::string& at, const char* what,
                  const char* array) {
    auto it = o.find(key);
    if (it == o.end()) return;
    std::string where = at + "/" + key;
    if (!it->is_array()) {
      problem(DiagnosticCode::GltfInvalid, where,
              where + " is " + describe(*it) + ", not an array of indices");
      return;
    }
    for (std::size_t i = 0; i < it->size() && problems_.size() < kMaxProblems; ++i) {
      index((*it)[i], where + "/" + std::to_string(i), what, size(array));
    }
  }

  // An object whose every member is an accessor index (attributes, a
  // morph target).
  void accessorMap(const Json& o, const std::string& at) {
    if (!o.is_object()) {
      problem(DiagnosticCode::GltfInvalid, at, at + " is " + describe(o) + ", not an object");
      return;
    }
    for (auto it = o.begin(); it != o.end() && problems_.size() < kMaxProblems; ++it) {
      index(it.value(), at + "/" + token(it.key()), "accessor", size("accessors"));
    }
  }

  void mesh(const Json& m, const std::string& at) {
    auto it = m.find("primitives");
    std::string where = at + "/primitives";
    if (it == m.end() || !it->is_array() || it->empty()) {
      problem(DiagnosticCode::GltfInvalid, it == m.end() ? at : where,
              (it == m.end() ? at + " has no primitives"
                             : where + " is " + (it->is_array() ? "empty" : describe(*it))) +
                  ": a glTF mesh needs at least one primitive");
      return;
    }
    for (std::size_t p = 0; p < it->size(); ++p) {
      const Json& prim = (*it)[p];
      std::string pat = where + "/" + std::to_string(p);
      if (!prim.is_object()) {
        problem(DiagnosticCode::GltfInvalid, pat,
                pat + " is " + describe(prim) + ", not an object");
        continue;
      }
      auto attributes = prim.find("attributes");
      if (attributes == prim.end()) {
        problem(DiagnosticCode::GltfInvalid, pat, pat + " has no attributes, which glTF requires");
      } else {
        accessorMap(*attributes, pat + "/attributes");
      }
      optional(prim, "indices", pat, "accessor", "accessors");
      optional(prim, "material", pat, "material", "materials");
      auto targets = prim.find("targets");
      if (targets != prim.end()) {
        if (!targets->is_array()) {
          problem(DiagnosticCode::GltfInvalid, pat + "/targets",
                  pat + "/targets is " + describe(*targets) + ", not an array");
          continue;
        }
        for (std::size_t t = 0; t < targets->size(); ++t) {
          accessorMap((*targets)[t], pat + "/targets/" + std::to_string(t));
        }
      }
    }
  }

  // A node's matrix, translation, rotation and scale: each an array of
  // finite numbers of its length, a matrix never beside the others (the
  // glTF schema), a rotation a unit quaternion. tinygltf leaves a property
  // it cannot read empty, which would put the node silently at the origin.
  void nodeTransform(const Json& n, const std::string& at) {
    std::string name;
    auto it = n.find("name");
    if (it != n.end() && it->is_string()) name = quoted(it->get<std::string>());
    std::string node = "node " + at.substr(at.rfind('/') + 1) + name;
    const std::pair<const char*, std::size_t> properties[] = {
        {"matrix", 16}, {"translation", 3}, {"rotation", 4}, {"scale", 3}};
    for (const auto& [key, length] : properties) {
      it = n.find(key);
      if (it == n.end()) continue;
      std::string where = at + "/" + key;
      std::string rule = "; glTF requires the " + std::string(key) + " of " + node + " to be " +
                         std::to_string(length) + " finite numbers";
      if (!it->is_array() || it->size() != length) {
        problem(DiagnosticCode::GltfInvalid, where,
                where +
                    (it->is_array() ? " has " + std::to_string(it->size()) + " elements"
                                    : " is " + describe(*it)) +
                    rule);
        continue;
      }
      for (std::size_t i = 0; i < length; ++i) {
        const Json& v = (*it)[i];
        if (!v.is_number() || !std::isfinite(v.get<double>())) {
          std::string element = where + "/" + std::to_string(i);
          problem(DiagnosticCode::GltfInvalid, element, element + " is " + describe(v) + rule);
          break;
        }
      }
    }
    if (n.contains("matrix")) {
      for (const char* key : {"translation", "rotation", "scale"}) {
        if (!n.contains(key)) continue;
        problem(DiagnosticCode::GltfInvalid, at + "/" + key,
                at + " (" + node + ") has both a matrix and a " + key +
                    "; glTF allows a matrix or a translation, rotation and scale, not both");
        break;
      }
    }
    rotation(n, at, node);
  }

  // The Khronos validator's rule: a rotation is a unit quaternion when its
  // length is within kUnitQuaternionTolerance of 1.
  void rotation(const Json& n, const std::string& at, const std::string& node) {
    auto it = n.find("rotation");
    if (it == n.end() || !it->is_array() || it->size() != 4) return;
    double sum = 0.0;
    for (const Json& v : *it) {
      if (!v.is_number()) return;
      sum += v.get<double>() * v.get<double>();
    }
    double length = std::sqrt(sum);
    if (std::abs(length - 1.0) <= kUnitQuaternionTolerance) return;
    std::string where = at + "/rotation";
    problem(DiagnosticCode::GltfInvalid, where,
            where + " " + it->dump() + " has length " + formatNumber(length) +
                "; glTF requires the rotation of " + node +
                " to be a unit quaternion (length within " +
                formatNumber(kUnitQuaternionTolerance) + " of 1)");
  }

  void textureInfo(const Json& m, const std::string& at, const char* key) {
    auto it = m.find(key);
    if (it == m.end()) return;
    std::string where = at + "/" + key;
    if (!it->is_object()) {
      problem(DiagnosticCode::GltfInvalid, where,
              where + " is " + describe(*it) + ", not an object");
      return;
    }
    required(*it, "index", where, "texture", size("textures"));
  }

  void camera(const Json& c, const std::string& at) {
    auto p = c.find("perspective");
    if (p == c.end() || !p->is_object()) return;
    std::string where = at + "/perspective";
    if (!p->contains("yfov")) {
      problem(DiagnosticCode::GltfInvalid, where, where + " has no yfov, which glTF requires");
    }
    std::optional<double> yfov = bounded(*p, "yfov", where, 0.0, false, "a field of view above 0");
    constexpr double kPi = 3.14159265358979323846;
    if (yfov && *yfov >= kPi) {
      problem(DiagnosticCode::GltfIgnored, where + "/yfov",
              where + "/yfov is " + describe((*p)["yfov"]) +
                  " radians, not below pi: no pinhole camera sees that wide, and the field of "
                  "view is dropped",
              loss_);
    }
    if (std::optional<double> aspect =
            bounded(*p, "aspectRatio", where, 0.0, false, "an aspect ratio above 0")) {
      problem(DiagnosticCode::GltfIgnored, where + "/aspectRatio",
              where + "/aspectRatio " + describe((*p)["aspectRatio"]) +
                  " is dropped: a scene file holds no image shape",
              loss_);
      if (!problems_.empty() && problems_.back().pointer == where + "/aspectRatio") {
        problems_.back().hint =
            "render with {0} and {1} in the ratio " + describe((*p)["aspectRatio"]);
        problems_.back().remedies = {{Setting::Width, ""}, {Setting::Height, ""}};
      }
    }
    bounded(*p, "znear", where, 0.0, false, "a near plane above 0");
  }

  // KHR_lights_punctual: a colour in [0, 1], an intensity from 0, a range
  // above 0 (which a scene file cannot hold), and colour times intensity,
  // the scene file's LIGHT colour, finite.
  void lightValues() {
    const Json* k = member(doc_, "extensions", "KHR_lights_punctual");
    if (!k || !k->is_object() || !k->contains("lights") || !(*k)["lights"].is_array()) return;
    const Json& lights = (*k)["lights"];
    for (std::size_t i = 0; i < lights.size() && problems_.size() < kMaxProblems; ++i) {
      const Json& light = lights[i];
      std::string at = "/extensions/KHR_lights_punctual/lights/" + std::to_string(i);
      if (!light.is_object()) {
        problem(DiagnosticCode::GltfInvalid, at, at + " is " + describe(light) + ", not an object");
        continue;
      }
      // The colour's largest channel (1 by default): its product with the
      // intensity is checked first, since a colour out of range is reported
      // after it.
      double largest = 1.0;
      bool inRange = true;
      auto colour = light.find("color");
      if (colour != light.end()) {
        bool numbers = colour->is_array() && colour->size() == 3;
        for (std::size_t c = 0; numbers && c < 3; ++c) {
          numbers = (*colour)[c].is_number();
          if (!numbers) break;
          double v = (*colour)[c].get<double>();
          largest = c == 0 ? std::abs(v) : std::max(largest, std::abs(v));
          inRange = inRange && v >= 0.0 && v <= 1.0;
        }
        if (!numbers) {
          problem(DiagnosticCode::GltfInvalid, at + "/color",
                  at + "/color is not three numbers, as glTF requires");
          continue;
        }
      }
      std::optional<double> intensity =
          bounded(light, "intensity", at, 0.0, true, "an intensity from 0");
      if (intensity && !std::isfinite(*intensity * largest)) {
        problem(DiagnosticCode::ValueNotFinite, at + "/intensity",
                at + "/intensity " + describe(light["intensity"]) +
                    " times the colour is not finite: the LIGHT's colour cannot be held");
      } else if (!inRange) {
        problem(DiagnosticCode::GltfInvalid, at + "/color",
                at + "/color is not three numbers in [0, 1], as glTF requires");
      }
      if (bounded(light, "range", at, 0.0, false, "a range above 0")) {
        problem(DiagnosticCode::GltfIgnored, at + "/range",
                at + "/range " + describe(light["range"]) +
                    " is dropped: a scene file's LIGHT reaches everywhere",
                loss_);
      }
    }
  }

  // Emission has no counterpart in a scene file.
  void emission(const Json& m, const std::string& at) {
    auto factor = m.find("emissiveFactor");
    bool glows = false;
    if (factor != m.end()) {
      bool ok = factor->is_array() && factor->size() == 3;
      for (std::size_t c = 0; ok && c < 3; ++c) {
        const Json& v = (*factor)[c];
        ok = v.is_number() && v.get<double>() >= 0.0 && v.get<double>() <= 1.0;
        glows |= ok && v.get<double>() > 0.0;
      }
      if (!ok) {
        problem(DiagnosticCode::GltfInvalid, at + "/emissiveFactor",
                at + "/emissiveFactor is not three numbers in [0, 1], as glTF requires");
        return;
      }
    }
    // The emission is the factor times the texture (black by default), so
    // a texture alone emits nothing.
    if (glows) {
      problem(DiagnosticCode::GltfIgnored, at + "/emissiveFactor",
              at + "/emissiveFactor " + factor->dump() +
                  " is dropped: a scene file's objects do not glow",
              loss_);
    }
  }

  void material(const Json& m, const std::string& at) {
    emission(m, at);
    auto pbr = m.find("pbrMetallicRoughness");
    if (pbr != m.end() && pbr->is_object()) {
      textureInfo(*pbr, at + "/pbrMetallicRoughness", "baseColorTexture");
      textureInfo(*pbr, at + "/pbrMetallicRoughness", "metallicRoughnessTexture");
    }
    for (const char* key : {"normalTexture", "occlusionTexture", "emissiveTexture"}) {
      textureInfo(m, at, key);
    }
  }

  // As many as the error limit could take, and not more: a file of a
  // million bad indices costs no more than one of a thousand.
  static constexpr std::size_t kMaxProblems = DiagnosticList::kDefaultErrorLimit + 1;

  const Json& doc_;
  Severity loss_;
  std::vector<DocumentProblem> problems_;
};

// The byte offset of each wanted pointer's value in `text`, found in one
// pass over the (already parsed, so well-formed) JSON.
class Locator {
 public:
  Locator(std::string_view text, std::size_t start) : t_(text), i_(start) {}

  std::map<std::string, std::size_t> find(const std::set<std::string>& wanted) {
    std::map<std::string, std::size_t> found;
    struct Frame {
      bool array;
      std::size_t count;
      std::size_t pathLength;
    };
    std::vector<Frame> stack;
    std::string path;
    bool expectValue = true;
    while (i_ < t_.size()) {
      if (expectValue) {
        space();
        if (i_ >= t_.size()) break;
        if (wanted.count(path)) found.emplace(path, i_);
        char c = t_[i_];
        if (c == '{' || c == '[') {
          ++i_;
          stack.push_back({c == '[', 0, path.size()});
          space();
          if (i_ < t_.size() && (t_[i_] == ']' || t_[i_] == '}')) {
            ++i_;
            stack.pop_back();
            expectValue = false;
          } else if (!member(stack.back(), path)) {
            break;
          }
          continue;
        }
        if (c == '"') {
          string();
        } else {
          while (i_ < t_.size() && !std::strchr(",]} \t\r\n", t_[i_])) ++i_;
        }
        expectValue = false;
        continue;
      }
      if (stack.empty()) break;
      space();
      if (i_ >= t_.size()) break;
      Frame& frame = stack.back();
      path.resize(frame.pathLength);
      if (t_[i_] == ',') {
        ++i_;
        ++frame.count;
        space();
        if (!member(frame, path)) break;
        expectValue = true;
      } else {
        ++i_;  // ']' or '}'
        stack.pop_back();
      }
    }
    return found;
  }

 private:
  void space() {
    while (i_ < t_.size() && (t_[i_] == ' ' || t_[i_] == '\t' || t_[i_] == '\n' || t_[i_] == '\r'))
      ++i_;
  }

  // At '"': the string's text with its simple escapes undone.
  std::string string() {
    std::string out;
    ++i_;
    while (i_ < t_.size() && t_[i_] != '"') {
      if (t_[i_] == '\\' && i_ + 1 < t_.size()) {
        ++i_;
        char e = t_[i_];
        out += e == 'n' ? '\n' : e == 't' ? '\t' : e == 'r' ? '\r' : e;
      } else {
        out += t_[i_];
      }
      ++i_;
    }
    ++i_;
    return out;
  }

  // The path of the next element of `frame`: its number, or (reading the
  // key and the colon) its key.
  template <typename F>
  bool member(const F& frame, std::string& path) {
    if (frame.array) {
      path += "/" + std::to_string(frame.count);
      return true;
    }
    space();
    if (i_ >= t_.size() || t_[i_] != '"') return false;
    path += "/" + token(string());
    space();
    if (i_ >= t_.size() || t_[i_] != ':') return false;
    ++i_;
    return true;
  }

  std::string_view t_;
  std::size_t i_;
};

}  // namespace

std::size_t countObjects(const Json& doc) {
  std::size_t count = 0;
  if (!doc.is_object()) return 0;
  for (auto it = doc.begin(); it != doc.end(); ++it) {
    if (it->is_array()) count += objectWeight(it.key()) * it->size();
  }
  auto meshes = doc.find("meshes");
  if (meshes != doc.end() && meshes->is_array()) {
    for (const Json& m : *meshes) {
      if (m.is_object() && m.contains("primitives") && m["primitives"].is_array()) {
        count += m["primitives"].size();
      }
    }
  }
  auto ext = doc.find("extensions");
  if (ext != doc.end() && ext->is_object() && ext->contains("KHR_lights_punctual")) {
    const Json& k = (*ext)["KHR_lights_punctual"];
    if (k.is_object() && k.contains("lights") && k["lights"].is_array()) {
      count += objectWeight("lights") * k["lights"].size();
    }
  }
  return count;
}

std::vector<DocumentProblem> checkDocument(const Json& doc, bool noLoss) {
  return Checker(doc, noLoss ? Severity::Error : Severity::Warning).run();
}

void reportProblems(const std::vector<DocumentProblem>& problems, std::string_view text,
                    std::size_t offset, DiagnosticList& out) {
  std::map<std::string, std::size_t> at;
  if (!text.empty()) {
    std::set<std::string> wanted;
    for (const DocumentProblem& p : problems) wanted.insert(p.pointer);
    at = Locator(text, offset).find(wanted);
  }
  // Lines and columns of every offset in one sweep.
  std::map<std::size_t, SourceSpan> spans;
  for (const auto& [pointer, byte] : at) spans.emplace(byte, SourceSpan{});
  LineColumnCounter counter(text);
  for (auto& [byte, s] : spans) {
    s = counter.at(byte);
    s.length = 1;
  }
  for (const DocumentProblem& p : problems) {
    auto found = at.find(p.pointer);
    Diagnostic& d = out.report(p.severity, p.code,
                               found == at.end() ? SourceSpan{} : spans[found->second], p.message);
    d.hint = p.hint;
    d.remedies = p.remedies;
    if (out.full()) return;
  }
}

OwnExtras trimForTinygltf(Json& doc) {
  OwnExtras own;
  auto take = [&doc](const char* array, std::vector<std::string>& into) {
    auto it = doc.find(array);
    if (it == doc.end() || !it->is_array()) return;
    into.resize(it->size());
    for (std::size_t i = 0; i < it->size(); ++i) {
      Json& o = (*it)[i];
      if (!o.is_object() || !o.contains("extras") || !o["extras"].is_object()) continue;
      auto sf = o["extras"].find(kExtrasKey);
      if (sf == o["extras"].end() || !sf->is_object()) continue;
      // Only the keys the reader reads: the rest could be any size.
      Json kept = Json::object();
      for (auto k = sf->begin(); k != sf->end(); ++k) {
        if (kOwnExtrasKeys.count(k.key())) kept[k.key()] = std::move(k.value());
      }
      into[i] = Json{{kExtrasKey, std::move(kept)}}.dump();
    }
  };
  take("nodes", own.nodes);
  take("materials", own.materials);
  take("meshes", own.meshes);
  // Depth is bounded (kMaxJsonDepth) before the document is parsed, so
  // this recursion is too.
  auto trim = [](auto& self, Json& j) -> void {
    if (j.is_array()) {
      for (Json& e : j) self(self, e);
      return;
    }
    if (!j.is_object()) return;
    j.erase("extras");
    auto ext = j.find("extensions");
    if (ext != j.end()) {
      if (!ext->is_object()) {
        j.erase(ext);
      } else {
        for (auto e = ext->begin(); e != ext->end();) {
          auto known = kReadExtensions.find(e.key());
          if (known == kReadExtensions.end() || !e->is_object()) {
            e = ext->erase(e);
            continue;
          }
          for (auto k = e->begin(); k != e->end();) {
            k = known->second.count(k.key()) ? std::next(k) : e->erase(k);
          }
          ++e;
        }
      }
    }
    for (auto& [key, value] : j.items()) {
      if (key != "extensions" || value.is_object()) self(self, value);
    }
  };
  trim(trim, doc);
  // Of a light, tinygltf reads these; the rest it would copy as values.
  static const std::set<std::string> kLightKeys = {"name",      "type",  "color",
                                                   "intensity", "range", "spot"};
  auto ext = doc.find("extensions");
  Json* lights = nullptr;
  if (ext != doc.end() && ext->is_object()) {
    auto k = ext->find("KHR_lights_punctual");
    if (k != ext->end() && k->is_object() && k->contains("lights")) lights = &(*k)["lights"];
  }
  {
    if (lights && lights->is_array()) {
      for (Json& light : *lights) {
        if (!light.is_object()) continue;
        for (auto k = light.begin(); k != light.end();) {
          k = kLightKeys.count(k.key()) ? std::next(k) : light.erase(k);
        }
      }
    }
  }
  return own;
}

}  // namespace scene::gltf
