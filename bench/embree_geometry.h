// Embree 3's user geometry for the renderer's objects (bench/embree_trace):
// each bounded object a primitive, its box the object's world bounds widened
// for Embree's float rays, and callbacks that run the renderer's exact
// double-precision test of the object on the double ray.
#pragma once

#include <embree3/rtcore.h>

#include <cstdint>
#include <glm/glm.hpp>
#include <limits>
#include <vector>

#include "renderer/float_error.h"
#include "renderer/render_scene.h"
#include "renderer/unit_shapes.h"

namespace bench {

// The renderer's test of one object by a camera ray (RenderScene's
// intersectObject for a ray that leaves no surface): the nearest end of the
// object's span ahead of the origin and nearer than tMax, or a negative
// value for none.
inline double objectDistance(const render::RenderObject& object, const render::Ray& ray,
                             double tMax) {
  glm::dvec3 o = object.toLocalPoint(ray.origin);
  glm::dvec3 d = object.toLocal * ray.direction;
  render::SpanDistances span = render::unitShapeDistances(object.kind, o, d);
  if (span.empty) return -1.0;
  if (span.enter > 0.0 && span.enter < tMax) return span.enter;
  if (object.kind != scene::ObjectKind::Plane && span.exit > 0.0 && span.exit < tMax) {
    return span.exit;
  }
  return -1.0;
}

// The renderer's test of object `index` by a ray leaving `source`
// (RenderScene's intersectObject): whether it meets the object at
// 0 < t < tMax.
inline bool blocks(const render::RenderObject& object, std::uint32_t index, const render::Ray& ray,
                   const render::RaySource& source, double tMax) {
  bool self = index == source.object;
  bool plane = object.kind == scene::ObjectKind::Plane;
  if (self && (plane || !source.inward)) return false;
  glm::dvec3 o = object.toLocalPoint(ray.origin);
  glm::dvec3 d = object.toLocal * ray.direction;
  render::SpanDistances span = render::unitShapeDistances(object.kind, o, d);
  if (span.empty) return false;
  if (!self && span.enter > 0.0 && span.enter < tMax) return true;
  return !plane && span.exit > 0.0 && span.exit < tMax;
}

// What the callbacks share: the objects, and Embree primitive -> object.
struct Geometry {
  const render::UnsetVector<render::RenderObject>* objects = nullptr;
  std::vector<std::uint32_t> bounded;
  std::vector<render::Bounds> bounds;
};

// Embree's context, extended with the double rays of the current call
// (one, or a packet's) and the exact distance of each one's nearest hit so
// far: Embree's float tfar only prunes its traversal.
struct TraceContext {
  RTCIntersectContext embree;
  const render::Ray* rays = nullptr;
  double* nearest = nullptr;
  // Shadow rays: what each leaves (nearest then holds each one's tMax).
  const render::RaySource* sources = nullptr;
};

inline void boundsOf(const RTCBoundsFunctionArguments* args) {
  const auto* g = static_cast<const Geometry*>(args->geometryUserPtr);
  const render::Bounds& b = g->bounds[args->primID];
  // Widened by 4 float steps of the box's size: a float ray, rounded from
  // the double one, must not miss a box the double ray meets.
  glm::dvec3 pad =
      (glm::abs(b.lo) + glm::abs(b.hi)) * (4.0 * std::numeric_limits<float>::epsilon());
  RTCBounds* out = args->bounds_o;
  out->lower_x = render::floatAtOrBelow(b.lo.x - pad.x);
  out->lower_y = render::floatAtOrBelow(b.lo.y - pad.y);
  out->lower_z = render::floatAtOrBelow(b.lo.z - pad.z);
  out->upper_x = render::floatAtOrAbove(b.hi.x + pad.x);
  out->upper_y = render::floatAtOrAbove(b.hi.y + pad.y);
  out->upper_z = render::floatAtOrAbove(b.hi.z + pad.z);
}

inline void intersect(const RTCIntersectFunctionNArguments* args) {
  const auto* g = static_cast<const Geometry*>(args->geometryUserPtr);
  auto* context = reinterpret_cast<TraceContext*>(args->context);
  std::uint32_t object = g->bounded[args->primID];
  RTCRayN* rays = RTCRayHitN_RayN(args->rayhit, args->N);
  RTCHitN* hits = RTCRayHitN_HitN(args->rayhit, args->N);
  for (unsigned lane = 0; lane < args->N; ++lane) {
    if (args->valid[lane] != -1) continue;
    unsigned id = RTCRayN_id(rays, args->N, lane);
    double& nearest = context->nearest[id];
    double t = objectDistance((*g->objects)[object], context->rays[id], nearest);
    if (t < 0.0) continue;
    nearest = t;
    RTCRayN_tfar(rays, args->N, lane) = render::floatAtOrAbove(t);
    RTCHitN_primID(hits, args->N, lane) = args->primID;
    RTCHitN_geomID(hits, args->N, lane) = args->geomID;
    RTCHitN_instID(hits, args->N, lane, 0) = RTC_INVALID_GEOMETRY_ID;
  }
}

inline void occluded(const RTCOccludedFunctionNArguments* args) {
  const auto* g = static_cast<const Geometry*>(args->geometryUserPtr);
  auto* context = reinterpret_cast<TraceContext*>(args->context);
  std::uint32_t object = g->bounded[args->primID];
  for (unsigned lane = 0; lane < args->N; ++lane) {
    if (args->valid[lane] != -1) continue;
    unsigned id = RTCRayN_id(args->ray, args->N, lane);
    if (blocks((*g->objects)[object], object, context->rays[id], context->sources[id],
               context->nearest[id])) {
      RTCRayN_tfar(args->ray, args->N, lane) = -std::numeric_limits<float>::infinity();
    }
  }
}

struct EmbreeScene {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  ~EmbreeScene() {
    if (scene) rtcReleaseScene(scene);
    if (device) rtcReleaseDevice(device);
  }
};

}  // namespace bench
