// A libscene scene compiled for tracing: per object the inverse and normal
// matrices and world bounds, a BVH over the bounded objects, and the
// unbounded planes kept aside.
#pragma once

#include <cstdint>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <optional>
#include <vector>

#include "renderer/bvh.h"
#include "renderer/direction_grid.h"
#include "renderer/material_maxima.h"
#include "renderer/unit_shapes.h"
#include "renderer/unset_allocator.h"
#include "scenefile/scene.h"

namespace render {

struct Ray {
  glm::dvec3 origin{0.0};
  glm::dvec3 direction{0.0, 0.0, -1.0};
};

// Which surface a ray leaves, so that it is not found again at t = 0: a ray
// leaving a convex solid (or a plane) outward cannot meet it again, and one
// going inward meets it only where it leaves.
// (Objects are numbered as RenderScene numbers them: RenderScene::objects.)
struct RaySource {
  static constexpr std::uint32_t kNone = 0xFFFFFFFF;
  std::uint32_t object = kNone;
  bool inward = false;
};

// What every ray that reaches an object reads of it, and the number of its
// material (104 bytes): its colour, read once per hit, is kept apart in
// RenderScene, and neither the 3x3 block of its matrix (toWorldLinear, the
// inverse of toLocal, worked out where needed) nor the normal matrix (the
// transpose of toLocal) is kept.
struct RenderObject {
  glm::dmat3 toLocal{1.0};      // inverse of the 3x3 block of the object's matrix
  glm::dvec3 translation{0.0};  // the matrix's last column
  scene::ObjectKind kind = scene::ObjectKind::Sphere;
  // Its material's properties but the colour: an index into a table of the
  // scene's distinct ones (in the padding after `kind`).
  std::uint32_t material = 0;

  // A world point in object space. The translation comes off first, in
  // world space: folding it into an offset (toLocal * t) would cancel large
  // terms for a small object far from the origin.
  glm::dvec3 toLocalPoint(const glm::dvec3& p) const { return toLocal * (p - translation); }
  // A normal in object space to world space, by the inverse transpose of
  // the 3x3 block: v * toLocal is transpose(toLocal) * v in glm, with the
  // same products added in the same order, so the same bits.
  glm::dvec3 normalToWorld(const glm::dvec3& n) const { return n * toLocal; }
  // The 3x3 block of the object's matrix as the tracer takes it: the
  // inverse of toLocal, so that the hit points, the BVH's boxes and the
  // grids all follow the one matrix that the intersections use.
  glm::dmat3 toWorldLinear() const;
};
static_assert(sizeof(RenderObject) == 104);

// The record of an object of kind `kind` under `toWorld` (material 0).
RenderObject renderObject(scene::ObjectKind kind, const glm::dmat4& toWorld);

// Object numbers first, first + 1, ..., first + count - 1: the bounded
// objects, laid out after the planes in the BVH's order (BVH item k is
// object first + k).
struct ObjectRange {
  std::uint32_t first = 0;
  std::uint32_t count = 0;
  std::size_t size() const { return count; }
  bool empty() const { return count == 0; }
  std::uint32_t operator[](std::size_t k) const { return first + static_cast<std::uint32_t>(k); }
};

struct RenderLight {
  glm::dvec3 position{0.0};
  glm::dvec3 colour{1.0};
};

// A surface point found by a ray.
struct Hit {
  double t = 0.0;
  std::uint32_t object = RaySource::kNone;  // as RenderScene numbers it (objects())
  glm::dvec3 point{0.0};                    // world space, on the surface
  glm::dvec3 pointError{0.0};               // bound on the error of `point`
  glm::dvec3 normal{0.0};                   // unit, outward (for a plane: its +y side)
  bool fromInside = false;                  // the ray was inside the solid
};

// The bounded objects binned by their direction from a camera's eye
// (RenderScene::eyeGrid), for its camera rays, which all leave the eye.
struct EyeGrid {
  DirectionGrid grid;
  // Per cell, the signs of its centre direction (bit i: component i is
  // negative, as Bvh::traverse takes them): its list is in the order in
  // which the BVH visits items for such a ray, and a ray with other signs
  // walks the BVH. kAnySigns for a cell of fewer than two items, whose
  // order is moot: every ray through it may use it.
  std::vector<std::uint8_t> signs;
  static constexpr std::uint8_t kAnySigns = 0xFF;
  // Whether a ray leaving the eye in `direction` through `cell` may take
  // the cell's list for its closest hit.
  bool servesSigns(std::uint32_t cell, const glm::dvec3& direction) const {
    return signs[cell] == kAnySigns || signs[cell] == directionSigns(direction);
  }
};

/// What a RenderScene holds after its build, by part, in bytes (its arrays'
/// elements): for a memory report.
struct RenderSceneMemory {
  std::uint64_t records = 0;  ///< the objects' and lights' records
  std::uint64_t bvh = 0;      ///< the hierarchy
  std::uint64_t grids = 0;    ///< the lights' direction grids
};

class RenderScene {
 public:
  /// Compiles the scene as RenderSceneBuilder does, in one batch (defined
  /// in render_scene_builder.cpp), its BVH built on `threads` threads (0: every
  /// core), which changes how long that takes, never what it builds.
  /// `lightGrids` false leaves out the lights' direction grids (lightGrid),
  /// for the tests and benchmarks that compare: the answers are the same.
  /// `imageSamples` as RenderSceneBuilder::finish takes them.
  explicit RenderScene(const scene::Scene& scene, int threads = 0, bool lightGrids = true,
                       std::optional<std::uint64_t> imageSamples = std::nullopt);

