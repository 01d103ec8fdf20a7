#include "scenefile/mesh_fit.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

namespace scene {

namespace {

constexpr double kPi = std::numbers::pi;
// Triangle normals within this of each other (1 - |cos|) face one way.
constexpr double kSameDirection = 1e-6;
// A direction within this of a coordinate axis is that axis: float vertex
// data should not tilt an axis-aligned shape by 1e-8.
constexpr double kSnap = 1e-6;
constexpr std::size_t kMaxClusters = 256;
// A tessellated sphere, cylinder or disc holds at least this share of the
// true shape's volume or area; a half or a wedge does not.
constexpr double kMinCoverage = 0.6;

struct Cluster {
  glm::dvec3 normal{0.0};
  double area = 0.0;
};

// What every test needs, computed once.
struct Mesh {
  std::vector<glm::dvec3> points;  // the referenced vertices, without repeats
  std::vector<std::array<glm::dvec3, 3>> triangles;
  glm::dvec3 centroid{0.0};
  double size = 0.0;  // the diagonal of the bounding box
  double area = 0.0;
  double volume = 0.0;  // signed, by the divergence theorem about the centroid
  glm::dvec3 areaNormal{0.0};
  std::vector<Cluster> clusters;  // by direction up to sign, largest area first
  bool tooManyDirections = false;
};

Mesh prepare(std::span<const glm::dvec3> positions, std::span<const std::uint32_t> indices) {
  Mesh m;
  std::vector<std::uint32_t> used(indices.begin(), indices.end());
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  for (std::uint32_t i : used) m.points.push_back(positions[i]);
  auto less = [](const glm::dvec3& a, const glm::dvec3& b) {
    return a.x != b.x ? a.x < b.x : a.y != b.y ? a.y < b.y : a.z < b.z;
  };
  std::sort(m.points.begin(), m.points.end(), less);
  m.points.erase(std::unique(m.points.begin(), m.points.end()), m.points.end());
  if (m.points.empty()) return m;
  glm::dvec3 lo = m.points[0], hi = m.points[0];
  for (const glm::dvec3& p : m.points) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
    m.centroid += p;
  }
  m.centroid /= static_cast<double>(m.points.size());
  m.size = glm::length(hi - lo);
  for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
    std::array<glm::dvec3, 3> tri = {positions[indices[t]], positions[indices[t + 1]],
                                     positions[indices[t + 2]]};
    m.triangles.push_back(tri);
    glm::dvec3 cross = glm::cross(tri[1] - tri[0], tri[2] - tri[0]);
    double twiceArea = glm::length(cross);
    m.area += 0.5 * twiceArea;
    m.areaNormal += cross;
    m.volume +=
        glm::dot(tri[0] - m.centroid, glm::cross(tri[1] - m.centroid, tri[2] - m.centroid)) / 6.0;
    if (!(twiceArea > 1e-12 * m.size * m.size)) continue;
    glm::dvec3 n = cross / twiceArea;
    bool merged = false;
    for (Cluster& c : m.clusters) {
      if (1.0 - std::abs(glm::dot(c.normal, n)) <= kSameDirection) {
        c.area += 0.5 * twiceArea;
        merged = true;
        break;
      }
    }
    if (merged) continue;
    if (m.clusters.size() < kMaxClusters) {
      m.clusters.push_back({n, 0.5 * twiceArea});
    } else {
      m.tooManyDirections = true;
    }
  }
  std::stable_sort(m.clusters.begin(), m.clusters.end(),
                   [](const Cluster& a, const Cluster& b) { return a.area > b.area; });
  return m;
}

// A direction with its largest component positive, moved onto the nearest
// coordinate axis when it is within kSnap of it.
glm::dvec3 canonicalAxis(glm::dvec3 d) {
  d = glm::normalize(d);
  int major = 0;
  for (int i = 1; i < 3; ++i) {
    if (std::abs(d[i]) > std::abs(d[major])) major = i;
  }
  if (d[major] < 0) d = -d;
  glm::dvec3 axis(0.0);
  axis[major] = 1.0;
  return glm::length(d - axis) <= kSnap ? axis : d;
}

