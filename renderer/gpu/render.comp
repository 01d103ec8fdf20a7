// sfrender's renderer on the GPU: one thread a pixel, every sample of it in
// turn, in double precision with the formulas of the CPU path
// (renderer/unit_shapes, render_scene, tracer, render.cpp), operation for
// operation and in the same order, so that the numbers are the same where
// the device rounds as the CPU does. `precise` keeps the compiler from
// fusing a product and a sum into one rounding (an FMA), which the CPU build
// never does. Reflection and refraction are traced to the depth limit with
// an explicit stack instead of recursion (docs/RENDERING.md, "The GPU path").
#version 450
#extension GL_ARB_gpu_shader_int64 : require

layout(local_size_x = 8, local_size_y = 8) in;

// What the host fills in (renderer/gpu/gpu_scene.h, GpuParams): the same
// layout, field for field.
layout(std430, binding = 0) readonly buffer Params {
  dvec4 eye;
  dvec4 forward;
  dvec4 up;
  dvec4 right;
  double tanHalfWidth;
  double tanHalfHeight;
  double imageWidth;
  double imageHeight;
  uint64_t seed;
  int regionX0;
  int regionY0;
  int regionWidth;
  int regionHeight;
  int rowBase;  // the first row of the region this dispatch draws
  int samplesPerPixel;
  int maxDepth;
  int planeCount;
  int lightCount;
  int nodeCount;
  int hasTransparency;
  int eyeMediaCount;
  int idsOnly;  // 1: only each pixel's centre ray's object (renderObjectIds)
  int pad0;
  uint eyeMedia[8];
};
// 32 doubles an object (kObjectDoubles): toLocal (column-major), the
// translation, the 3x3 block of the matrix (column-major), the kind, then
// the material.
layout(std430, binding = 1) readonly buffer Objects { double objects[]; };
// BvhNode as the CPU keeps it, 8 words a node: six float planes, the offset,
// then count (low 16 bits) and axis (next 8).
layout(std430, binding = 2) readonly buffer Nodes { uint nodes[]; };
layout(std430, binding = 3) readonly buffer Planes { uint planes[]; };
// 6 doubles a light: position, colour.
layout(std430, binding = 4) readonly buffer Lights { double lights[]; };
// Per pixel of the region: red, green, blue, coverage.
layout(std430, binding = 5) writeonly buffer Colours { vec4 colours[]; };
// Per pixel: reflected and refracted rays, shadow rays, branches dropped on
// a full stack, and the object the last camera ray met.
layout(std430, binding = 6) writeonly buffer Counts { uvec4 counts[]; };

const int kObjectDoubles = 32;
const int kMaterial = 22;
const uint kNone = 0xFFFFFFFFu;
const int kPlane = 0, kSphere = 1, kCylinder = 2, kCube = 3;  // gpu_scene.cpp, shaderKind
const int kFaceNone = -2, kFaceCurved = -1;
const int kBvhStack = 128;   // Bvh::kStackSize
const int kMediaCapacity = 8;
const int kPendingCapacity = 16;

const double kEpsilon = 1.1102230246251565404236316680908203125e-16LF;  // 2^-53

double gamma(int n) {
  precise double r = (double(n) * kEpsilon) / (1.0LF - double(n) * kEpsilon);
  return r;
}

double infinity() { return packDouble2x32(uvec2(0u, 0x7FF00000u)); }
bool signBit(double v) { return (unpackDouble2x32(v).y & 0x80000000u) != 0u; }
double copySign(double x, double s) { return signBit(s) ? -abs(x) : abs(x); }
// nextUp and nextDown of float_error.h, by stepping the bits.
double nextUp(double v) {
  if (v != v || v == infinity()) return v;
  if (v == 0.0LF) return packDouble2x32(uvec2(1u, 0u));
  uint64_t bits = doubleBitsToUint64(v);
  bits = v > 0.0LF ? bits + 1UL : bits - 1UL;
  return uint64BitsToDouble(bits);
}
double nextDown(double v) {
  if (v != v || v == -infinity()) return v;
  if (v == 0.0LF) return -packDouble2x32(uvec2(1u, 0u));
  uint64_t bits = doubleBitsToUint64(v);
  bits = v < 0.0LF ? bits + 1UL : bits - 1UL;
  return uint64BitsToDouble(bits);
}

