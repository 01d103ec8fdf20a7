#include "renderer/render_scene.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <numeric>

#include "renderer/bvh_packet.h"
#include "renderer/float_error.h"
#include "renderer/parallel_parts.h"
#include "renderer/permute_in_place.h"
#include "renderer/saturating.h"
#include "renderer/unit_shapes.h"

namespace render {

namespace {

// The inverse of a 3x3 block from its adjugate: each entry is a product of
// the original entries, which keeps the digits that glm::inverse's division
// first would lose on a badly scaled block.
glm::dmat3 inverse3(const glm::dmat3& a) {
  glm::dmat3 adjugateT(glm::cross(a[1], a[2]), glm::cross(a[2], a[0]), glm::cross(a[0], a[1]));
  double det = glm::dot(a[0], adjugateT[0]);
  return glm::transpose(adjugateT) / det;
}

// Half the size of a unit shape's box under `m` on each axis (none for a
// plane); the box's centre is m[3].
std::optional<glm::dvec3> shapeExtent(scene::ObjectKind kind, const glm::dmat4& m) {
  if (kind == scene::ObjectKind::Plane) return std::nullopt;
  glm::dvec3 extent(0.0);
  for (int r = 0; r < 3; ++r) {
    double x = m[0][r];
    double y = m[1][r];
    double z = m[2][r];
    switch (kind) {
      case scene::ObjectKind::Sphere:
        extent[r] = std::sqrt(x * x + y * y + z * z);
        break;
      case scene::ObjectKind::Cylinder:
        extent[r] = std::sqrt(x * x + z * z) + std::abs(y);
        break;
      case scene::ObjectKind::Cube:
        extent[r] = std::abs(x) + std::abs(y) + std::abs(z);
        break;
      case scene::ObjectKind::Plane:  // unbounded: returned above
        break;
    }
  }
  return extent;
}

// The 3x3 block of the object the last hit was on (toWorldLinear, an
// inverse): neighbouring rays of a packet or a row mostly meet one object,
// whose inverse is then worked out once for the run of them.
class LastHitLinear {
 public:
  const glm::dmat3& of(std::uint32_t index, const RenderObject& object) {
    if (index != index_) {
      index_ = index;
      linear_ = object.toWorldLinear();
    }
    return linear_;
  }

