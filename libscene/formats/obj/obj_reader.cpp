#include "libscene/formats/obj/obj_reader.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>
#include <iterator>
#include <map>
#include <set>

#include "libscene/core/default_camera.h"
#include "libscene/formats/obj/obj_mtl.h"
#include "libscene/formats/obj/obj_statements.h"
#include "libscene/text/number.h"
#include "scenefile/mesh.h"
#include "scenefile/mesh_fit.h"
#include "scenefile/transform.h"
#include "scenefile/validation.h"

namespace scene {

namespace {

namespace fs = std::filesystem;

// A mesh still the writer's when every vertex lies this close (relative to
// the mesh's size): the agreement of glTF extras.
constexpr double kMeshAgreement = 1e-9;

// Why an MTL name may not be read, or nothing: only a plain file name
// beside the OBJ.
std::optional<std::string> libraryProblem(const std::string& name) {
  if (name.empty() || name == "." || name == "..") return "is no file name";
  for (char c : name) {
    if (c == '/' || c == '\\') return "is a path, not a file beside the OBJ";
    if (c < ' ' || c > '~') return "holds a byte that is not printable ASCII";
  }
  return std::nullopt;
}

class ObjImporter {
 public:
  ObjImporter(const std::optional<fs::path>& folder, const ReadOptions& options, ReadResult& result)
      : folder_(folder),
        options_(options),
        result_(result),
        out_(result.diagnostics),
        loss_(options.noLoss ? Severity::Error : Severity::Warning) {}

  void run(std::string_view text);

 private:
  void readLibraries();
  void readLibrary(const ObjLibrary& library);
  void addGroup(const ObjGroup& group);
  bool isWrittenMesh(const ObjGroup& group, const ObjectComment& c) const;
  Material groupMaterial(const ObjGroup& group, const ObjectComment* c);
  void defaultCamera();

  const std::optional<fs::path>& folder_;
  const ReadOptions& options_;
  ReadResult& result_;
  DiagnosticList& out_;
  Severity loss_;
  ObjStatements file_;
  std::map<std::string, MtlMaterial> materials_;
  bool librariesRead_ = false;
  std::set<std::string> unknownMaterials_;
};

void ObjImporter::run(std::string_view text) {
  file_ = readObjStatements(text, options_, out_);
  if (out_.hasErrors()) return;
  readLibraries();
  for (const ObjGroup& group : file_.groups) {
    addGroup(group);
    if (out_.hasErrors()) return;
  }
  Scene& scene = result_.scene;
  scene.lights = file_.comments.lights;
  scene.view = file_.comments.view;
  scene.outputFile = file_.comments.outputFile;
  if (file_.comments.camera) {
    scene.camera = *file_.comments.camera;
  } else {
    defaultCamera();
  }
}

void ObjImporter::readLibraries() {
  for (const ObjLibrary& library : file_.libraries) {
    if (std::optional<std::string> problem = libraryProblem(library.name)) {
      out_.warning(DiagnosticCode::ObjMaterial, library.span,
                   "the MTL file named here is not read: it " + *problem);
      continue;
    }
    readLibrary(library);
  }
}

void ObjImporter::readLibrary(const ObjLibrary& library) {
  Diagnostic* missing = nullptr;
  if (!folder_) {
    missing = &out_.warning(
        DiagnosticCode::ObjMaterial, library.span,
        "the MTL file '" + library.name + "' is not read: the OBJ has no folder to look in");
  } else {
    std::error_code ec;
    fs::path base = fs::weakly_canonical(fs::absolute(folder_->empty() ? "." : *folder_), ec);
    fs::path target = fs::weakly_canonical(base / library.name, ec);
    if (ec || target.parent_path() != base || !fs::is_regular_file(target, ec)) {
      missing = &out_.warning(
          DiagnosticCode::ObjMaterial, library.span,
          "the MTL file '" + library.name + "' is not a file beside the OBJ: it is not read");
    } else if (fs::file_size(target, ec) > options_.maxFileSize || ec) {
      missing = &out_.warning(DiagnosticCode::ObjMaterial, library.span,
                              "the MTL file '" + library.name + "' is larger than " +
                                  std::to_string(options_.maxFileSize) +
                                  " bytes (the input limit): it is not read");
    } else {
      std::ifstream in(target, std::ios::binary);
      std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      std::map<std::string, MtlMaterial> read = parseMtl(text, library.name, out_);
      materials_.merge(read);
      librariesRead_ = true;
    }
  }
  if (missing) {
    missing->hint = "without it each object keeps the material its comment gives, or the default";
  }
}

// Whether the group's triangles are, corner by corner, the writer's mesh of
// the comment's object: its tessellation placed by its matrix.
bool ObjImporter::isWrittenMesh(const ObjGroup& group, const ObjectComment& c) const {
  TriangleMesh mesh = primitiveMesh(c.object.kind, c.segments, c.planeHalfSize);
  if (group.corners.size() != mesh.indices.size()) return false;
  std::vector<glm::dvec3> expected;
  double size = 0.0;
  for (const glm::vec3& p : mesh.positions) {
    expected.emplace_back(c.object.matrix * glm::dvec4(glm::dvec3(p), 1.0));
    size = std::max({size, std::abs(expected.back().x), std::abs(expected.back().y),
                     std::abs(expected.back().z)});
  }
  double tolerance = kMeshAgreement * size;
  bool mirrored = glm::determinant(glm::dmat3(c.object.matrix)) < 0.0;
  for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
    for (std::size_t k = 0; k < 3; ++k) {
      glm::dvec3 d = file_.positions[group.corners[t + k]] -
                     expected[mesh.indices[t + (mirrored ? 2 - k : k)]];
      if (!(std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)}) <= tolerance)) return false;
    }
  }
  return true;
}