// glm's dot, length and normalize, summed in glm's order.
double dot3(dvec3 a, dvec3 b) {
  precise double r = a.x * b.x + a.y * b.y + a.z * b.z;
  return r;
}
double dot2(dvec2 a, dvec2 b) {
  precise double r = a.x * b.x + a.y * b.y;
  return r;
}
dvec3 normalise(dvec3 v) {
  precise double inverse = 1.0LF / sqrt(dot3(v, v));
  precise dvec3 r = v * inverse;
  return r;
}
// glm::reflect: i - n * dot(n, i) * 2.
dvec3 reflectAbout(dvec3 i, dvec3 n) {
  precise dvec3 r = i - n * dot3(n, i) * 2.0LF;
  return r;
}

double objectValue(uint o, int k) { return objects[o * kObjectDoubles + k]; }
dvec3 objectVector(uint o, int k) {
  uint b = o * kObjectDoubles + k;
  return dvec3(objects[b], objects[b + 1], objects[b + 2]);
}
int objectKind(uint o) { return int(objectValue(o, 21)); }
// glm's dmat3 * dvec3 for toLocal (column-major at 0).
dvec3 toLocalVector(uint o, dvec3 v) {
  uint b = o * kObjectDoubles;
  precise double x = objects[b + 0] * v.x + objects[b + 3] * v.y + objects[b + 6] * v.z;
  precise double y = objects[b + 1] * v.x + objects[b + 4] * v.y + objects[b + 7] * v.z;
  precise double z = objects[b + 2] * v.x + objects[b + 5] * v.y + objects[b + 8] * v.z;
  return dvec3(x, y, z);
}
dvec3 toLocalPoint(uint o, dvec3 p) {
  precise dvec3 q = p - objectVector(o, 9);
  return toLocalVector(o, q);
}
// RenderObject::normalToWorld: n * toLocal.
dvec3 normalToWorld(uint o, dvec3 n) {
  uint b = o * kObjectDoubles;
  precise double x = objects[b + 0] * n.x + objects[b + 1] * n.y + objects[b + 2] * n.z;
  precise double y = objects[b + 3] * n.x + objects[b + 4] * n.y + objects[b + 5] * n.z;
  precise double z = objects[b + 6] * n.x + objects[b + 7] * n.y + objects[b + 8] * n.z;
  return dvec3(x, y, z);
}

// ---- unit shapes (renderer/unit_shapes.h) ----

struct Span {
  double enter;
  double exit;
  int enterFace;
  int exitFace;
  bool empty;
};

void clipToSlab(inout Span span, double o, double d, int axis) {
  if (d == 0.0LF) {
    if (o < -1.0LF || o > 1.0LF) span.empty = true;
    return;
  }
  precise double tLow = (-1.0LF - o) / d;
  precise double tHigh = (1.0LF - o) / d;
  int lowFace = 2 * axis;
  int highFace = 2 * axis + 1;
  if (d < 0.0LF) {
    double t = tLow;
    tLow = tHigh;
    tHigh = t;
    int f = lowFace;
    lowFace = highFace;
    highFace = f;
  }
  if (tLow > span.enter) {
    span.enter = tLow;
    span.enterFace = lowFace;
  }
  if (tHigh < span.exit) {
    span.exit = tHigh;
    span.exitFace = highFace;
  }
}

bool rootsFrom(double a, double b, double ff, double oo, out double t0, out double t1) {
  precise double discriminant = a * (1.0LF - ff);
  if (!(discriminant >= 0.0LF)) return false;
  precise double q = -(b + copySign(sqrt(discriminant), b));
  if (q == 0.0LF) {
    t0 = 0.0LF;
    t1 = 0.0LF;
    return true;
  }
  precise double c = oo - 1.0LF;
  precise double r0 = q / a;
  precise double r1 = c / q;
  if (r0 > r1) {
    t0 = r1;
    t1 = r0;
  } else {
    t0 = r0;
    t1 = r1;
  }
  return true;
}

bool quadricRoots3(dvec3 o, dvec3 d, out double t0, out double t1) {
  t0 = 0.0LF;
  t1 = 0.0LF;
  double a = dot3(d, d);
  if (a == 0.0LF) return false;
  double b = dot3(o, d);
  precise dvec3 f = o - (b / a) * d;
  return rootsFrom(a, b, dot3(f, f), dot3(o, o), t0, t1);
}

