#include "libscene/formats/obj/obj_writer.h"

#include <algorithm>
#include <cmath>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "libscene/formats/obj/obj_exact.h"
#include "libscene/formats/obj/obj_mtl.h"
#include "libscene/text/number.h"
#include "scenefile/mesh.h"

namespace scene {

namespace {

bool finite(const glm::dvec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

void appendLine(std::string& out, std::string_view statement, const glm::dvec3& v) {
  out += statement;
  for (double x : {v.x, v.y, v.z}) {
    out += ' ';
    appendNumber(out, x);
  }
  out += '\n';
}

// The sphere and the cylinder are smooth: their normals go with them, so
// that other programs shade them round. The box and the plane are flat,
// which every program makes of faces without normals.
bool smooth(ObjectKind kind) {
  return kind == ObjectKind::Sphere || kind == ObjectKind::Cylinder;
}

void reportLosses(const Scene& scene, Severity severity, DiagnosticList& out) {
  out.report(severity, DiagnosticCode::ObjWriteLoss, scene.camera.span,
             "CAMERA is not written as OBJ: the format has no camera")
      .hint =
      "other programs show the meshes from a camera of their own; the OBJ reader reads the "
      "camera back from the file's comments";
  for (std::size_t i = 0; i < scene.lights.size(); ++i) {
    out.report(severity, DiagnosticCode::ObjWriteLoss, scene.lights[i].span,
               "LIGHT " + std::to_string(i + 1) +
                   " is not written as OBJ: the format has no "
                   "lights")
        .hint = "the OBJ reader reads the lights back from the file's comments";
  }
}

// One object's group: its comment, `o`, `usemtl`, its vertices in world
// space, its normals for a smooth shape, and its triangles turning
// counter-clockwise seen from outside (reversed under a mirroring matrix).
// `written` counts the vertices and the normals written before it: OBJ
// numbers each kind on its own.
struct Written {
  std::size_t vertices = 0;
  std::size_t normals = 0;
};

bool appendObject(std::string& obj, const ObjectComment& c, std::size_t index, Written& written,
                  bool material, DiagnosticList& out) {
  const Object& object = c.object;
  TriangleMesh mesh = primitiveMesh(object.kind, c.segments, c.planeHalfSize);
  std::string name = objGroupName(object, index);
  std::string text = objectComment(c) + "o " + name + "\n";
  if (material) text += "usemtl " + name + "\n";
  for (const glm::vec3& p : mesh.positions) {
    glm::dvec3 world(object.matrix * glm::dvec4(glm::dvec3(p), 1.0));
    if (!finite(world)) {
      out.error(DiagnosticCode::ValueNotFinite, object.span,
                std::string(objectKindName(object.kind)) + " object " + std::to_string(index + 1) +
                    ": a vertex of its mesh in world space is not finite (OBJ has no "
                    "transforms, so each vertex is written where the matrix puts it)");
      return false;
    }
    appendLine(text, "v", world);
  }
  glm::dmat3 normalMatrix = glm::transpose(glm::inverse(glm::dmat3(object.matrix)));
  bool normals = smooth(object.kind);
  if (normals) {
    std::string lines;
    for (const glm::vec3& n : mesh.normals) {
      glm::dvec3 world = glm::normalize(normalMatrix * glm::dvec3(n));
      normals = normals && finite(world);
      appendLine(lines, "vn", world);
    }
    if (normals) text += lines;
  }
  bool mirrored = glm::determinant(glm::dmat3(object.matrix)) < 0.0;
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    text += 'f';
    for (int k = 0; k < 3; ++k) {
      std::size_t corner = mesh.indices[t + (mirrored ? 2 - k : k)];
      std::string v = std::to_string(written.vertices + corner + 1);
      std::string n = std::to_string(written.normals + corner + 1);
      text += ' ' + (normals ? v + "//" + n : v);
    }
    text += '\n';
  }
  written.vertices += mesh.positions.size();
  if (normals) written.normals += mesh.normals.size();
  obj += text;
  return true;
}

}  // namespace

std::string objGroupName(const Object& object, std::size_t index) {
  return std::string(objectKindName(object.kind)) + "_" + std::to_string(index + 1);
}

std::optional<ConvertedFiles> writeObj(const Scene& scene, const ConversionOptions& options,
                                       DiagnosticList& out) {
  std::size_t errors = out.errorCount();
  reportLosses(scene, options.noLoss ? Severity::Error : Severity::Warning, out);
  if (out.errorCount() != errors) return std::nullopt;
  int segments = std::clamp(options.obj.segments, kMinSegments, kMaxSegments);
  float planeSize = scenePlaneHalfSize(scene);
  const std::string& library = options.obj.materialLibrary;
  ConvertedFiles files;
  std::string& obj = files.main;
  obj =
      "# Wavefront OBJ written by scenefile: one group a primitive, its vertices in world space "
      "(OBJ has no transforms).\n"
      "# The '" +
      std::string(kObjExactComment) +
      "' comments carry the exact scene, camera and lights included, for reading back.\n";
  if (!library.empty()) obj += "mtllib " + library + "\n";
  obj += sceneComments(scene);
  Written written;
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    ObjectComment c{scene.objects[i], segments, planeSize};
    if (!appendObject(obj, c, i, written, !library.empty(), out)) return std::nullopt;
    if (!library.empty()) {
      files.sidecar +=
          mtlBlock(objGroupName(scene.objects[i], i), mtlOf(scene.objects[i].material));
    }
  }
  if (!library.empty() && files.sidecar.empty()) files.sidecar = "# no materials\n";
  return files;
}

}  // namespace scene