// The group's material: the comment's while the MTL still holds what the
// writer wrote for it (or no MTL was read), else the MTL's.
Material ObjImporter::groupMaterial(const ObjGroup& group, const ObjectComment* c) {
  if (group.severalMaterials) {
    out_.note(DiagnosticCode::ObjIgnored, group.span,
              "group '" + group.name + "' uses several materials: the first, '" +
                  objPrintableName(group.material) + "', colours it all");
  }
  auto found = materials_.find(group.material);
  if (found == materials_.end()) {
    if (librariesRead_ && !group.material.empty() && unknownMaterials_.size() < 16 &&
        unknownMaterials_.insert(group.material).second) {
      out_.warning(DiagnosticCode::ObjMaterial, group.materialSpan,
                   "no MTL file read defines the material '" + objPrintableName(group.material) +
                       "': it is read as " + (c ? "its comment gives it" : "the default"));
    }
    return c ? c->object.material : Material{};
  }
  if (c) {
    if (sameMtl(found->second, mtlOf(c->object.material))) return c->object.material;
    out_.note(DiagnosticCode::ObjCommentStale, group.materialSpan,
              "the material of group '" + group.name +
                  "' no longer matches its comment (the MTL was edited elsewhere): it is read "
                  "from the MTL");
  }
  return materialOf(found->second);
}

void ObjImporter::addGroup(const ObjGroup& group) {
  const ObjectComment* c = group.comment ? &*group.comment : nullptr;
  Object object;
  if (c && isWrittenMesh(group, *c)) {
    object = c->object;
    object.material = groupMaterial(group, c);
    object.span = group.span;
    result_.scene.objects.push_back(std::move(object));
    return;
  }
  if (c) {
    out_.note(DiagnosticCode::ObjCommentStale, group.span,
              "group '" + group.name + "' no longer matches the " +
                  std::string(objectKindName(c->object.kind)) +
                  " that its comment describes (the file was edited elsewhere): its mesh is "
                  "read as it is");
  }
  // The group's own vertices, numbered from 0, for the fitting.
  std::map<std::uint32_t, std::uint32_t> local;
  std::vector<glm::dvec3> positions;
  std::vector<std::uint32_t> indices;
  for (std::uint32_t corner : group.corners) {
    auto [it, fresh] = local.emplace(corner, static_cast<std::uint32_t>(positions.size()));
    if (fresh) positions.push_back(file_.positions[corner]);
    indices.push_back(it->second);
  }
  FitResult fit = fitPrimitive(positions, indices);
  if (!fit.fit) {
    out_.report(loss_, DiagnosticCode::ObjMeshNotPrimitive, group.span,
                "group '" + group.name + "' is not a sphere, box, cylinder or plane (" +
                    fit.reason + "); it is skipped")
        .hint = "the tolerance is " + formatNumber(kFitTolerance) +
                " of the shape's size; see docs/GLTF.md, \"Other programs' meshes\"";
    return;
  }
  out_.note(DiagnosticCode::ObjMeshFit, group.span,
            "group '" + group.name + "' is read as a " +
                std::string(objectKindName(fit.fit->kind)) + " (largest deviation " +
                formatNumber(fit.fit->error) + " of its size)");
  object.kind = fit.fit->kind;
  object.matrix = fit.fit->shape;
  // The material's comment is judged on its own: a mesh reshaped elsewhere
  // may keep its material.
  object.material = groupMaterial(group, c);
  object.span = group.span;
  result_.scene.objects.push_back(std::move(object));
}

// OBJ has no camera: one on +Z that sees every object's centre.
void ObjImporter::defaultCamera() {
  std::optional<glm::dmat4> camera = cameraSeeingObjects(result_.scene.objects);
  if (!camera) {
    out_.error(DiagnosticCode::ValueNotFinite, {},
               "the file has no camera, and one on +Z that sees every object would stand "
               "beyond the largest number");
    return;
  }
  result_.scene.camera.matrix = *camera;
  out_.note(DiagnosticCode::ObjNoCamera, {},
            "the file has no camera (OBJ holds none): CAMERA looks at the scene from +Z");
}

}  // namespace

ReadResult parseObj(std::string_view text, std::string fileName,
                    const std::optional<fs::path>& folder, const ReadOptions& options) {
  ReadResult result{Scene{}, DiagnosticList(fileName, options.errorLimit)};
  ObjImporter(folder, options, result).run(text);
  if (result.diagnostics.hasErrors()) return result;
  result.diagnostics.append(validateScene(result.scene, fileName));
  return result;
}

}  // namespace scene