bool quadricRoots2(dvec2 o, dvec2 d, out double t0, out double t1) {
  t0 = 0.0LF;
  t1 = 0.0LF;
  double a = dot2(d, d);
  if (a == 0.0LF) return false;
  double b = dot2(o, d);
  precise dvec2 f = o - (b / a) * d;
  return rootsFrom(a, b, dot2(f, f), dot2(o, o), t0, t1);
}

Span unitShapeDistances(int kind, dvec3 o, dvec3 d) {
  Span span = Span(-infinity(), infinity(), kFaceNone, kFaceNone, false);
  if (kind == kPlane) {
    if (d.y == 0.0LF) {
      span.empty = true;
      return span;
    }
    precise double t = -o.y / d.y;
    span.enter = t;
    span.exit = t;
    span.enterFace = 3;
    span.exitFace = 3;
    return span;
  }
  if (kind == kCube) {
    for (int axis = 0; axis < 3 && !span.empty; ++axis) clipToSlab(span, o[axis], d[axis], axis);
  } else if (kind == kSphere) {
    double t0, t1;
    if (!quadricRoots3(o, d, t0, t1)) span.empty = true;
    span.enter = t0;
    span.exit = t1;
    span.enterFace = kFaceCurved;
    span.exitFace = kFaceCurved;
    return span;
  } else {
    dvec2 o2 = dvec2(o.x, o.z);
    dvec2 d2 = dvec2(d.x, d.z);
    if (d2.x == 0.0LF && d2.y == 0.0LF) {
      if (dot2(o2, o2) > 1.0LF) span.empty = true;
    } else {
      double t0, t1;
      if (!quadricRoots2(o2, d2, t0, t1)) {
        span.empty = true;
        return span;
      }
      span.enter = t0;
      span.exit = t1;
      span.enterFace = kFaceCurved;
      span.exitFace = kFaceCurved;
    }
    if (!span.empty) clipToSlab(span, o.y, d.y, 1);
  }
  if (!span.empty && !(span.enter <= span.exit)) span.empty = true;
  return span;
}

dvec3 spanFaceNormal(int kind, int face, dvec3 o, dvec3 d, double t) {
  if (face == kFaceNone) return dvec3(0.0LF);
  if (face == kFaceCurved) {
    if (kind == kSphere) {
      precise dvec3 n = o + t * d;
      return n;
    }
    precise dvec2 n = dvec2(o.x, o.z) + t * dvec2(d.x, d.z);
    return dvec3(n.x, 0.0LF, n.y);
  }
  dvec3 n = dvec3(0.0LF);
  n[face / 2] = face % 2 == 1 ? 1.0LF : -1.0LF;
  return n;
}

struct SurfacePoint {
  dvec3 point;
  dvec3 normal;
  dvec3 error;
};

SurfacePoint refineOntoSurface(int kind, dvec3 o, dvec3 d, double t, dvec3 normal) {
  SurfacePoint s;
  precise dvec3 p = o + t * d;
  precise dvec3 rawError = gamma(3) * (abs(o) + abs(t * d));
  if (kind == kPlane) {
    p.y = 0.0LF;
    s.normal = dvec3(0.0LF, 1.0LF, 0.0LF);
    s.error = dvec3(rawError.x, 0.0LF, rawError.z);
  } else if (kind == kCube) {
    int axis = normal.x != 0.0LF ? 0 : (normal.y != 0.0LF ? 1 : 2);
    p = clamp(p, dvec3(-1.0LF), dvec3(1.0LF));
    p[axis] = normal[axis] > 0.0LF ? 1.0LF : -1.0LF;
    s.normal = dvec3(0.0LF);
    s.normal[axis] = p[axis];
    s.error = rawError;
    s.error[axis] = 0.0LF;
  } else if (kind == kSphere) {
    precise double len = sqrt(dot3(p, p));
    if (len > 0.0LF) p = p / len;
    s.normal = p;
    s.error = gamma(5) * abs(p);
  } else if (normal.y != 0.0LF) {
    p.y = normal.y > 0.0LF ? 1.0LF : -1.0LF;
    s.normal = dvec3(0.0LF, p.y, 0.0LF);
    s.error = dvec3(rawError.x, 0.0LF, rawError.z);
  } else {
    // std::hypot: the same to within an ulp for these points near radius 1.
    precise double radius = sqrt(p.x * p.x + p.z * p.z);
    if (radius > 0.0LF) {
      p.x = p.x / radius;
      p.z = p.z / radius;
    }
    p.y = clamp(p.y, -1.0LF, 1.0LF);
    s.normal = dvec3(p.x, 0.0LF, p.z);
    s.error = dvec3(gamma(5) * abs(p.x), rawError.y, gamma(5) * abs(p.z));
  }
  s.point = p;
  return s;
}