// The rotation that takes +Y to `y` by the shortest arc: the identity when
// `y` is +Y, so that a shape already upright keeps its frame.
glm::dmat3 frameWithY(const glm::dvec3& y) {
  glm::dvec3 up(0.0, 1.0, 0.0);
  double c = glm::dot(up, y);
  if (c >= 1.0) return glm::dmat3(1.0);
  if (c <= -1.0 + 1e-12)
    return glm::dmat3(glm::dvec3(1, 0, 0), glm::dvec3(0, -1, 0), glm::dvec3(0, 0, -1));
  glm::dvec3 v = glm::cross(up, y);
  glm::dmat3 k(glm::dvec3(0, v.z, -v.y), glm::dvec3(-v.z, 0, v.x), glm::dvec3(v.y, -v.x, 0));
  glm::dmat3 r = glm::dmat3(1.0) + k + k * k * (1.0 / (1.0 + c));
  // Re-orthonormalise the columns so that no rounding reads as shear.
  glm::dvec3 x = glm::normalize(r[0]);
  glm::dvec3 z = glm::normalize(glm::cross(x, y));
  return glm::dmat3(x, y, z);
}

// Solves the n x n system a * x = b (n <= 4) by Gaussian elimination with
// partial pivoting; false when it is singular.
template <int N>
bool solve(std::array<std::array<double, N + 1>, N> a, std::array<double, N>& x) {
  for (int col = 0; col < N; ++col) {
    int pivot = col;
    for (int r = col + 1; r < N; ++r) {
      if (std::abs(a[r][col]) > std::abs(a[pivot][col])) pivot = r;
    }
    if (!(std::abs(a[pivot][col]) > 1e-300)) return false;
    std::swap(a[col], a[pivot]);
    for (int r = col + 1; r < N; ++r) {
      double f = a[r][col] / a[col][col];
      for (int c = col; c <= N; ++c) a[r][c] -= f * a[col][c];
    }
  }
  for (int r = N - 1; r >= 0; --r) {
    double s = a[r][N];
    for (int c = r + 1; c < N; ++c) s -= a[r][c] * x[c];
    x[r] = s / a[r][r];
  }
  for (double v : x) {
    if (!std::isfinite(v)) return false;
  }
  return true;
}

// The least-squares sphere |p - c| = r through `points` (algebraic fit,
// centred and scaled for conditioning).
bool fitSphereLsq(const std::vector<glm::dvec3>& points, const glm::dvec3& origin, double scale,
                  glm::dvec3& centre, double& radius) {
  std::array<std::array<double, 5>, 4> a{};
  for (const glm::dvec3& p : points) {
    glm::dvec3 q = (p - origin) / scale;
    std::array<double, 4> row = {2 * q.x, 2 * q.y, 2 * q.z, 1.0};
    double rhs = glm::dot(q, q);
    for (int i = 0; i < 4; ++i) {
      for (int j = 0; j < 4; ++j) a[i][j] += row[i] * row[j];
      a[i][4] += row[i] * rhs;
    }
  }
  std::array<double, 4> x{};
  if (!solve<4>(a, x)) return false;
  glm::dvec3 c(x[0], x[1], x[2]);
  double r2 = x[3] + glm::dot(c, c);
  if (!(r2 > 0.0)) return false;
  centre = origin + c * scale;
  radius = std::sqrt(r2) * scale;
  return true;
}

// The least-squares circle through 2D points.
bool fitCircleLsq(const std::vector<glm::dvec2>& points, double scale, glm::dvec2& centre,
                  double& radius) {
  if (points.size() < 3) return false;
  glm::dvec2 origin(0.0);
  for (const glm::dvec2& p : points) origin += p;
  origin /= static_cast<double>(points.size());
  std::array<std::array<double, 4>, 3> a{};
  for (const glm::dvec2& p : points) {
    glm::dvec2 q = (p - origin) / scale;
    std::array<double, 3> row = {2 * q.x, 2 * q.y, 1.0};
    double rhs = glm::dot(q, q);
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) a[i][j] += row[i] * row[j];
      a[i][3] += row[i] * rhs;
    }
  }
  std::array<double, 3> x{};
  if (!solve<3>(a, x)) return false;
  glm::dvec2 c(x[0], x[1]);
  double r2 = x[2] + glm::dot(c, c);
  if (!(r2 > 0.0)) return false;
  centre = origin + c * scale;
  radius = std::sqrt(r2) * scale;
  return true;
}