  /// What the build (RenderSceneBuilder) allocates for a scene of `objects`
  /// objects, `lights` lights and `materials` distinct materials (colour
  /// aside), in bytes, as two parts.
  struct Bytes {
    /// Made as the objects are added: the objects' records, colours and
    /// scene indices, the materials' table, the lights.
    std::uint64_t scene = 0;
    /// Made by finish(): the BVH with its build's temporaries, or for
    /// planes their normals and list; the records' reorder's temporaries;
    /// and the lights' direction grids with theirs, where a render of
    /// `cameraSamples` samples builds them (lightGridsPay).
    std::uint64_t bvh = 0;
  };
  /// The most the build holds for such a scene, from the sizes and
  /// capacities it allocates (Bvh::bytesFor for the hierarchy), so that a
  /// caller can refuse a scene that cannot fit before compiling it; the
  /// scene::Scene itself is not counted. Saturates: a hostile count gives
  /// UINT64_MAX, never a wrapped figure.
  static Bytes bytesFor(std::uint64_t objects, std::uint64_t lights, std::uint64_t materials,
                        std::uint64_t cameraSamples);

  /// What this scene holds, by part.
  RenderSceneMemory memory() const;

  /// The objects' records, numbered as every object here is (Hit::object,
  /// RaySource::object, the accessors below): the planes first, then the
  /// bounded objects in the BVH's order, where neighbours in space lie
  /// together in memory. sceneObject gives an object's index in the scene.
  const UnsetVector<RenderObject>& objects() const { return objects_; }
  /// The index in scene::Scene::objects of object `object`.
  std::uint32_t sceneObject(std::uint32_t object) const { return sceneObjects_[object]; }
  scene::Material material(std::uint32_t object) const {
    scene::Material m = materials_[objects_[object].material];
    m.colour = colours_[object];
    return m;
  }
  const std::vector<RenderLight>& lights() const { return lights_; }
  const scene::Camera& camera() const { return camera_; }
  bool hasTransparency() const { return hasTransparency_; }
  // The objects' materials' largest terms (RadianceBound's).
  const MaterialMaxima& materialMaxima() const { return materialMaxima_; }
  const Bvh& bvh() const { return bvh_; }
  // What the GPU renderer uploads (renderer/gpu/gpu_scene.h): per BVH item
  // its object, the planes kept apart, and each object's 3x3 block.
  ObjectRange boundedObjects() const { return bounded_; }
  const std::vector<std::uint32_t>& planeObjects() const { return planes_; }
  glm::dmat3 linearToWorld(std::uint32_t object) const { return objects_[object].toWorldLinear(); }