// ---- the scene's queries (renderer/render_scene.cpp) ----

struct Candidate {
  double t;
  bool atExit;
  int face;
};

struct Hit {
  double t;
  uint object;
  dvec3 point;
  dvec3 pointError;
  dvec3 normal;
  bool fromInside;
};

// RenderScene::intersectObject: whether `index` gives a candidate nearer
// than tMax.
bool intersectObject(uint index, dvec3 origin, dvec3 direction, uint source, bool inward,
                     double tMax, out Candidate c) {
  c = Candidate(0.0LF, false, kFaceNone);
  int kind = objectKind(index);
  bool self = index == source;
  if (self && (kind == kPlane || !inward)) return false;
  dvec3 o = toLocalPoint(index, origin);
  dvec3 d = toLocalVector(index, direction);
  Span span = unitShapeDistances(kind, o, d);
  if (span.empty) return false;
  if (!self && span.enter > 0.0LF && span.enter < tMax) {
    c = Candidate(span.enter, false, span.enterFace);
    return true;
  }
  if (kind != kPlane && span.exit > 0.0LF && span.exit < tMax) {
    c = Candidate(span.exit, true, span.exitFace);
    return true;
  }
  return false;
}

Hit hitOn(uint index, dvec3 origin, dvec3 direction, Candidate c) {
  int kind = objectKind(index);
  dvec3 o = toLocalPoint(index, origin);
  dvec3 d = toLocalVector(index, direction);
  dvec3 localNormal = spanFaceNormal(kind, c.face, o, d, c.t);
  SurfacePoint s = refineOntoSurface(kind, o, d, c.t, localNormal);
  Hit hit;
  hit.t = c.t;
  hit.object = index;
  dvec3 m0 = objectVector(index, 12);
  dvec3 m1 = objectVector(index, 15);
  dvec3 m2 = objectVector(index, 18);
  dvec3 translation = objectVector(index, 9);
  precise dvec3 point = (m0 * s.point.x + m1 * s.point.y) + (m2 * s.point.z + translation);
  hit.point = point;
  for (int r = 0; r < 3; ++r) {
    precise double magnitude = abs(translation[r]);
    precise double carried = 0.0LF;
    dvec3 row = dvec3(m0[r], m1[r], m2[r]);
    for (int k = 0; k < 3; ++k) {
      magnitude += abs(row[k] * s.point[k]);
      carried += abs(row[k]) * s.error[k];
    }
    precise double e = gamma(3) * magnitude + (1.0LF + gamma(3)) * carried;
    hit.pointError[r] = e;
  }
  hit.normal = normalise(normalToWorld(index, s.normal));
  hit.fromInside = c.atExit;
  return hit;
}

// The ray as the node test wants it (Bvh::NodeRay).
struct NodeRay {
  dvec3 origin;
  dvec3 inverseDirection;
  ivec3 nearPlane;
  ivec3 farPlane;
  bvec3 negative;
};

NodeRay nodeRay(dvec3 origin, dvec3 direction) {
  NodeRay r;
  r.origin = origin;
  for (int i = 0; i < 3; ++i) {
    // 1 / +-0 is +-infinity, as on the CPU, without a division by zero.
    double inv = direction[i] == 0.0LF ? copySign(infinity(), direction[i]) : 1.0LF / direction[i];
    r.inverseDirection[i] = inv;
    r.negative[i] = inv < 0.0LF;
    r.nearPlane[i] = r.negative[i] ? 3 + i : i;
    r.farPlane[i] = r.negative[i] ? i : 3 + i;
  }
  return r;
}

