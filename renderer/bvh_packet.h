// Bvh::traversePacket: up to Bvh::kPacketSize coherent rays (a row of a
// tile's camera rays) walked down the hierarchy together, each box tested
// for all of them at once in SIMD lanes (SSE2, or AVX2 where the processor
// has it: the same operations on each lane, so the same bits), with every
// ray visiting exactly the leaves, in exactly the order, that Bvh::traverse
// visits for it alone.
//
// Why the hits are the same, bit for bit (docs/TRACING.md, "Packets"): a
// ray's closest hit is the first item, in its own visiting order, that
// reaches the least t under the strict t < tMax test, so a ray that visits
// the same items in the same order with the same tMax before each ends with
// the same Hit. The packet walk keeps, per node, the set (a bit mask) of rays
// whose own walk reaches that node, and replays Bvh::traverse per ray:
//  - the near child is chosen by the split axis' direction sign, which is
//    the same for every ray of the packet (a packet whose rays differ in a
//    sign on any axis is traced ray by ray with Bvh::traverse instead);
//  - each ray's box test is hitsNode's arithmetic on its own lane (the float
//    planes converted to double, the far distance widened, NaN ignored,
//    against the ray's own current tMax), so each ray meets exactly the
//    boxes it meets alone;
//  - a ray that meets the near child goes down it; one that meets only the
//    far child waits with the far child on the stack while the others take
//    the near subtree, where it visits nothing and its tMax does not change,
//    so its pop test (entry distance <= tMax) passes as the direct descent
//    did; one that meets both pushes the far child with its entry distance,
//    as Bvh::traverse does, and is dropped at the pop under the same test
//    with the same tMax;
//  - at a leaf, each ray in the mask runs the caller's exact object test on
//    the leaf's items in order (rays between them in any order: one ray's
//    tests do not change another's tMax).
// By induction over the depth-first walk, each ray's sequence of leaf
// visits, and its tMax before each, is the single-ray one.
#pragma once

#include <cstdint>
#include <limits>
#include <utility>

#include "renderer/bvh.h"

#if defined(__SSE2__) && (defined(__x86_64__) || defined(__i386__)) && defined(__GNUC__)
#include <emmintrin.h>
#define SCENEFILE_PACKET_AVX2 1
#endif

namespace render {

namespace detail {

// The packet's rays as the lanes of the box test want them, and the plane
// indices that their shared direction signs pick (Bvh::NodeRay per ray).
struct PacketNodeRays {
  static constexpr int kLanes = Bvh::kPacketSize;
  static_assert(kLanes == 4, "the wide box test holds the lanes in one vector");
#if defined(SCENEFILE_PACKET_AVX2)
  using Doubles4 = double __attribute__((vector_size(32)));
  using Longs4 = long long __attribute__((vector_size(32)));
#endif

  // Fills lanes past `count` with the first ray's values; their tMax of
  // -infinity keeps them out of every box.
  PacketNodeRays(const BoxRay* rays, int count) {
    for (int i = 0; i < 3; ++i) {
      negative[i] = rays[0].inverseDirection[i] < 0.0;
      nearPlane[i] = negative[i] ? 3 + i : i;
      farPlane[i] = negative[i] ? i : 3 + i;
      for (int lane = 0; lane < kLanes; ++lane) {
        const BoxRay& ray = rays[lane < count ? lane : 0];
        origin[i][lane] = ray.origin[i];
        inverseDirection[i][lane] = ray.inverseDirection[i];
      }
    }
  }

  // Whether every ray's direction has the same sign as the first ray's on
  // each axis (the test Bvh::NodeRay makes), so that one near child suits
  // them all.
  static bool sameSigns(const BoxRay* rays, int count) {
    for (int i = 0; i < 3; ++i) {
      bool first = rays[0].inverseDirection[i] < 0.0;
      for (int lane = 1; lane < count; ++lane) {
        if ((rays[lane].inverseDirection[i] < 0.0) != first) return false;
      }
    }
    return true;
  }