  // The nearest surface with 0 < t < tMax.
  std::optional<Hit> closestHit(const Ray& ray, const RaySource& source,
                                double tMax = std::numeric_limits<double>::infinity()) const;
  // closestHit for each of `count` rays (out[k] for rays[k], sources[k]),
  // found as packets of Bvh::kPacketSize rays walked down the hierarchy
  // together (Bvh::traversePacket): the same hits, bit for bit, at less cost
  // where the rays are coherent (a row of camera rays).
  void closestHits(const Ray* rays, const RaySource* sources, int count, std::optional<Hit>* out,
                   double tMax = std::numeric_limits<double>::infinity()) const;
  // Whether any surface lies at 0 < t < tMax (shadow rays: transparent
  // objects cast shadows too). `lastOccluder`, when given, is a hint kept by
  // the caller: the object tested first (neighbouring shadow rays toward one
  // light are mostly blocked by the same object), then set to the object
  // that blocked this ray, or to none (RaySource::kNone) when nothing did,
  // so that unblocked rays, most of them, pay no extra test. The answer
  // does not depend on it: it is whether any object blocks, and the hint
  // only finds one sooner.
  bool anyHit(const Ray& ray, const RaySource& source, double tMax,
              std::uint32_t* lastOccluder = nullptr) const;
  // anyHit for each of `count` rays (blocked[k] for rays[k], sources[k],
  // tMaxes[k]), the hint tried first on each; those it leaves open walk the
  // hierarchy as packets of Bvh::kPacketSize (shadow rays toward one light
  // from neighbouring hits). The same answers as anyHit's, ray by ray.
  void anyHits(const Ray* rays, const RaySource* sources, const double* tMaxes, int count,
               bool* blocked, std::uint32_t* lastOccluder) const;
  // anyHit for a shadow ray aimed at light `light`, whose direction is
  // lights()[light].position - ray.origin: the same answer, found through
  // the light's direction grid (lightGrid) where a cell can give it: `cell`
  // when given (shadowCell's for the hit the ray leaves), else the cell of
  // the ray's own direction.
  bool anyHitTowardLight(std::size_t light, const Ray& ray, const RaySource& source, double tMax,
                         std::uint32_t* lastOccluder = nullptr,
                         std::uint32_t cell = DirectionGrid::kNoCell) const;
  // The cell of light `light`'s grid that lists every bounded object a
  // shadow ray toward it from a hit at `point` (within `pointError`) can
  // meet, whatever origin off the surface the ray starts from; kNoCell
  // where the grid cannot tell (no grid, a full cell, an origin's possible
  // offset too large beside the distance to the light).
  std::uint32_t shadowCell(std::size_t light, const glm::dvec3& point,
                           const glm::dvec3& pointError) const;
  // Whether the scene has no plane but `source`, which a ray leaving it
  // cannot meet: then a shadow ray from `source` whose shadowCell lists
  // nothing is clear.
  bool noPlaneBut(std::uint32_t source) const {
    return planes_.empty() || (planes_.size() == 1 && planes_[0] == source);
  }
  // The objects binned by their direction from light `light` (bounded
  // objects by their BVH item), or nullptr for a light that has none: only
  // the first kMaxLightGrids lights have one.
  const DirectionGrid* lightGrid(std::size_t light) const {
    return light < lightGrids_.size() && lightGrids_[light].built() ? &lightGrids_[light] : nullptr;
  }
  static constexpr std::size_t kMaxLightGrids = 8;
  // The lights' grids built side by side, on as many threads, at most.
  static constexpr int kGridsBuiltAtOnce = 2;
  // Scenes with fewer objects make their records on one thread: starting
  // more would cost about what they save.
  static constexpr std::size_t kMinParallelObjects = 16384;
  // Scenes with fewer bounded objects have no light grids: any bounded
  // object pays for them. At 5 to 50 objects they take 10% to 18% of the
  // instructions off a render (callgrind); their build is a millisecond.
  static constexpr std::size_t kMinLightGridObjects = 1;
  // Whether the lights' direction grids pay for their build in a render of
  // `cameraSamples` camera samples (uniformSampleCount) of a scene of
  // `objects` objects: from kLightGridSamplesPerObject samples an object
  // on. Their build costs about the same for each bounded object and what
  // they save about the same for each shadow ray, which the camera samples
  // stand for (docs/TRACING.md, "Direction grids"). All objects are
  // counted, planes too, so that the memory estimate (bytesFor) knows it
  // before the objects are read.
  static bool lightGridsPay(std::uint64_t objects, std::uint64_t cameraSamples) {
    return objects >= kMinLightGridObjects && cameraSamples / kLightGridSamplesPerObject >= objects;
  }
  // At floor-1000000 in 1080p at 1 spp (2.1 samples an object) they took
  // 0.3 to 0.6 s to build and 0.54 s off the render, about even, and held
  // 61 bytes an object; at 720p and 4 spp (3.7), 0.31 s for 0.69 s.
  static constexpr std::uint64_t kLightGridSamplesPerObject = 3;
  // Renders of scenes with fewer bounded objects have no eye grid: below
  // that, the packets' walk of a small BVH is about as quick (glass-mirror,
  // 8 objects: 1% fewer instructions with it).
  static constexpr std::size_t kMinEyeGridObjects = 64;
  // How the faces of a light's grid are cut (DirectionGrid::FaceCells):
  // 8 cells a box, fewer where boxes overlap as seen from the light, on
  // the rectangle of each face that boxes reach, at most 1024 x 1024.
  // Against whole faces of 4 sqrt(n) cells a side (at most 512), the same
  // images and 5% less CPU at floor-100000 in 1080p, 20% less rendering at
  // floor-1000000 (docs/history/PERFORMANCE.md, "Light grids fitted to
  // their boxes"); 16 a box was no quicker and built larger grids.
  static constexpr DirectionGrid::FaceCells kLightGridCells{8.0, 8.0, 1,
                                                            std::uint64_t{1024} * 1024};
  // The world box of BVH item `item`, as the constructor made it.
  Bounds itemBounds(std::uint32_t item) const;