// Bvh::hitsNode: the float planes tested in double, the far distances
// widened by their rounding.
bool hitsNode(uint node, NodeRay r, double tMax, out double tEntry) {
  precise double tMin = 0.0LF;
  double widen = 1.0LF + 2.0LF * gamma(3);
  for (int i = 0; i < 3; ++i) {
    double nearPlane = double(uintBitsToFloat(nodes[node * 8u + uint(r.nearPlane[i])]));
    double farPlane = double(uintBitsToFloat(nodes[node * 8u + uint(r.farPlane[i])]));
    precise double tNear = (nearPlane - r.origin[i]) * r.inverseDirection[i];
    precise double tFar = (farPlane - r.origin[i]) * r.inverseDirection[i];
    tFar = tFar * widen;
    tMin = tNear > tMin ? tNear : tMin;
    tMax = tFar < tMax ? tFar : tMax;
  }
  tEntry = tMin;
  return tMin <= tMax;
}

// RenderScene::closestHit (and anyHit with `any`): the planes, then the
// hierarchy depth first, near child first, as Bvh::traverse walks it.
bool searchScene(dvec3 origin, dvec3 direction, uint source, bool inward, double tMax, bool any,
                 out uint best, out Candidate bestCandidate) {
  best = kNone;
  bestCandidate = Candidate(tMax, false, kFaceNone);
  Candidate c;
  for (int p = 0; p < planeCount; ++p) {
    if (intersectObject(planes[p], origin, direction, source, inward, bestCandidate.t, c)) {
      best = planes[p];
      bestCandidate = c;
      if (any) return true;
    }
  }
  if (nodeCount == 0) return best != kNone;
  NodeRay r = nodeRay(origin, direction);
  double limit = bestCandidate.t;
  double tEntry;
  if (!hitsNode(0u, r, limit, tEntry)) return best != kNone;
  uint stackNode[kBvhStack];
  double stackEntry[kBvhStack];
  int top = 0;
  uint current = 0u;
  for (;;) {
    uint offset = nodes[current * 8u + 6u];
    uint packed = nodes[current * 8u + 7u];
    uint count = packed & 0xFFFFu;
    if (count > 0u) {
      for (uint i = 0u; i < count; ++i) {
        // The objects lie the planes first, then in the BVH's item order.
        uint object = uint(planeCount) + offset + i;
        if (intersectObject(object, origin, direction, source, inward, bestCandidate.t, c)) {
          best = object;
          bestCandidate = c;
          if (any) return true;
        }
      }
      limit = bestCandidate.t;
    } else {
      uint axis = (packed >> 16) & 0xFFu;
      uint nearChild = current + 1u;
      uint farChild = offset;
      if (r.negative[axis]) {
        nearChild = offset;
        farChild = current + 1u;
      }
      double nearEntry, farEntry;
      bool hitNear = hitsNode(nearChild, r, limit, nearEntry);
      bool hitFar = hitsNode(farChild, r, limit, farEntry);
      if (hitNear) {
        if (hitFar && top < kBvhStack) {
          stackNode[top] = farChild;
          stackEntry[top] = farEntry;
          ++top;
        }
        current = nearChild;
        continue;
      }
      if (hitFar) {
        current = farChild;
        continue;
      }
    }
    bool next = false;
    while (top > 0) {
      --top;
      if (stackEntry[top] <= limit) {
        current = stackNode[top];
        next = true;
        break;
      }
    }
    if (!next) break;
  }
  return best != kNone;
}

bool closestHit(dvec3 origin, dvec3 direction, uint source, bool inward, out Hit hit) {
  uint best;
  Candidate c;
  hit.object = kNone;
  if (!searchScene(origin, direction, source, inward, infinity(), false, best, c)) return false;
  hit = hitOn(best, origin, direction, c);
  return true;
}

// ---- shading (renderer/tracer.cpp) ----

dvec3 offsetRayOrigin(dvec3 p, dvec3 pError, dvec3 n, dvec3 w) {
  double d = dot3(abs(n), pError);
  precise dvec3 offset = d * n;
  if (dot3(w, n) < 0.0LF) offset = -offset;
  precise dvec3 po = p + offset;
  for (int i = 0; i < 3; ++i) {
    if (offset[i] > 0.0LF) {
      po[i] = nextUp(po[i]);
    } else if (offset[i] < 0.0LF) {
      po[i] = nextDown(po[i]);
    }
  }
  return po;
}