 private:
  std::uint32_t index_ = RaySource::kNone;
  glm::dmat3 linear_{1.0};
};

}  // namespace

std::optional<Bounds> shapeBounds(scene::ObjectKind kind, const glm::dmat4& m) {
  std::optional<glm::dvec3> extent = shapeExtent(kind, m);
  if (!extent) return std::nullopt;
  glm::dvec3 centre(m[3]);
  return Bounds{centre - *extent, centre + *extent};
}

RenderObject renderObject(scene::ObjectKind kind, const glm::dmat4& toWorld) {
  RenderObject record;
  record.kind = kind;
  record.translation = glm::dvec3(toWorld[3]);
  record.toLocal = inverse3(glm::dmat3(toWorld));
  return record;
}

glm::dmat3 RenderObject::toWorldLinear() const {
  return inverse3(toLocal);
}

std::optional<Bounds> worldBounds(const RenderObject& object) {
  glm::dmat4 matrix(object.toWorldLinear());
  matrix[3] = glm::dvec4(object.translation, 1.0);
  return worldBounds(object.kind, matrix);
}

std::optional<Bounds> worldBounds(scene::ObjectKind kind, const glm::dmat4& m) {
  std::optional<glm::dvec3> extent = shapeExtent(kind, m);
  if (!extent) return std::nullopt;
  glm::dvec3 centre(m[3]);
  // Widen by the rounding of the bounds themselves.
  glm::dvec3 slack = gamma(8) * (abs(centre) + *extent);
  return Bounds{centre - *extent - slack, centre + *extent + slack};
}

RenderScene::Bytes RenderScene::bytesFor(std::uint64_t objects, std::uint64_t lights,
                                         std::uint64_t materials, std::uint64_t cameraSamples) {
  // The vectors of RenderSceneBuilder. Made as objects are added: per
  // object its record, colour and scene index (the order finish() lays the
  // records out in), and the table of materials with their numbers by
  // their properties (a std::map node each, about four pointers besides).
  Bytes bytes;
  constexpr std::uint64_t kPerObject =
      sizeof(RenderObject) + sizeof(glm::dvec3) + sizeof(std::uint32_t);
  constexpr std::uint64_t kPerMaterial = sizeof(scene::Material) +
                                         sizeof(std::array<std::uint64_t, 7>) +
                                         sizeof(std::uint32_t) + 4 * sizeof(void*);
  bytes.scene = saturatingSum(saturatingSum(saturatingProduct(objects, kPerObject),
                                            saturatingProduct(materials, kPerMaterial)),
                              saturatingProduct(lights, sizeof(RenderLight)));
  // Made by finish(), for bounded objects: the BVH with its build's
  // temporaries (Bvh::bytesFor), which the reorder's (a byte a record and
  // the records at every permute_in_place station) come after; for planes,
  // each one's normal and place in the plane list. The larger of the two,
  // as any object may be a plane.
  constexpr std::uint64_t kPerPlane = sizeof(glm::dvec3) + sizeof(std::uint32_t);
  constexpr std::uint64_t kReorderPerObject =
      1 + (sizeof(RenderObject) + sizeof(glm::dvec3)) / permute_detail::kStride + 1;
  bytes.bvh =
      std::max(saturatingSum(Bvh::bytesFor(objects), saturatingProduct(objects, kReorderPerObject)),
               saturatingProduct(objects, kPerPlane));
  // The lights' grids where they are built (DirectionGrid::bytes, bounded
  // by its limits), each item's leaf, and while the grids are built
  // (kGridsBuiltAtOnce at a time), each one's cell ranges of each box (at
  // most one a window, in a vector that may double).
  std::uint64_t grids = std::min<std::uint64_t>(lights, kMaxLightGrids);
  if (grids > 0 && lightGridsPay(objects, cameraSamples)) {
    DirectionGrid::Limits limits;
    std::uint64_t cells =
        saturatingProduct(DirectionGrid::kMaxWindows, kLightGridCells.bound(objects)) + 1;
    std::uint64_t entries =
        std::min(saturatingSum(saturatingProduct(limits.coverPerBox, objects), cells),
                 saturatingProduct(limits.perCell, cells));
    std::uint64_t perGrid = saturatingSum(saturatingProduct(cells, 9 + sizeof(std::uint32_t)),
                                          saturatingProduct(entries, sizeof(std::uint32_t)));
    std::uint64_t atOnce = std::min<std::uint64_t>(grids, kGridsBuiltAtOnce);
    std::uint64_t building = saturatingProduct(
        objects, atOnce * 2 * DirectionGrid::kMaxWindows * DirectionGrid::kRangeBytes);
    std::uint64_t leaves = saturatingProduct(objects, sizeof(std::uint32_t));
    bytes.bvh = saturatingSum(bytes.bvh, saturatingSum(saturatingProduct(grids, perGrid),
                                                       saturatingSum(building, leaves)));
  }
  return bytes;
}

namespace {

// The bytes of the elements a vector holds: room reserved past them (an
// estimate of the count a little over) is never touched, so never
// resident.
template <typename T, typename Allocator>
std::uint64_t heldBytes(const std::vector<T, Allocator>& v) {
  return static_cast<std::uint64_t>(v.size()) * sizeof(T);
}

}  // namespace

RenderSceneMemory RenderScene::memory() const {
  RenderSceneMemory memory;
  memory.records = heldBytes(objects_) + heldBytes(colours_) + heldBytes(materials_) +
                   heldBytes(sceneObjects_) + heldBytes(planes_) + heldBytes(planeNormals_) +
                   heldBytes(lights_);
  memory.bvh = bvh_.nodes().size_bytes() + heldBytes(bvh_.order());
  memory.grids = heldBytes(leafOf_);
  for (const DirectionGrid& grid : lightGrids_) memory.grids += grid.bytes();
  return memory;
}

void RenderScene::buildLightGrids(int threads) {
  // Each item's leaf first. The grids are built over the leaves' boxes, in
  // float, rounded outward from the items' (so holding them), read from the
  // nodes rather than copied into a list of their own; a shadow ray through
  // a cell tests the same box before the object (meetsItemBox).
  std::span<const BvhNode> nodes = bvh_.nodes();
  leafOf_.resize(bounded_.size());
  for (std::uint32_t node = 0; node < nodes.size(); ++node) {
    for (std::uint32_t k = 0; k < nodes[node].count; ++k) {
      leafOf_[nodes[node].offset + k] = node;
    }
  }
  const GridBoxes leafBoxes(bounded_.count, [this](std::uint32_t item) { return leafBox(item); });
  // The grids are independent: up to kGridsBuiltAtOnce at a time (what
  // bytesFor counts), each built by one thread as it would be alone.
  lightGrids_.resize(std::min(lights_.size(), kMaxLightGrids));
  runParts(lightGrids_.size(), std::min(threads, kGridsBuiltAtOnce), [&](std::size_t i) {
    lightGrids_[i] = DirectionGrid::cubeAround(lights_[i].position, leafBoxes, kLightGridCells,
                                               DirectionGrid::Limits{});
  });
}

Bounds RenderScene::leafBox(std::uint32_t item) const {
  const float* planes = bvh_.nodes()[leafOf_[item]].planes;
  return Bounds{glm::dvec3(planes[0], planes[1], planes[2]),
                glm::dvec3(planes[3], planes[4], planes[5])};
}

Bounds RenderScene::itemBounds(std::uint32_t item) const {
  return *worldBounds(objects_[bounded_[item]]);
}

EyeGrid RenderScene::eyeGrid(const glm::dvec3& eye, const GridWindow& window) const {
  std::vector<Bounds> boxes(bounded_.size());
  for (std::uint32_t item = 0; item < boxes.size(); ++item) boxes[item] = itemBounds(item);
  EyeGrid eyeGrid{
      DirectionGrid(eye, {window}, boxes,
                    DirectionGrid::Limits{.farLookup = std::numeric_limits<double>::infinity()}),
      {}};
  DirectionGrid& grid = eyeGrid.grid;
  if (!grid.built()) return eyeGrid;
  // Each cell's list in the BVH's order for its centre's direction signs;
  // with fewer than two items there is no order to keep (its corners were
  // a quarter of the grid's build at floor-100000 in 1080p).
  std::array<std::vector<std::uint32_t>, 8> ranks;
  eyeGrid.signs.assign(grid.cellCount(), EyeGrid::kAnySigns);
  for (std::uint32_t cell = 0; cell < grid.cellCount(); ++cell) {
    std::span<std::uint32_t> items = grid.mutableItems(cell);
    if (items.size() < 2) continue;
    std::array<glm::dvec3, 4> corners = grid.cellCorners(cell);
    glm::dvec3 centre = (corners[0] + corners[3]) * 0.5;
    std::uint8_t signs = directionSigns(centre);
    eyeGrid.signs[cell] = signs;
    if (ranks[signs].empty()) ranks[signs] = bvh_.visitRanks(signs);
    const std::vector<std::uint32_t>& rank = ranks[signs];
    std::sort(items.begin(), items.end(),
              [&](std::uint32_t a, std::uint32_t b) { return rank[a] < rank[b]; });
  }
  return eyeGrid;
}

void RenderScene::closestHitsFromEye(const EyeGrid& eye, const Ray* rays, int count,
                                     std::optional<Hit>* out) const {
  constexpr int kPacket = Bvh::kPacketSize;
  const RaySource fromEye[kPacket] = {};
  Ray left[kPacket];
  int leftAt[kPacket];
  LastHitLinear linear;
  for (int first = 0; first < count; first += kPacket) {
    int n = std::min(kPacket, count - first);
    int leftCount = 0;
    for (int k = first; k < first + n; ++k) {
      const Ray& ray = rays[k];
      std::uint32_t cell = ray.origin == eye.grid.apex() ? eye.grid.cellOf(0, ray.direction)
                                                         : DirectionGrid::kNoCell;
      if (cell == DirectionGrid::kNoCell || eye.grid.full(cell) ||
          !eye.servesSigns(cell, ray.direction)) {
        left[leftCount] = ray;
        leftAt[leftCount++] = k;
        continue;
      }
      // As closestHit: the planes, then the items in the BVH's order.
      std::uint32_t best = RaySource::kNone;
      Candidate bestCandidate{std::numeric_limits<double>::infinity(), false, SpanFace::None};
      auto consider = [&](std::uint32_t index) {
        if (auto c = intersectObject(index, ray, fromEye[0], bestCandidate.t)) {
          best = index;
          bestCandidate = *c;
        }
      };
      considerPlanes(ray, fromEye[0], best, bestCandidate);
      for (std::uint32_t item : eye.grid.items(cell)) consider(bounded_[item]);
      if (best == RaySource::kNone) {
        out[k].reset();
      } else {
        hitOn(best, ray, bestCandidate, linear.of(best, objects_[best]), out[k].emplace());
      }
    }
    if (leftCount == 0) continue;
    std::optional<Hit> found[kPacket];
    closestHits(left, fromEye, leftCount, found);
    for (int k = 0; k < leftCount; ++k) out[leftAt[k]] = found[k];
  }
}

// Inlined into the searches: it runs for every object a ray reaches.
[[gnu::always_inline]] inline std::optional<RenderScene::Candidate> RenderScene::intersectObject(
    std::uint32_t index, const Ray& ray, const RaySource& source, double tMax) const {
  const RenderObject& object = objects_[index];
  bool self = index == source.object;
  // A ray leaving a plane, or leaving a convex solid outward, cannot meet it.
  if (self && (object.kind == scene::ObjectKind::Plane || !source.inward)) return std::nullopt;
  glm::dvec3 o = object.toLocalPoint(ray.origin);
  glm::dvec3 d = object.toLocal * ray.direction;
  // Distances only: the normal is worked out once, for the winner.
  SpanDistances span = unitShapeDistances(object.kind, o, d);
  if (span.empty) return std::nullopt;
  // The nearest end of the span ahead of the origin; a ray that left this
  // solid inward meets it again only where it leaves.
  if (!self && span.enter > 0.0 && span.enter < tMax) {
    return Candidate{span.enter, false, span.enterFace};
  }
  if (object.kind != scene::ObjectKind::Plane && span.exit > 0.0 && span.exit < tMax) {
    return Candidate{span.exit, true, span.exitFace};
  }
  return std::nullopt;
}

[[gnu::always_inline]] inline std::optional<RenderScene::Candidate> RenderScene::intersectPlane(
    std::uint32_t index, const Ray& ray, const RaySource& source, double tMax) const {
  // A ray leaving a plane cannot meet it.
  if (index == source.object) return std::nullopt;
  const RenderObject& object = objects_[index];
  // The y components of toLocalPoint(origin) and toLocal * direction, added
  // up as glm's matrix product adds them (column by column, left to right).
  const glm::dmat3& m = object.toLocal;
  const glm::dvec3 p = ray.origin - object.translation;
  const glm::dvec3& d = ray.direction;
  double originY = m[0][1] * p.x + m[1][1] * p.y + m[2][1] * p.z;
  double directionY = m[0][1] * d.x + m[1][1] * d.y + m[2][1] * d.z;
  // unitShapeDistances for a plane: one distance, entering its +y face.
  if (directionY == 0.0) return std::nullopt;
  double t = -originY / directionY;
  if (t > 0.0 && t < tMax) return Candidate{t, false, static_cast<SpanFace>(3)};
  return std::nullopt;
}

[[gnu::always_inline]] inline void RenderScene::considerPlanes(const Ray& ray,
                                                               const RaySource& source,
                                                               std::uint32_t& best,
                                                               Candidate& bestCandidate) const {
  for (std::uint32_t plane : planes_) {
    if (auto c = intersectPlane(plane, ray, source, bestCandidate.t)) {
      best = plane;
      bestCandidate = *c;
    }
  }
}

void RenderScene::hitOn(std::uint32_t index, const Ray& ray, const Candidate& c, Hit& hit) const {
  hitOn(index, ray, c, objects_[index].toWorldLinear(), hit);
}

void RenderScene::hitOn(std::uint32_t index, const Ray& ray, const Candidate& c,
                        const glm::dmat3& m, Hit& hit) const {
  const RenderObject& object = objects_[index];
  glm::dvec3 o = object.toLocalPoint(ray.origin);
  glm::dvec3 d = object.toLocal * ray.direction;
  const bool plane = object.kind == scene::ObjectKind::Plane;
  SurfacePoint s = plane ? refineOntoPlane(o, d, c.t)
                         : refineOntoSurface(object.kind, o, d, c.t,
                                             spanFaceNormal(object.kind, c.face, o, d, c.t));

  // Step 1: to world space, with the error bound of an affine transform of
  // a point that already carries an error (pbrt-v4, Transform of Point3fi).
  hit.t = c.t;
  hit.object = index;
  // m * (point, 1) as glm's dmat4 product adds it up: the first two
  // columns' products, then the third's with the translation (times 1).
  const glm::dvec3& translation = object.translation;
  hit.point = (m[0] * s.point.x + m[1] * s.point.y) + (m[2] * s.point.z + translation);
  for (int r = 0; r < 3; ++r) {
    double magnitude = std::abs(translation[r]);
    double carried = 0.0;
    for (int k = 0; k < 3; ++k) {
      magnitude += std::abs(m[k][r] * s.point[k]);
      carried += std::abs(m[k][r]) * s.error[k];
    }
    hit.pointError[r] = gamma(3) * magnitude + (1.0 + gamma(3)) * carried;
  }
  // Step 2: the normal, through the inverse transpose; a plane's was made
  // by the same expression in the constructor (the planes are the first
  // objects, so plane `index` has the normal at `index`).
  if (plane) {
    hit.normal = planeNormals_[index];
  } else {
    hit.normal = glm::normalize(object.normalToWorld(s.normal));
  }
  hit.fromInside = c.atExit;
}

std::optional<Hit> RenderScene::closestHit(const Ray& ray, const RaySource& source,
                                           double tMax) const {
  std::uint32_t best = RaySource::kNone;
  Candidate bestCandidate{tMax, false, SpanFace::None};
  auto consider = [&](std::uint32_t index) {
    if (auto c = intersectObject(index, ray, source, bestCandidate.t)) {
      best = index;
      bestCandidate = *c;
    }
  };
  considerPlanes(ray, source, best, bestCandidate);
  BoxRay boxRay{ray.origin, 1.0 / ray.direction};
  bvh_.traverse(boxRay, bestCandidate.t, [&](std::uint32_t item) {
    consider(bounded_[item]);
    return bestCandidate.t;
  });
  if (best == RaySource::kNone) return std::nullopt;
  return hitOn(best, ray, bestCandidate);
}

void RenderScene::closestHits(const Ray* rays, const RaySource* sources, int count,
                              std::optional<Hit>* out, double tMax) const {
  constexpr int kPacket = Bvh::kPacketSize;
  LastHitLinear linear;
  for (int first = 0; first < count; first += kPacket) {
    int n = std::min(kPacket, count - first);
    const Ray* ray = rays + first;
    const RaySource* source = sources + first;
    std::uint32_t best[kPacket];
    Candidate bestCandidate[kPacket];
    BoxRay boxRays[kPacket];
    double tMaxes[kPacket];
    // Per ray, as closestHit: the planes first, then the hierarchy.
    auto consider = [&](int lane, std::uint32_t index) {
      if (auto c = intersectObject(index, ray[lane], source[lane], bestCandidate[lane].t)) {
        best[lane] = index;
        bestCandidate[lane] = *c;
      }
    };
    for (int lane = 0; lane < n; ++lane) {
      best[lane] = RaySource::kNone;
      bestCandidate[lane] = Candidate{tMax, false, SpanFace::None};
      considerPlanes(ray[lane], source[lane], best[lane], bestCandidate[lane]);
      boxRays[lane] = BoxRay{ray[lane].origin, 1.0 / ray[lane].direction};
      tMaxes[lane] = bestCandidate[lane].t;
    }
    bvh_.traversePacket(boxRays, n, tMaxes, [&](int lane, std::uint32_t item) {
      consider(lane, bounded_[item]);
      return bestCandidate[lane].t;
    });
    for (int lane = 0; lane < n; ++lane) {
      if (best[lane] == RaySource::kNone) {
        out[first + lane].reset();
      } else {
        hitOn(best[lane], ray[lane], bestCandidate[lane],
              linear.of(best[lane], objects_[best[lane]]), out[first + lane].emplace());
      }
    }
  }
}

void RenderScene::hitsOnObjects(const std::uint32_t* objects, const Ray* rays, const double* tMaxes,
                                int count, std::optional<Hit>* out) const {
  LastHitLinear linear;
  for (int k = 0; k < count; ++k) {
    std::uint32_t object = objects[k];
    std::optional<Candidate> c;
    if (object != RaySource::kNone) c = intersectObject(object, rays[k], RaySource{}, tMaxes[k]);
    if (!c) {
      out[k].reset();
    } else {
      hitOn(object, rays[k], *c, linear.of(object, objects_[object]), out[k].emplace());
    }
  }
}

std::optional<Hit> RenderScene::closestHitBruteForce(const Ray& ray, const RaySource& source,
                                                     double tMax) const {
  std::uint32_t best = RaySource::kNone;
  Candidate bestCandidate{tMax, false, SpanFace::None};
  for (std::uint32_t i = 0; i < objects_.size(); ++i) {
    if (auto c = intersectObject(i, ray, source, bestCandidate.t)) {
      best = i;
      bestCandidate = *c;
    }
  }
  if (best == RaySource::kNone) return std::nullopt;
  return hitOn(best, ray, bestCandidate);
}

bool RenderScene::blockedByPlane(const Ray& ray, const RaySource& source, double tMax,
                                 std::uint32_t* lastOccluder) const {
  for (std::uint32_t plane : planes_) {
    if (intersectPlane(plane, ray, source, tMax)) {
      if (lastOccluder) *lastOccluder = plane;
      return true;
    }
  }
  return false;
}

[[gnu::always_inline]] inline bool RenderScene::meetsItemBox(std::uint32_t item, const BoxRay& ray,
                                                             double tMax) const {
  return hitsBox(leafBox(item), ray, 0.0, tMax);
}

std::uint32_t RenderScene::shadowCell(std::size_t light, const glm::dvec3& point,
                                      const glm::dvec3& pointError) const {
  const DirectionGrid* grid = lightGrid(light);
  if (!grid) return DirectionGrid::kNoCell;
  glm::dvec3 fromLight = point - lights_[light].position;
  // The ray's origin lies off `point` by the error bound along the unit
  // normal (at most sqrt(3) times its largest component) and a rounding:
  // within `slack`, which must be a billionth of the distance or less, so
  // that the ray's direction is that of fromLight to well within the
  // grid's margin (docs/TRACING.md, "Direction grids").
  double largestError = std::max({pointError.x, pointError.y, pointError.z});
  double slack = 2.0 * largestError + 0x1p-51 * DirectionGrid::largestMagnitude(point);
  if (!(slack <= 1e-9 * DirectionGrid::largestMagnitude(fromLight))) return DirectionGrid::kNoCell;
  std::uint32_t cell = grid->cubeCellOf(fromLight);
  return cell != DirectionGrid::kNoCell && !grid->full(cell) ? cell : DirectionGrid::kNoCell;
}

bool RenderScene::anyHitTowardLight(std::size_t light, const Ray& ray, const RaySource& source,
                                    double tMax, std::uint32_t* lastOccluder,
                                    std::uint32_t cell) const {
  const DirectionGrid* grid = lightGrid(light);
  if (!grid) return anyHit(ray, source, tMax, lastOccluder);
  // The ray seen from the light: its direction is light - origin, so this
  // is origin - light, bit for bit.
  if (cell == DirectionGrid::kNoCell) cell = grid->cubeCellOf(-ray.direction);
  if (cell == DirectionGrid::kNoCell || grid->full(cell)) {
    return anyHit(ray, source, tMax, lastOccluder);
  }
  // The cell lists every bounded object that can block the ray, so the
  // hint, which saves a walk down the BVH, is not needed here.
  if (blockedByPlane(ray, source, tMax, lastOccluder)) return true;
  BoxRay boxRay{ray.origin, 1.0 / ray.direction};
  for (std::uint32_t item : grid->items(cell)) {
    if (meetsItemBox(item, boxRay, tMax) && intersectObject(bounded_[item], ray, source, tMax)) {
      if (lastOccluder) *lastOccluder = bounded_[item];
      return true;
    }
  }
  if (lastOccluder) *lastOccluder = RaySource::kNone;
  return false;
}

bool RenderScene::anyHit(const Ray& ray, const RaySource& source, double tMax,
                         std::uint32_t* lastOccluder) const {
  if (lastOccluder && *lastOccluder < objects_.size() &&
      intersectObject(*lastOccluder, ray, source, tMax)) {
    return true;
  }
  if (blockedByPlane(ray, source, tMax, lastOccluder)) return true;
  std::uint32_t found = RaySource::kNone;
  BoxRay boxRay{ray.origin, 1.0 / ray.direction};
  bvh_.traverse(boxRay, tMax, [&](std::uint32_t item) {
    if (intersectObject(bounded_[item], ray, source, tMax)) {
      found = bounded_[item];
      return -1.0;
    }
    return tMax;
  });
  if (lastOccluder) *lastOccluder = found;
  return found != RaySource::kNone;
}

void RenderScene::anyHits(const Ray* rays, const RaySource* sources, const double* tMaxes,
                          int count, bool* blocked, std::uint32_t* lastOccluder) const {
  constexpr int kPacket = Bvh::kPacketSize;
  for (int first = 0; first < count; first += kPacket) {
    int n = std::min(kPacket, count - first);
    // Each ray's occluder, and the rays neither the hint nor a plane
    // blocks, for the walk.
    std::uint32_t occluder[kPacket];
    BoxRay boxRays[kPacket];
    double tMax[kPacket];
    int at[kPacket];
    int open = 0;
    for (int lane = 0; lane < n; ++lane) {
      int k = first + lane;
      occluder[lane] = *lastOccluder;
      blocked[k] = (*lastOccluder < objects_.size() &&
                    intersectObject(*lastOccluder, rays[k], sources[k], tMaxes[k])) ||
                   blockedByPlane(rays[k], sources[k], tMaxes[k], &occluder[lane]);
      if (blocked[k]) continue;
      occluder[lane] = RaySource::kNone;
      boxRays[open] = BoxRay{rays[k].origin, 1.0 / rays[k].direction};
      tMax[open] = tMaxes[k];
      at[open++] = lane;
    }
    if (open > 0) {
      bvh_.traversePacket(boxRays, open, tMax, [&](int lane, std::uint32_t item) {
        int k = first + at[lane];
        if (intersectObject(bounded_[item], rays[k], sources[k], tMaxes[k])) {
          blocked[k] = true;
          occluder[at[lane]] = bounded_[item];
          return -1.0;
        }
        return tMaxes[k];
      });
    }
    // As anyHit leaves it after the packet's last ray.
    *lastOccluder = occluder[n - 1];
  }
}

std::vector<std::uint32_t> RenderScene::mediaContaining(const glm::dvec3& p) const {
  std::vector<std::uint32_t> media;
  for (std::uint32_t i = 0; i < objects_.size(); ++i) {
    const RenderObject& object = objects_[i];
    if (object.kind == scene::ObjectKind::Plane || materials_[object.material].transparency <= 0.0)
      continue;
    glm::dvec3 local = object.toLocalPoint(p);
    bool inside = false;
    switch (object.kind) {
      case scene::ObjectKind::Sphere:
        inside = glm::dot(local, local) < 1.0;
        break;
      case scene::ObjectKind::Cube:
        inside = std::abs(local.x) < 1.0 && std::abs(local.y) < 1.0 && std::abs(local.z) < 1.0;
        break;
      case scene::ObjectKind::Cylinder:
        inside = local.x * local.x + local.z * local.z < 1.0 && std::abs(local.y) < 1.0;
        break;
      case scene::ObjectKind::Plane:
        break;
    }
    if (inside) media.push_back(i);
  }
  // Larger solids first: the smallest is the innermost; of equal ones, the
  // first in the scene first, whatever the BVH's order.
  std::sort(media.begin(), media.end(), [this](std::uint32_t a, std::uint32_t b) {
    double volumeA = std::abs(glm::determinant(linearToWorld(a)));
    double volumeB = std::abs(glm::determinant(linearToWorld(b)));
    if (volumeA != volumeB) return volumeA > volumeB;
    return sceneObjects_[a] < sceneObjects_[b];
  });
  return media;
}

}  // namespace render