// A circle through the rim of a disc or a cylinder's cross-section: fitted
// to every point, then again without the points near the centre (a cap's
// middle vertex), which may stand there too.
bool fitRim(const std::vector<glm::dvec2>& points, double scale, glm::dvec2& centre,
            double& radius) {
  if (!fitCircleLsq(points, scale, centre, radius)) return false;
  std::vector<glm::dvec2> rim;
  for (const glm::dvec2& p : points) {
    if (glm::length(p - centre) >= 0.5 * radius) rim.push_back(p);
  }
  return fitCircleLsq(rim, scale, centre, radius);
}

glm::dmat4 affine(const glm::dmat3& linear, const glm::dvec3& translation) {
  glm::dmat4 m(linear);
  m[3] = glm::dvec4(translation, 1.0);
  return m;
}

glm::dmat3 scaledColumns(const glm::dmat3& r, const glm::dvec3& s) {
  return glm::dmat3(r[0] * s.x, r[1] * s.y, r[2] * s.z);
}

// A deviation for a message: three significant digits say enough.
std::string shortNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

struct Attempt {
  std::optional<MeshFit> fit;
  ObjectKind kind = ObjectKind::Sphere;
  double error = std::numeric_limits<double>::infinity();  // of the nearest candidate
  std::string why;
};

void consider(Attempt& best, const Attempt& next) {
  if (next.error < best.error || (best.why.empty() && !next.why.empty())) best = next;
}

// A flat mesh seen from its normal: the rotation that takes +Y to the
// normal, the points in the plane's x and z, their mean height along the
// normal and how far (relative to the mesh's size) any is off that height.
struct PlaneFrame {
  glm::dmat3 frame;
  glm::dmat3 toFrame;
  std::vector<glm::dvec2> flat;
  double height = 0.0;
  double offPlane = 0.0;
};

PlaneFrame planeFrame(const Mesh& m) {
  glm::dvec3 normal = glm::length(m.areaNormal) > 0.0 ? m.areaNormal : m.clusters[0].normal;
  normal = glm::normalize(normal);
  // Keep the mesh's front as +Y, snapping only onto an axis of the same sign.
  for (int i = 0; i < 3; ++i) {
    glm::dvec3 axis(0.0);
    axis[i] = normal[i] < 0 ? -1.0 : 1.0;
    if (glm::length(normal - axis) <= kSnap) normal = axis;
  }
  PlaneFrame f;
  f.frame = frameWithY(normal);
  f.toFrame = glm::transpose(f.frame);
  for (const glm::dvec3& p : m.points) {
    glm::dvec3 q = f.toFrame * p;
    f.flat.emplace_back(q.x, q.z);
    f.height += q.y;
  }
  f.height /= static_cast<double>(m.points.size());
  for (const glm::dvec3& p : m.points) {
    f.offPlane = std::max(f.offPlane, std::abs((f.toFrame * p).y - f.height));
  }
  f.offPlane /= m.size;
  return f;
}