// Tracer::shadowed, without the hint (which changes no answer).
bool shadowed(Hit hit, dvec3 light, inout uint shadowRays) {
  ++shadowRays;
  precise dvec3 toLight = light - hit.point;
  dvec3 origin = offsetRayOrigin(hit.point, hit.pointError, hit.normal, toLight);
  precise dvec3 direction = light - origin;
  bool inward = dot3(direction, hit.normal) < 0.0LF;
  double extent = max(max(max(abs(light.x), abs(light.y)), max(abs(light.z), abs(origin.x))),
                      max(abs(origin.y), abs(origin.z)));
  double len = max(max(abs(direction.x), abs(direction.y)), abs(direction.z));
  if (len == 0.0LF) return false;
  precise double tMax = 1.0LF - gamma(32) * extent / len;
  if (tMax <= 0.0LF) return false;
  uint best;
  Candidate c;
  return searchScene(origin, direction, hit.object, inward, tMax, true, best, c);
}

// specularPower of tracer.cpp: repeated squaring for whole exponents up to
// 1024; any other exponent in single precision (GLSL has no double pow).
double specularPower(double x, double e) {
  if (!(e >= 0.0LF && e <= 1024.0LF) || e != floor(e)) return double(pow(float(x), float(e)));
  uint n = uint(e);
  precise double result = 1.0LF;
  precise double base = x;
  while (n > 0u) {
    if ((n & 1u) != 0u) result = result * base;
    base = base * base;
    n >>= 1;
  }
  return result;
}

dvec3 shadeSurface(Hit hit, dvec3 normal, dvec3 toViewer, inout uint shadowRays) {
  uint o = hit.object;
  dvec3 colour = objectVector(o, kMaterial);
  double ambient = objectValue(o, kMaterial + 3);
  double diffuse = objectValue(o, kMaterial + 4);
  double specular = objectValue(o, kMaterial + 5);
  double shininess = objectValue(o, kMaterial + 6);
  precise dvec3 result = dvec3(0.0LF);
  for (int i = 0; i < lightCount; ++i) {
    dvec3 position = dvec3(lights[6 * i], lights[6 * i + 1], lights[6 * i + 2]);
    dvec3 lightColour = dvec3(lights[6 * i + 3], lights[6 * i + 4], lights[6 * i + 5]);
    result = result + colour * lightColour * ambient;
    precise dvec3 l = position - hit.point;
    precise double distance = sqrt(dot3(l, l));
    if (!(distance > 0.0LF)) continue;
    l = l / distance;
    double cosine = dot3(l, normal);
    if (cosine <= 0.0LF || shadowed(hit, position, shadowRays)) continue;
    result = result + colour * lightColour * (diffuse * cosine);
    dvec3 reflected = reflectAbout(-l, normal);
    double highlight = max(0.0LF, dot3(reflected, toViewer));
    if (highlight > 0.0LF && specular > 0.0LF) {
      result = result + lightColour * (specular * specularPower(highlight, shininess));
    }
  }
  return result;
}

double schlickReflectance(double n1, double n2, double cosIncident) {
  precise double r0 = (n1 - n2) / (n1 + n2);
  r0 = r0 * r0;
  precise double cosine = cosIncident;
  if (n1 > n2) {
    precise double sin2t = (n1 / n2) * (n1 / n2) * (1.0LF - cosIncident * cosIncident);
    if (sin2t >= 1.0LF) return 1.0LF;
    cosine = sqrt(1.0LF - sin2t);
  }
  precise double x = 1.0LF - cosine;
  precise double r = r0 + (1.0LF - r0) * x * x * x * x * x;
  return r;
}

bool refractDirection(dvec3 d, dvec3 n, double n1, double n2, out dvec3 refracted) {
  refracted = d;
  precise double eta = n1 / n2;
  double cosIncident = -dot3(d, n);
  precise double k = 1.0LF - eta * eta * (1.0LF - cosIncident * cosIncident);
  if (k < 0.0LF) return false;
  precise dvec3 t = eta * d + (eta * cosIncident - sqrt(k)) * n;
  refracted = normalise(t);
  return true;
}

// ---- a sample: Whitted tracing with an explicit stack ----

// A ray still to trace: where it starts, what it leaves, how much its colour
// counts, and the media it travels through.
struct Ray {
  dvec3 origin;
  dvec3 direction;
  double weight;
  uint source;
  bool inward;
  int bounce;
  int mediaCount;
  uint media[kMediaCapacity];
};