  // hitsNode on every lane for the box `node`: bit `lane` set where that
  // ray meets it within tMax[lane], its entry distance in tEntry[lane],
  // with hitsNode's operations in its order on each lane: the float planes
  // convert to double exactly, `x > m ? x : m` and `x < m ? x : m` (SSE2's
  // max and min) leave m as it was for a NaN distance, as in hitsNode, and
  // nothing is fused (neither target has FMA), so every version gives the
  // same bits. kWide: four lanes a vector in GCC's vector extensions, for
  // the walk built for AVX2, where each is one instruction (at x86-64's
  // baseline they cost a fifth more than the SSE2 code below).
  template <bool kWide>
  int hits(const BvhNode& node, const double* tMax, double* tEntry) const {
    const double widen = 1.0 + 2.0 * gamma(3);
    int mask = 0;
#if defined(SCENEFILE_PACKET_AVX2)
    if constexpr (kWide) {
      Doubles4 tMin = {0.0, 0.0, 0.0, 0.0};
      Doubles4 tFarthest;
      __builtin_memcpy(&tFarthest, tMax, sizeof tFarthest);
      for (int i = 0; i < 3; ++i) {
        double nearOne = node.planes[nearPlane[i]];
        double farOne = node.planes[farPlane[i]];
        const Doubles4& o = *reinterpret_cast<const Doubles4*>(&origin[i][0]);
        const Doubles4& inverse = *reinterpret_cast<const Doubles4*>(&inverseDirection[i][0]);
        Doubles4 tNear = (nearOne - o) * inverse;
        Doubles4 tFar = (farOne - o) * inverse;
        tFar *= widen;
        tMin = tNear > tMin ? tNear : tMin;
        tFarthest = tFar < tFarthest ? tFar : tFarthest;
      }
      __builtin_memcpy(tEntry, &tMin, sizeof tMin);
      // Each lane's compare is all ones or all zeros: its bit, or'd up.
      Longs4 bits = (tMin <= tFarthest) & Longs4{1, 2, 4, 8};
      return static_cast<int>((bits[0] | bits[1]) | (bits[2] | bits[3]));
    }
#endif
#if defined(__SSE2__)
    for (int first = 0; first < kLanes; first += 2) {
      __m128d tMin = _mm_setzero_pd();
      __m128d tFarthest = _mm_loadu_pd(tMax + first);
      for (int i = 0; i < 3; ++i) {
        __m128d nearBoth = _mm_set1_pd(static_cast<double>(node.planes[nearPlane[i]]));
        __m128d farBoth = _mm_set1_pd(static_cast<double>(node.planes[farPlane[i]]));
        __m128d o = _mm_load_pd(&origin[i][first]);
        __m128d inverse = _mm_load_pd(&inverseDirection[i][first]);
        __m128d tNear = _mm_mul_pd(_mm_sub_pd(nearBoth, o), inverse);
        __m128d tFar = _mm_mul_pd(_mm_mul_pd(_mm_sub_pd(farBoth, o), inverse), _mm_set1_pd(widen));
        tMin = _mm_max_pd(tNear, tMin);
        tFarthest = _mm_min_pd(tFar, tFarthest);
      }
      _mm_storeu_pd(tEntry + first, tMin);
      mask |= _mm_movemask_pd(_mm_cmple_pd(tMin, tFarthest)) << first;
    }
#else
    for (int lane = 0; lane < kLanes; ++lane) {
      double tMin = 0.0;
      double tFarthest = tMax[lane];
      for (int i = 0; i < 3; ++i) {
        double nearOne = node.planes[nearPlane[i]];
        double farOne = node.planes[farPlane[i]];
        double tNear = (nearOne - origin[i][lane]) * inverseDirection[i][lane];
        double tFar = (farOne - origin[i][lane]) * inverseDirection[i][lane];
        tFar *= widen;
        tMin = tNear > tMin ? tNear : tMin;
        tFarthest = tFar < tFarthest ? tFar : tFarthest;
      }
      tEntry[lane] = tMin;
      if (tMin <= tFarthest) mask |= 1 << lane;
    }
#endif
    return mask;
  }

  // The lanes of `mask` whose entry distance lies within their tMax.
  static int within(int mask, const double* tEntry, const double* tMax) {
    int kept = 0;
    for (int lane = 0; lane < kLanes; ++lane) {
      if (tEntry[lane] <= tMax[lane]) kept |= 1 << lane;
    }
    return mask & kept;
  }