// A rectangle: its sides give the in-plane angle (taken in (-45, 45]
// degrees, so that an axis-aligned quad keeps its frame). True when one
// fits; else `out` keeps the nearest miss.
bool fitRectangle(const Mesh& m, const PlaneFrame& f, double tol, Attempt& out) {
  std::vector<double> angles;
  for (const auto& tri : m.triangles) {
    for (int e = 0; e < 3 && angles.size() < 64; ++e) {
      glm::dvec3 d = f.toFrame * (tri[(e + 1) % 3] - tri[e]);
      if (std::hypot(d.x, d.z) <= 1e-9 * m.size) continue;
      double theta = std::atan2(d.z, d.x);
      theta -= std::round(theta / (kPi / 2)) * (kPi / 2);
      if (std::abs(theta) <= 1e-9) theta = 0.0;
      bool seen = false;
      for (double a : angles) seen = seen || std::abs(a - theta) <= 1e-9;
      if (!seen) angles.push_back(theta);
    }
  }
  for (double theta : angles) {
    double c = std::cos(theta), s = std::sin(theta);
    glm::dvec2 lo(std::numeric_limits<double>::infinity()), hi(-lo);
    std::vector<glm::dvec2> turned;
    for (const glm::dvec2& p : f.flat) {
      glm::dvec2 t(c * p.x + s * p.y, -s * p.x + c * p.y);
      turned.push_back(t);
      lo = glm::min(lo, t);
      hi = glm::max(hi, t);
    }
    glm::dvec2 extent = hi - lo;
    if (!(extent.x > tol * m.size && extent.y > tol * m.size)) continue;
    double cornerError = 0.0;
    for (int corner = 0; corner < 4; ++corner) {
      glm::dvec2 want((corner & 1) ? hi.x : lo.x, (corner & 2) ? hi.y : lo.y);
      double nearest = std::numeric_limits<double>::infinity();
      for (const glm::dvec2& t : turned) nearest = std::min(nearest, glm::length(t - want));
      cornerError = std::max(cornerError, nearest / m.size);
    }
    double areaError = std::abs(m.area / (extent.x * extent.y) - 1.0);
    double error = std::max({cornerError, f.offPlane, areaError / 10.0});
    if (error > tol) {
      if (error < out.error) {
        out.error = error;
        out.why = "the nearest PLANE (a rectangle) is off by " + shortNumber(error);
      }
      continue;
    }
    glm::dvec2 middle = 0.5 * (lo + hi);
    glm::dvec3 ex = f.frame * glm::dvec3(c, 0.0, s);
    glm::dvec3 ey = f.frame[1];
    glm::dvec3 ez = glm::cross(ex, ey);
    glm::dvec3 centre =
        f.frame * glm::dvec3(c * middle.x - s * middle.y, f.height, s * middle.x + c * middle.y);
    double hx = extent.x / 2, hz = extent.y / 2;
    MeshFit fit{ObjectKind::Plane,
                affine(glm::dmat3(ex * hx, ey * std::sqrt(hx * hz), ez * hz), centre), error};
    out.fit = fit;
    out.error = error;
    return true;
  }
  return false;
}

// A disc: its rim a circle, the mesh covering most of it. True when one
// fits; else `out` keeps the nearest miss.
bool fitDisc(const Mesh& m, const PlaneFrame& f, double tol, Attempt& out) {
  glm::dvec2 centre2;
  double radius = 0.0;
  if (!fitRim(f.flat, m.size, centre2, radius)) return false;
  double error = f.offPlane;
  for (const glm::dvec2& p : f.flat) {
    double rho = glm::length(p - centre2);
    error = std::max(error, std::min(std::abs(rho - radius), rho) / radius);
  }
  double coverage = m.area / (kPi * radius * radius);
  if (error <= tol && coverage >= kMinCoverage && coverage <= 1.0 + 10 * tol) {
    glm::dvec3 centre = f.frame * glm::dvec3(centre2.x, f.height, centre2.y);
    out.fit = MeshFit{ObjectKind::Plane, affine(scaledColumns(f.frame, glm::dvec3(radius)), centre),
                      error};
    out.error = error;
    return true;
  }
  if (error < out.error) {
    out.error = error;
    out.why = coverage < kMinCoverage
                  ? "it is flat but neither a rectangle nor a whole disc"
                  : "the nearest PLANE (a disc) is off by " + shortNumber(error);
  }
  return false;
}

Attempt fitPlane(const Mesh& m, double tol) {
  Attempt out;
  out.kind = ObjectKind::Plane;
  if (m.clusters.size() != 1 || m.tooManyDirections) {
    out.why = "it is not flat";
    return out;
  }
  PlaneFrame f = planeFrame(m);
  if (fitRectangle(m, f, tol, out) || fitDisc(m, f, tol, out)) return out;
  if (out.why.empty()) out.why = "it is flat but neither a rectangle nor a disc";
  return out;
}