double refractiveIndex(Ray ray) {
  return ray.mediaCount == 0 ? 1.0LF : objectValue(ray.media[ray.mediaCount - 1], kMaterial + 9);
}

void pushMedium(inout Ray ray, uint object) {
  if (ray.mediaCount < kMediaCapacity) {
    ray.media[ray.mediaCount] = object;
    ++ray.mediaCount;
  }
}

void removeMedium(inout Ray ray, uint object) {
  for (int i = ray.mediaCount - 1; i >= 0; --i) {
    if (ray.media[i] == object) {
      for (int k = i; k + 1 < ray.mediaCount; ++k) ray.media[k] = ray.media[k + 1];
      --ray.mediaCount;
      return;
    }
  }
}

Ray childRay(Ray parent, Hit hit, dvec3 direction, double weight) {
  Ray child = parent;
  child.origin = offsetRayOrigin(hit.point, hit.pointError, hit.normal, direction);
  child.direction = direction;
  precise double w = parent.weight * weight;
  child.weight = w;
  child.source = hit.object;
  child.inward = dot3(direction, hit.normal) < 0.0LF;
  child.bounce = parent.bounce + 1;
  return child;
}

// The camera ray through image position `at` (PinholeCamera::rayThrough).
dvec3 cameraDirection(dvec2 at) {
  precise double sx = (2.0LF * at.x / imageWidth - 1.0LF) * tanHalfWidth;
  precise double sy = (1.0LF - 2.0LF * at.y / imageHeight) * tanHalfHeight;
  precise dvec3 d = forward.xyz + sx * right.xyz + sy * up.xyz;
  return normalise(d);
}

uint64_t mixBits(uint64_t x) {
  x += 0x9E3779B97F4A7C15UL;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9UL;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBUL;
  return x ^ (x >> 31);
}

// PixelSampleSequence of sample_sequence.cpp: Owen-scrambled Sobol points,
// bit for bit.
uint sobolSecond(uint index) {
  uint result = 0u;
  for (uint column = 0x80000000u; index != 0u; index >>= 1, column ^= column >> 1) {
    if ((index & 1u) != 0u) result ^= column;
  }
  return result;
}

uint owenScramble(uint v, uint scramble) {
  v = bitfieldReverse(v);
  v ^= v * 0x3d20adeau;
  v += scramble;
  v *= (scramble >> 16) | 1u;
  v ^= v * 0x05526c56u;
  v ^= v * 0x53a22864u;
  return bitfieldReverse(v);
}

// samplePosition of camera.cpp.
dvec2 samplePosition(int i, int j, int index, int count) {
  if (count <= 1) return dvec2(double(i) + 0.5LF, double(j) + 0.5LF);
  uint64_t state = mixBits(seed ^ mixBits((uint64_t(j) << 32) ^ uint64_t(uint(i))));
  uint xScramble = uint(mixBits(state) >> 32);
  uint yScramble = uint(mixBits(state + 1UL) >> 32);
  const double kFraction = 2.3283064365386962890625e-10LF;  // 2^-32
  double u = double(owenScramble(bitfieldReverse(uint(index)), xScramble)) * kFraction;
  double v = double(owenScramble(sobolSecond(uint(index)), yScramble)) * kFraction;
  precise double x = double(i) + u;
  precise double y = double(j) + v;
  return dvec2(x, y);
}