  // The grid of the bounded objects' directions from `eye` in `window`
  // (docs/TRACING.md, "Direction grids"); not built (grid.built() false)
  // where the objects would cover too many cells.
  EyeGrid eyeGrid(const glm::dvec3& eye, const GridWindow& window) const;
  // closestHits for camera rays: a ray leaving the grid's apex whose cell
  // can answer tests the planes and that cell's objects alone, in the order
  // the BVH would visit them, so that the hit is the same bit for bit; the
  // others go down the BVH as packets.
  void closestHitsFromEye(const EyeGrid& eye, const Ray* rays, int count,
                          std::optional<Hit>* out) const;

  // For `count` rays that leave no surface, the hit that closestHit makes
  // where rays[k] meets object objects[k] nearer than tMaxes[k], or none
  // (also for RaySource::kNone): for a search made by other means (another
  // tracer's hierarchy) to finish with the renderer's own hits, bit for bit,
  // as the packet searches make them.
  void hitsOnObjects(const std::uint32_t* objects, const Ray* rays, const double* tMaxes, int count,
                     std::optional<Hit>* out) const;

  // The same queries without the hierarchy: every object is tested. The
  // reference that the BVH must agree with.
  std::optional<Hit> closestHitBruteForce(const Ray& ray, const RaySource& source,
                                          double tMax) const;

  // Transparent solids that contain `p`, outermost first (by volume): the
  // media a camera placed there starts in.
  std::vector<std::uint32_t> mediaContaining(const glm::dvec3& p) const;

