// The glTF's meshes as the scene's primitives: each primitive's triangles
// read from its accessors, with every bound checked before a byte is read,
// and handed to the fitting (mesh_fit.h), which tells which of the four
// primitives they describe.
#pragma once

#include <cstddef>
#include <glm/mat4x4.hpp>
#include <initializer_list>
#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "libscene/formats/gltf/gltf_import_context.h"
#include "scenefile/mesh_fit.h"
#include "scenefile/read.h"

namespace scene::gltf {

// One object that a mesh becomes, and the glTF material that colours it.
struct FittedPart {
  MeshFit fit;
  int material = -1;
};

class MeshReader {
 public:
  // Bounds the POSITION vertices and the indices read from the whole file
  // by options.gltf.maxVertices (and three times as many indices).
  MeshReader(const ImportContext& context, const ReadOptions& options);

  // The objects of mesh `mesh`, fitted once however many nodes use it
  // (`node` names the first in the messages): all its primitives as one
  // shape first (an exporter splits a mesh by material), else each alone;
  // none when it is not a primitive.
  const std::vector<FittedPart>& fitMesh(int mesh, int node);

  // Whether the mesh's one primitive is the writer's mesh of `kind`
  // (isWrittenMesh, gltf_extras.h): a node edited to point at another mesh,
  // or a mesh edited, keeps its old extras, and they are believed only while
  // the mesh is still their kind's. Cached by accessors, which the writer
  // shares among a kind's meshes.
  bool holdsWrittenMesh(int mesh, ObjectKind kind);

  // The instances of node `node`'s EXT_mesh_gpu_instancing (`attributes`,
  // its JSON): each one's TRANSLATION * ROTATION * SCALE, read from float
  // accessors of one count. Nothing when the node has none; an empty list
  // with a diagnostic when they cannot be read (a loss for a valid file
  // whose accessors are not floats, an error for an invalid one, or for
  // more than `limit` instances, which bounds what is allocated).
  std::optional<std::vector<glm::dmat4>> instanceMatrices(int node, std::size_t limit);

 private:
  // The triangles of one primitive, as indices into its POSITION data.
  struct Triangles {
    std::vector<glm::dvec3> positions;
    std::vector<std::uint32_t> indices;
  };
  // Where an accessor's elements lie in its buffer, once every bound holds.
  struct Layout {
    const unsigned char* base = nullptr;
    std::size_t stride = 0;
    int componentSize = 0;
    int components = 0;
  };

  std::optional<std::vector<double>> readAccessor(int index, int wantType,
                                                  std::initializer_list<int> componentTypes,
                                                  const std::string& role, std::size_t limit,
                                                  std::size_t& read, bool& skipped);
  bool accessorReadable(int index, int wantType, std::initializer_list<int> componentTypes,
                        const std::string& role, std::size_t limit, std::size_t read,
                        bool& skipped);
  std::optional<Layout> accessorLayout(int index, const std::string& role);
  std::optional<Triangles> primitiveTriangles(int mesh, std::size_t p);
  std::optional<std::vector<std::uint32_t>> vertexOrder(int indices, std::size_t vertices,
                                                        const std::string& label);
  void reportFit(const std::string& label, const MeshFit& fit);

  const ImportContext& c_;
  std::map<int, std::vector<FittedPart>> fitted_;
  // By POSITION accessor, indices accessor, mode and kind.
  std::map<std::tuple<int, int, int, ObjectKind>, bool> writtenMesh_;
  // POSITION vertices and indices allowed in the whole file, and read so far.
  std::size_t maxVertices_;
  std::size_t maxIndices_;
  std::size_t verticesRead_ = 0;
  std::size_t indicesRead_ = 0;
};

}  // namespace scene::gltf