Attempt fitBox(const Mesh& m, double tol) {
  Attempt out;
  out.kind = ObjectKind::Cube;
  if (m.clusters.size() != 3 || m.tooManyDirections) {
    out.why = "its faces do not face three ways";
    return out;
  }
  // Give each face direction the coordinate axis nearest to it.
  std::array<glm::dvec3, 3> axes;
  std::array<bool, 3> taken{};
  for (int axis = 0; axis < 3; ++axis) {
    int best = -1;
    for (int c = 0; c < 3; ++c) {
      if (taken[c]) continue;
      if (best < 0 ||
          std::abs(m.clusters[c].normal[axis]) > std::abs(m.clusters[best].normal[axis])) {
        best = c;
      }
    }
    taken[best] = true;
    glm::dvec3 n = m.clusters[best].normal;
    if (n[axis] < 0) n = -n;
    glm::dvec3 e(0.0);
    e[axis] = 1.0;
    axes[axis] = glm::length(n - e) <= kSnap ? e : n;
  }
  for (int i = 0; i < 3; ++i) {
    for (int j = i + 1; j < 3; ++j) {
      if (std::abs(glm::dot(axes[i], axes[j])) > tol) {
        out.why = "its faces are not at right angles";
        return out;
      }
    }
  }
  glm::dvec3 x = glm::normalize(axes[0]);
  glm::dvec3 y = glm::normalize(axes[1] - glm::dot(axes[1], x) * x);
  glm::dmat3 frame(x, y, glm::cross(x, y));
  glm::dmat3 toFrame = glm::transpose(frame);
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
  std::vector<glm::dvec3> local;
  for (const glm::dvec3& p : m.points) {
    local.push_back(toFrame * p);
    lo = glm::min(lo, local.back());
    hi = glm::max(hi, local.back());
  }
  glm::dvec3 half = 0.5 * (hi - lo);
  double largest = std::max({half.x, half.y, half.z});
  if (!(std::min({half.x, half.y, half.z}) > tol * largest)) {
    out.why = "it is flat";
    return out;
  }
  double error = 0.0;
  for (const glm::dvec3& q : local) {
    double d = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 3; ++i) d = std::min({d, std::abs(q[i] - lo[i]), std::abs(q[i] - hi[i])});
    error = std::max(error, d / largest);
  }
  for (int corner = 0; corner < 8; ++corner) {
    glm::dvec3 want((corner & 1) ? hi.x : lo.x, (corner & 2) ? hi.y : lo.y,
                    (corner & 4) ? hi.z : lo.z);
    double nearest = std::numeric_limits<double>::infinity();
    for (const glm::dvec3& q : local) nearest = std::min(nearest, glm::length(q - want));
    error = std::max(error, nearest / largest);
  }
  double volumeError = std::abs(std::abs(m.volume) / (8.0 * half.x * half.y * half.z) - 1.0);
  error = std::max(error, volumeError / 10.0);
  out.error = error;
  if (error > tol) {
    out.why = "the nearest CUBE is off by " + shortNumber(error);
    return out;
  }
  out.fit = MeshFit{ObjectKind::Cube, affine(scaledColumns(frame, half), frame * (0.5 * (lo + hi))),
                    error};
  return out;
}