// The colour of one sample; `object` is what its camera ray met, or kNone.
dvec3 traceSample(dvec2 at, inout uvec3 rayCounts, out uint object) {
  Ray pending[kPendingCapacity];
  int top = 0;
  Ray ray;
  ray.origin = eye.xyz;
  ray.direction = cameraDirection(at);
  ray.weight = 1.0LF;
  ray.source = kNone;
  ray.inward = false;
  ray.bounce = 0;
  ray.mediaCount = hasTransparency != 0 ? eyeMediaCount : 0;
  for (int k = 0; k < kMediaCapacity; ++k) ray.media[k] = eyeMedia[k];
  object = kNone;
  precise dvec3 colour = dvec3(0.0LF);
  for (;;) {
    Hit hit;
    bool found = closestHit(ray.origin, ray.direction, ray.source, ray.inward, hit);
    if (ray.bounce == 0) object = found ? hit.object : kNone;
    bool haveNext = false;
    Ray next;
    if (found) {
      dvec3 d = normalise(ray.direction);
      dvec3 n = dot3(hit.normal, d) > 0.0LF ? -hit.normal : hit.normal;
      dvec3 surface = shadeSurface(hit, n, -d, rayCounts.y);
      colour = colour + ray.weight * surface;
      double reflectivity = objectValue(hit.object, kMaterial + 7);
      double transparency = objectValue(hit.object, kMaterial + 8);
      if (ray.bounce + 1 <= maxDepth) {
        if (hasTransparency != 0 && transparency > 0.0LF) {
          // Tracer::reflectAndRefract's shares and directions.
          Ray after = ray;
          dvec3 t = d;
          bool passes = true;
          double reflectance = 1.0LF;
          if (objectKind(hit.object) != kPlane) {
            double ri = objectValue(hit.object, kMaterial + 9);
            bool entering = !hit.fromInside;
            double n1 = entering ? refractiveIndex(ray) : ri;
            if (entering) {
              pushMedium(after, hit.object);
            } else {
              removeMedium(after, hit.object);
            }
            double n2 = entering ? ri : refractiveIndex(after);
            reflectance = schlickReflectance(n1, n2, -dot3(d, n));
            passes = refractDirection(d, n, n1, n2, t);
          } else {
            reflectance = 0.0LF;
          }
          bool reflects = reflectivity > 0.0LF;
          precise double reflectedWeight = reflects ? reflectance * reflectivity : 0.0LF;
          precise double refractedWeight =
              passes ? (reflects ? 1.0LF - reflectance : 1.0LF) * transparency : 0.0LF;
          bool traceReflected = reflects && reflectedWeight != 0.0LF;
          bool traceRefracted = passes && refractedWeight != 0.0LF;
          if (traceRefracted) {
            next = childRay(after, hit, t, refractedWeight);
            haveNext = true;
            ++rayCounts.x;
          }
          if (traceReflected) {
            Ray reflected = childRay(ray, hit, reflectAbout(d, n), reflectedWeight);
            ++rayCounts.x;
            if (!haveNext) {
              next = reflected;
              haveNext = true;
            } else if (top < kPendingCapacity) {
              pending[top] = reflected;
              ++top;
            } else {
              ++rayCounts.z;
            }
          }
        } else if (reflectivity > 0.0LF) {
          next = childRay(ray, hit, reflectAbout(d, n), reflectivity);
          haveNext = true;
          ++rayCounts.x;
        }
      }
    }
    if (haveNext) {
      ray = next;
      continue;
    }
    if (top == 0) break;
    --top;
    ray = pending[top];
  }
  return colour;
}

// toStoredChannel of render.cpp: NaN is 0, and the float range holds.
float stored(double v) {
  if (!(v == v)) return 0.0;
  const double kMax = 3.4028234663852886e38LF;
  return float(clamp(v, -kMax, kMax));
}

void main() {
  uint gx = gl_GlobalInvocationID.x;
  uint gy = gl_GlobalInvocationID.y + uint(rowBase);
  if (gx >= uint(regionWidth) || gy >= uint(regionHeight)) return;
  int i = regionX0 + int(gx);
  int j = regionY0 + int(gy);
  uint at = gy * uint(regionWidth) + gx;
  uvec3 rayCounts = uvec3(0u);
  if (idsOnly != 0) {
    Hit hit;
    dvec2 centre = dvec2(double(i) + 0.5LF, double(j) + 0.5LF);
    bool found = closestHit(eye.xyz, cameraDirection(centre), kNone, false, hit);
    counts[at] = uvec4(0u, 0u, 0u, found ? hit.object : kNone);
    return;
  }
  int spp = max(1, samplesPerPixel);
  precise dvec3 sum = dvec3(0.0LF);
  int hits = 0;
  uint object = kNone;
  for (int s = 0; s < spp; ++s) {
    dvec3 colour = traceSample(samplePosition(i, j, s, spp), rayCounts, object);
    sum = sum + colour;
    if (object != kNone) ++hits;
  }
  if (spp > 1) sum = sum / double(spp);
  double coverage = double(hits) / double(spp);
  colours[at] = vec4(stored(sum.x), stored(sum.y), stored(sum.z), float(coverage));
  counts[at] = uvec4(rayCounts, object);
}