  alignas(64) double origin[3][kLanes];
  alignas(64) double inverseDirection[3][kLanes];
  bool negative[3];
  int nearPlane[3];
  int farPlane[3];
};

// Whether this processor runs AVX2 code, asked once.
inline bool hasAvx2() {
#if defined(SCENEFILE_PACKET_AVX2)
  static const bool avx2 = __builtin_cpu_supports("avx2");
  return avx2;
#else
  return false;
#endif
}

}  // namespace detail

// The walk itself, inlined into traversePacket's two versions; kWide picks
// the box test.
template <bool kWide, typename Visit>
[[gnu::always_inline]] inline void Bvh::walkPacket(const BoxRay* rays, int count,
                                                   const double* tMax, Visit& visit) const {
  detail::PacketNodeRays r(rays, count);
  constexpr double kOut = -std::numeric_limits<double>::infinity();
  // Each ray's current tMax; -infinity for a lane without a ray, or whose
  // ray has stopped (visit returned a negative value), which then meets no
  // box.
  alignas(64) double tMaxes[kPacketSize];
  for (int lane = 0; lane < kPacketSize; ++lane) tMaxes[lane] = lane < count ? tMax[lane] : kOut;
  struct Pending {
    alignas(64) double tEntry[kPacketSize];
    std::uint32_t node;
    int mask;
  };
  // One more than the deepest walk pushes: the far child's entries are
  // written in place, at the top, before it is known to be pushed.
  Pending stack[kStackSize + 1];
  int top = 0;
  alignas(64) double tEntries[kPacketSize];
  const BvhNode* nodes = nodes_.span().data();
  int mask = r.template hits<kWide>(nodes[0], tMaxes, tEntries);
  int stopped = 0;
  std::uint32_t current = 0;
  while (mask != 0) {
    const BvhNode& node = nodes[current];
    if (node.count > 0) {
      for (std::uint32_t i = 0; i < node.count && mask != 0; ++i) {
        std::uint32_t item = node.offset + i;
        for (int lanes = mask; lanes != 0; lanes &= lanes - 1) {
          int lane = __builtin_ctz(static_cast<unsigned>(lanes));
          double t = visit(lane, item);
          if (t < 0.0) {
            stopped |= 1 << lane;
            mask &= ~(1 << lane);
            tMaxes[lane] = kOut;
          } else {
            tMaxes[lane] = t;
          }
        }
      }
    } else {
      std::uint32_t nearChild = current + 1;
      std::uint32_t farChild = node.offset;
      if (r.negative[node.axis]) std::swap(nearChild, farChild);
      alignas(64) double nearEntries[kPacketSize];
      Pending& far = stack[top];
      int hitNear = r.template hits<kWide>(nodes[nearChild], tMaxes, nearEntries) & mask;
      int hitFar = r.template hits<kWide>(nodes[farChild], tMaxes, far.tEntry) & mask;
      if (hitNear != 0) {
        if (hitFar != 0) {
          far.node = farChild;
          far.mask = hitFar;
          ++top;
        }
        current = nearChild;
        mask = hitNear;
        continue;
      }
      if (hitFar != 0) {
        current = farChild;
        mask = hitFar;
        continue;
      }
    }
    mask = 0;
    while (mask == 0 && top > 0) {
      const Pending& next = stack[--top];
      mask = detail::PacketNodeRays::within(next.mask & ~stopped, next.tEntry, tMaxes);
      current = next.node;
    }
  }
}

#if defined(SCENEFILE_PACKET_AVX2)
// The walk built for AVX2: the same code, inlined here, where its vector
// operations take four lanes at once.
template <typename Visit>
[[gnu::target("avx2")]] void Bvh::walkPacketAvx2(const BoxRay* rays, int count, const double* tMax,
                                                 Visit& visit) const {
  walkPacket<true>(rays, count, tMax, visit);
}
#endif

template <typename Visit>
void Bvh::traversePacket(const BoxRay* rays, int count, const double* tMax, Visit&& visit) const {
  if (empty() || count <= 0) return;
  if (count > kPacketSize) count = kPacketSize;
  if (count == 1 || !detail::PacketNodeRays::sameSigns(rays, count)) {
    for (int lane = 0; lane < count; ++lane) {
      traverse(rays[lane], tMax[lane], [&](std::uint32_t item) { return visit(lane, item); });
    }
    return;
  }
#if defined(SCENEFILE_PACKET_AVX2)
  if (detail::hasAvx2()) {
    walkPacketAvx2(rays, count, tMax, visit);
    return;
  }
#endif
  walkPacket<false>(rays, count, tMax, visit);
}

}  // namespace render