Attempt fitCylinder(const Mesh& m, double tol) {
  Attempt out;
  out.kind = ObjectKind::Cylinder;
  out.why = "no axis has two flat caps";
  std::size_t candidates = m.clusters.size() <= 64 ? m.clusters.size() : 16;
  for (std::size_t k = 0; k < candidates; ++k) {
    glm::dmat3 frame = frameWithY(canonicalAxis(m.clusters[k].normal));
    glm::dmat3 toFrame = glm::transpose(frame);
    std::vector<glm::dvec3> local;
    std::vector<glm::dvec2> section;
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const glm::dvec3& p : m.points) {
      local.push_back(toFrame * p);
      section.emplace_back(local.back().x, local.back().z);
      lo = std::min(lo, local.back().y);
      hi = std::max(hi, local.back().y);
    }
    double height = hi - lo;
    glm::dvec2 centre;
    double radius = 0.0;
    if (!(height > tol * m.size) || !fitRim(section, m.size, centre, radius)) continue;
    double scale = std::max(radius, height / 2);
    double error = 0.0;
    for (const glm::dvec3& q : local) {
      double rho = glm::length(glm::dvec2(q.x, q.z) - centre);
      double side = std::abs(rho - radius);
      double cap = rho <= radius * (1 + tol) ? std::min(std::abs(q.y - lo), std::abs(q.y - hi))
                                             : std::numeric_limits<double>::infinity();
      error = std::max(error, std::min(side, cap) / scale);
    }
    double coverage = std::abs(m.volume) / (kPi * radius * radius * height);
    if (error > tol || coverage < kMinCoverage || coverage > 1.0 + 10 * tol) {
      if (error < out.error) {
        out.error = error;
        out.why = error > tol ? "the nearest CYLINDER is off by " + shortNumber(error)
                              : "it has the outline of a CYLINDER but not its volume";
      }
      continue;
    }
    if (out.fit && out.fit->error <= error) continue;
    glm::dvec3 middle = frame * glm::dvec3(centre.x, 0.5 * (lo + hi), centre.y);
    out.fit = MeshFit{ObjectKind::Cylinder,
                      affine(scaledColumns(frame, {radius, height / 2, radius}), middle), error};
    out.error = error;
  }
  return out;
}

Attempt fitSphere(const Mesh& m, double tol) {
  Attempt out;
  out.kind = ObjectKind::Sphere;
  glm::dvec3 centre;
  double radius = 0.0;
  if (m.points.size() < 4 || !fitSphereLsq(m.points, m.centroid, m.size, centre, radius)) {
    out.why = "its vertices lie on no sphere";
    return out;
  }
  double error = 0.0;
  for (const glm::dvec3& p : m.points) {
    error = std::max(error, std::abs(glm::length(p - centre) - radius) / radius);
  }
  double coverage = std::abs(m.volume) / (4.0 / 3.0 * kPi * radius * radius * radius);
  out.error = error;
  if (error > tol) {
    out.why = "the nearest SPHERE is off by " + shortNumber(error);
    return out;
  }
  if (coverage < kMinCoverage || coverage > 1.0 + 10 * tol) {
    out.why = "its vertices lie on a sphere, but it is not a whole one";
    return out;
  }
  glm::dmat4 shape(radius);
  shape[3] = glm::dvec4(centre, 1.0);
  out.fit = MeshFit{ObjectKind::Sphere, shape, error};
  return out;
}

// Why the triangles cannot be fitted at all, or nothing: the fitting sorts
// and indexes the vertices, which an index past them or a NaN would break.
std::optional<std::string> unusable(std::span<const glm::dvec3> positions,
                                    std::span<const std::uint32_t> indices) {
  if (indices.size() % 3 != 0) {
    return std::to_string(indices.size()) + " indices are not whole triangles";
  }
  for (std::uint32_t i : indices) {
    if (i >= positions.size()) {
      return "index " + std::to_string(i) + " is past the " + std::to_string(positions.size()) +
             " vertices";
    }
    const glm::dvec3& p = positions[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
      return "vertex " + std::to_string(i) + " is not finite";
    }
  }
  return std::nullopt;
}

}  // namespace

FitResult fitPrimitive(std::span<const glm::dvec3> positions,
                       std::span<const std::uint32_t> indices, double tolerance) {
  FitResult result;
  if (std::optional<std::string> why = unusable(positions, indices)) {
    result.reason = *why;
    return result;
  }
  Mesh m = prepare(positions, indices);
  if (m.points.size() < 3 || !(m.size > 0.0) || !std::isfinite(m.size)) {
    result.reason = "it has no area";
    return result;
  }
  Attempt best;
  for (auto test : {fitPlane, fitBox, fitCylinder, fitSphere}) {
    Attempt a = test(m, tolerance);
    if (a.fit) {
      result.fit = a.fit;
      return result;
    }
    consider(best, a);
  }
  result.reason = best.why;
  return result;
}

}  // namespace scene