 private:
  struct Candidate {
    double t;
    bool atExit;  // the far end of the span: the ray was inside
    SpanFace face;
  };
  std::optional<Candidate> intersectObject(std::uint32_t index, const Ray& ray,
                                           const RaySource& source, double tMax) const;
  // intersectObject for plane `index` (one of planes_), bit for bit, from
  // the y row of its transform alone: a plane's distance reads only the
  // object-space y of the origin and the direction, and every ray tests
  // every plane.
  std::optional<Candidate> intersectPlane(std::uint32_t index, const Ray& ray,
                                          const RaySource& source, double tMax) const;
  // The searches' first step: every plane, the nearest met before
  // bestCandidate.t becoming `best` (closestHit and the packet and eye
  // searches alike).
  void considerPlanes(const Ray& ray, const RaySource& source, std::uint32_t& best,
                      Candidate& bestCandidate) const;
  // The hit on object `index` that `candidate` found along `ray`, written
  // into `hit` in place: returned by value, it was copied into an optional
  // with wide loads that waited on the narrow stores that made it.
  void hitOn(std::uint32_t index, const Ray& ray, const Candidate& candidate, Hit& hit) const;
  // The same with the object's toWorldLinear() given: the searches of many
  // rays work it out once for consecutive hits on one object.
  void hitOn(std::uint32_t index, const Ray& ray, const Candidate& candidate,
             const glm::dmat3& toWorldLinear, Hit& hit) const;
  // The same hit in a new optional.
  std::optional<Hit> hitOn(std::uint32_t index, const Ray& ray, const Candidate& candidate) const {
    std::optional<Hit> hit;
    hitOn(index, ray, candidate, hit.emplace());
    return hit;
  }
  friend class RenderSceneBuilder;
  RenderScene() = default;
  // The build's last step (RenderSceneBuilder::finish): each item's leaf,
  // and the lights' grids over the leaves' boxes.
  void buildLightGrids(int threads);
  // The box of the leaf that holds BVH item `item`, which contains the
  // item's (itemBounds).
  Bounds leafBox(std::uint32_t item) const;
  // Whether the ray meets the box of the leaf holding BVH item `item`
  // within (0, tMax): hitsBox on the leaf's float box, which contains the
  // object's box.
  bool meetsItemBox(std::uint32_t item, const BoxRay& ray, double tMax) const;
  // Whether a plane blocks the ray within (0, tMax); if so, it becomes
  // `lastOccluder`, when there is one.
  bool blockedByPlane(const Ray& ray, const RaySource& source, double tMax,
                      std::uint32_t* lastOccluder) const;

  // Written in full by RenderSceneBuilder::add, on its threads.
  UnsetVector<RenderObject> objects_;
  UnsetVector<glm::dvec3> colours_;          // per object, read once per hit
  std::vector<scene::Material> materials_;   // RenderObject::material's table (colour unused)
  std::vector<std::uint32_t> sceneObjects_;  // object -> its index in the scene
  ObjectRange bounded_;                      // BVH item -> object
  std::vector<std::uint32_t> planes_;        // unbounded objects, tested for every ray
  // Per plane (as planes_: objects 0 to its size less 1), its world normal:
  // the same at every point, so made once, by the expression hitOn uses
  // for other objects.
  std::vector<glm::dvec3> planeNormals_;
  std::vector<RenderLight> lights_;
  scene::Camera camera_;
  Bvh bvh_;
  std::vector<DirectionGrid> lightGrids_;
  // Per BVH item, the leaf that holds it, made with the light grids: their
  // rays test its box before the object, as a walk down the BVH would.
  std::vector<std::uint32_t> leafOf_;
  bool hasTransparency_ = false;
  MaterialMaxima materialMaxima_;
};

// The axis-aligned box of a unit shape under an object matrix, as the
// matrix's numbers give it (none for a plane): what a user is shown.
std::optional<Bounds> shapeBounds(scene::ObjectKind kind, const glm::dmat4& toWorld);
// shapeBounds widened by its own rounding, so that it holds every point the
// tracer can find on the shape.
std::optional<Bounds> worldBounds(scene::ObjectKind kind, const glm::dmat4& toWorld);
// worldBounds of a compiled object, under the matrix the tracer takes
// (RenderObject::toWorldLinear and its translation).
std::optional<Bounds> worldBounds(const RenderObject& object);

}  // namespace render
