#include "renderer/direction_grid.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec4.hpp>
#include <limits>

#include "renderer/saturating.h"

namespace render {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

bool finite(const Bounds& b) {
  return std::isfinite(b.lo.x) && std::isfinite(b.lo.y) && std::isfinite(b.lo.z) &&
         std::isfinite(b.hi.x) && std::isfinite(b.hi.y) && std::isfinite(b.hi.z);
}

// [from, to] widened by the margin.
void widen(double& from, double& to) {
  from -= DirectionGrid::kMargin * (1.0 + std::abs(from));
  to += DirectionGrid::kMargin * (1.0 + std::abs(to));
}

// The cells [low, high] of one axis of a window that the widened tangent
// range [from, to] covers; false when it misses the window.
bool cellSpan(double from, double to, double windowLow, double scale, int cells, int& low,
              int& high) {
  // The same expression as cellAt's, (u - windowLow) * scale, which only
  // grows with u: a lookup inside [from, to] lands inside [low, high].
  double x = (from - windowLow) * scale;
  double y = (to - windowLow) * scale;
  if (!(x < cells) || !(y >= 0.0)) return false;
  low = x < 0.0 ? 0 : static_cast<int>(x);
  high = y >= cells ? cells - 1 : static_cast<int>(y);
  return true;
}

// Columns and rows for about `cells` cells, about square, over a
// rectangle `width` x `height` (both above 0): each at least 1, their
// product at most `cells`.
void cutRectangle(double width, double height, std::uint64_t cells, int& columns, int& rows) {
  double across = std::round(std::sqrt(static_cast<double>(cells) * (width / height)));
  std::uint64_t c = static_cast<std::uint64_t>(std::clamp(across, 1.0, static_cast<double>(cells)));
  columns = static_cast<int>(c);
  rows = static_cast<int>(std::max<std::uint64_t>(cells / c, 1));
}

}  // namespace

std::uint64_t DirectionGrid::FaceCells::forFace(std::uint64_t boxes, double boxArea,
                                                double area) const {
  double wanted = perBox * static_cast<double>(boxes);
  // The mean box's area is boxArea / boxes.
  if (boxArea > 0.0)
    wanted = std::min(wanted, perBoxArea * area * static_cast<double>(boxes) / boxArea);
  // Not a number fails the test, and gives least.
  double rounded = std::ceil(wanted);
  double lower = static_cast<double>(least);
  double cells = rounded >= lower ? rounded : lower;
  double upper = std::min(static_cast<double>(most), static_cast<double>(kMaxFaceCells));
  return static_cast<std::uint64_t>(cells <= upper ? cells : upper);
}

std::uint64_t DirectionGrid::FaceCells::bound(std::uint64_t boxes) const {
  return forFace(boxes, 0.0, 0.0);
}

DirectionGrid::DirectionGrid(const glm::dvec3& apex, std::vector<GridWindow> windows,
                             const GridBoxes& boxes, const Limits& limits)
    : DirectionGrid(apex, std::move(windows), boxes, limits, nullptr, {}) {}

DirectionGrid::DirectionGrid(const glm::dvec3& apex, std::vector<GridWindow> windows,
                             const GridBoxes& boxes, const Limits& limits,
                             const FaceCells* cubeCells, std::span<const std::uint32_t> labels)
    : apex_(apex), windows_(std::move(windows)), cube_(cubeCells != nullptr) {
  windows_.resize(std::min<std::size_t>(windows_.size(), kMaxWindows));

  // Step 1: the scale of the scene as seen from the apex, which sets how
  // near a box must be to be listed everywhere, and how far a lookup may go.
  double reach = 0.0;
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const Bounds box = boxes[i];
    if (!finite(box)) continue;
    reach = std::max({reach, largestMagnitude(box.lo - apex_), largestMagnitude(box.hi - apex_)});
  }
  nearApex_ = kNearApex * reach;
  // Set once the grid is built: until then every lookup fails.
  double farLookup = boxes.empty() ? kInfinity : limits.farLookup * reach;

  // Step 2: the cells of each box, found once, giving up past the budget.
  BoxCells binned;
  if (!binBoxes(boxes, limits, cubeCells, binned)) return;
  const std::vector<CellRange>& ranges = binned.ranges;
  const std::vector<std::uint32_t>& firstRange = binned.firstRange;
  const std::array<bool, kMaxWindows>& used = binned.used;

  // Step 3: cells for the windows that some box reaches; the others share
  // one empty cell, the last.
  std::uint64_t cells = 0;
  for (std::size_t w = 0; w < windows_.size(); ++w) {
    firstCell_.push_back(static_cast<std::uint32_t>(cells));
    windowUsed_[w] = used[w];
    if (used[w]) {
      cells += static_cast<std::uint64_t>(windows_[w].columns) * windows_[w].rows;
    }
  }
  if (cells + 1 >= kNoCell) return;
  emptyCell_ = static_cast<std::uint32_t>(cells);
  firstCell_.push_back(static_cast<std::uint32_t>(++cells));
  setLookups();
  auto forEachCell = [&](const CellRange& r, auto&& visit) {
    std::uint64_t first = firstCell_[r.window];
    int columns = windows_[r.window].columns;
    for (int row = r.rowLow; row <= r.rowHigh; ++row) {
      std::uint64_t line = first + static_cast<std::uint64_t>(row) * columns;
      for (int column = r.columnLow; column <= r.columnHigh; ++column) visit(line + column);
    }
  };
  std::vector<std::uint32_t> counts(cells, 0);
  for (const CellRange& r : ranges) forEachCell(r, [&](std::uint64_t cell) { ++counts[cell]; });

  // Step 4: the lists, a full cell's left empty; counts becomes each
  // cell's next free place.
  full_.resize(cells);
  start_.resize(cells + 1);
  std::uint64_t total = 0;
  for (std::uint64_t c = 0; c < cells; ++c) {
    start_[c] = static_cast<std::uint32_t>(total);
    if (counts[c] > limits.perCell) {
      full_[c] = 1;
    } else {
      total += counts[c];
    }
    counts[c] = start_[c];
  }
  start_[cells] = static_cast<std::uint32_t>(total);
  items_.resize(total);
  for (std::uint32_t i = 0; i < boxes.size(); ++i) {
    std::uint32_t item = labels.empty() ? i : labels[i];
    for (std::uint32_t r = firstRange[i]; r < firstRange[i + 1]; ++r) {
      forEachCell(ranges[r], [&](std::uint64_t cell) {
        if (!full_[cell]) items_[counts[cell]++] = item;
      });
    }
  }
  farLookup_ = farLookup;
}

bool DirectionGrid::binBoxes(const GridBoxes& boxes, const Limits& limits,
                             const FaceCells* cubeCells, BoxCells& binned) {
  // A cube's faces are fitted to what their boxes reach first, and where
  // the boxes cover too many cells, cut a quarter as fine, then again,
  // down to kLeastRetryCells a face.
  std::array<FaceReach, kMaxWindows> reaching{};
  if (cube_) reaching = fitCubeFaces(boxes);
  FaceCells cut = cube_ ? *cubeCells : FaceCells{};
  // Room for a range per box and window it reaches, which a cube has
  // counted: room for one a box made the list grow where boxes are seen on
  // two faces, and its copy into twice the room took 3,000 more page
  // faults at 1,000,000 boxes.
  std::uint64_t reaches = 0;
  for (const FaceReach& face : reaching) reaches += face.boxes;
  binned.ranges.reserve(cube_ ? reaches : boxes.size());
  for (;;) {
    if (cube_) cutCubeFaces(reaching, cut);
    for (std::size_t w = 0; w < windows_.size(); ++w) {
      const GridWindow& win = windows_[w];
      scales_[w] =
          glm::dvec2(win.columns / (win.uHigh - win.uLow), win.rows / (win.vHigh - win.vLow));
    }
    if (coverBoxes(boxes, limits, binned)) return true;
    std::uint64_t finest = 0;
    for (const GridWindow& w : windows_) {
      finest = std::max<std::uint64_t>(finest, static_cast<std::uint64_t>(w.columns) * w.rows);
    }
    if (!cube_ || finest <= kLeastRetryCells) return false;
    cut =
        FaceCells{cut.perBox / 4.0, cut.perBoxArea / 4.0, std::max<std::uint64_t>(cut.least / 4, 1),
                  std::max<std::uint64_t>(cut.most / 4, 1)};
  }
}

void DirectionGrid::setLookups() {
  for (std::size_t w = 0; w < windows_.size(); ++w) {
    const GridWindow& win = windows_[w];
    WindowLookup& lookup = lookups_[w];
    if (windowUsed_[w]) {
      lookup = WindowLookup{win.uLow,     win.uHigh,     win.vLow,    win.vHigh, scales_[w].x,
                            scales_[w].y, firstCell_[w], win.columns, win.rows};
    }
    glm::dvec4 open = cube_ ? glm::dvec4(-1.0, 1.0, -1.0, 1.0)
                            : glm::dvec4(win.uLow, win.uHigh, win.vLow, win.vHigh);
    lookup.openULow = open.x;
    lookup.openUHigh = open.y;
    lookup.openVLow = open.z;
    lookup.openVHigh = open.w;
  }
}

bool DirectionGrid::coverBoxes(const GridBoxes& boxes, const Limits& limits,
                               BoxCells& binned) const {
  std::uint64_t windowCells = 0;
  for (const GridWindow& w : windows_) {
    windowCells += static_cast<std::uint64_t>(std::max(w.columns, 0)) * std::max(w.rows, 0);
  }
  // At most kNoCell - 1 entries in all, so that a cell's start fits its
  // 32 bits.
  std::uint64_t budget = std::min<std::uint64_t>(
      saturatingSum(saturatingProduct(limits.coverPerBox, boxes.size()), windowCells), kNoCell - 1);
  std::uint64_t covered = 0;
  binned.ranges.clear();
  binned.firstRange.assign(boxes.size() + 1, 0);
  binned.used.fill(false);
  for (std::uint32_t i = 0; i < boxes.size(); ++i) {
    binned.firstRange[i] = static_cast<std::uint32_t>(binned.ranges.size());
    bool over = false;
    forEachReach(boxes[i], [&](int window, const TangentRange& tangents) {
      CellRange r;
      if (over || !cover(tangents, window, r)) return;
      covered += static_cast<std::uint64_t>(r.columnHigh - r.columnLow + 1) *
                 static_cast<std::uint64_t>(r.rowHigh - r.rowLow + 1);
      if (covered > budget || binned.ranges.size() >= kNoCell) over = true;
      if (over) return;
      binned.ranges.push_back(r);
      binned.used[r.window] = true;
    });
    if (over) return false;
  }
  binned.firstRange[boxes.size()] = static_cast<std::uint32_t>(binned.ranges.size());
  return true;
}

DirectionGrid DirectionGrid::cubeAround(const glm::dvec3& apex, const GridBoxes& boxes,
                                        const FaceCells& cells, const Limits& limits,
                                        std::span<const std::uint32_t> labels) {
  std::vector<GridWindow> faces;
  for (int axis = 0; axis < 3; ++axis) {
    for (double sign : {1.0, -1.0}) {
      GridWindow face;
      face.forward = glm::dvec3(0.0);
      face.forward[axis] = sign;
      face.uAxis = glm::dvec3(0.0);
      face.uAxis[(axis + 1) % 3] = 1.0;
      face.vAxis = glm::dvec3(0.0);
      face.vAxis[(axis + 2) % 3] = 1.0;
      faces.push_back(face);
    }
  }
  if (labels.size() != boxes.size()) labels = {};
  return DirectionGrid(apex, std::move(faces), boxes, limits, &cells, labels);
}

DirectionGrid DirectionGrid::cubeAround(const glm::dvec3& apex, const GridBoxes& boxes,
                                        int resolution, const Limits& limits) {
  std::uint64_t side = static_cast<std::uint64_t>(std::max(resolution, 1));
  return cubeAround(apex, boxes, FaceCells{0.0, 0.0, side * side, side * side}, limits);
}

std::array<DirectionGrid::FaceReach, DirectionGrid::kMaxWindows> DirectionGrid::fitCubeFaces(
    const GridBoxes& boxes) {
  // Per face, the rectangle its boxes reach, widened by the margin as
  // their cells will be, how many reach it, and their areas within it.
  std::array<TangentRange, kMaxWindows> fitted;
  fitted.fill(TangentRange{kInfinity, -kInfinity, kInfinity, -kInfinity});
  std::array<FaceReach, kMaxWindows> reaching{};
  auto within = [](double from, double to) {
    return std::max(0.0, std::min(to, 1.0) - std::max(from, -1.0));
  };
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    forEachReach(boxes[i], [&](int w, const TangentRange& r) {
      TangentRange& f = fitted[w];
      f = TangentRange{std::min(f.uFrom, r.uFrom), std::max(f.uTo, r.uTo),
                       std::min(f.vFrom, r.vFrom), std::max(f.vTo, r.vTo)};
      ++reaching[w].boxes;
      reaching[w].area += within(r.uFrom, r.uTo) * within(r.vFrom, r.vTo);
    });
  }
  // Each face's window is that rectangle, within the face.
  for (std::size_t w = 0; w < windows_.size(); ++w) {
    GridWindow& win = windows_[w];
    const TangentRange& f = fitted[w];
    win.uLow = std::clamp(f.uFrom, -1.0, 1.0);
    win.uHigh = std::clamp(f.uTo, -1.0, 1.0);
    win.vLow = std::clamp(f.vFrom, -1.0, 1.0);
    win.vHigh = std::clamp(f.vTo, -1.0, 1.0);
    // A widened range is never a point, but one outside the face clamps
    // to its edge: such a face, and one no box reaches, is the whole face.
    if (reaching[w].boxes == 0 || !(win.uHigh > win.uLow && win.vHigh > win.vLow)) {
      win.uLow = win.vLow = -1.0;
      win.uHigh = win.vHigh = 1.0;
    }
  }
  return reaching;
}

void DirectionGrid::cutCubeFaces(const std::array<FaceReach, kMaxWindows>& reaching,
                                 const FaceCells& cells) {
  for (std::size_t w = 0; w < windows_.size(); ++w) {
    GridWindow& win = windows_[w];
    // A face that no box reaches keeps one cell, which no box covers.
    if (reaching[w].boxes == 0) {
      win.columns = win.rows = 1;
      continue;
    }
    double width = win.uHigh - win.uLow;
    double height = win.vHigh - win.vLow;
    cutRectangle(width, height, cells.forFace(reaching[w].boxes, reaching[w].area, width * height),
                 win.columns, win.rows);
  }
}

bool DirectionGrid::reachOnCube(const Bounds& box, int window, TangentRange& range) const {
  // The frame is the axes: f, a and b are the box's own intervals, apex
  // subtracted (for a -axis face, f's negated), and a / f over it is
  // extreme at the ends of a and f.
  int axis = window / 2;
  int uAxis = (axis + 1) % 3;
  int vAxis = (axis + 2) % 3;
  double f0 = window % 2 ? apex_[axis] - box.hi[axis] : box.lo[axis] - apex_[axis];
  double f1 = window % 2 ? apex_[axis] - box.lo[axis] : box.hi[axis] - apex_[axis];
  if (!(f1 > 0.0)) return false;
  auto tangentRange = [&](int along, double& from, double& to) {
    double a0 = box.lo[along] - apex_[along];
    double a1 = box.hi[along] - apex_[along];
    if (f0 > 0.0) {
      from = std::min(a0 / f0, a0 / f1);
      to = std::max(a1 / f0, a1 / f1);
    } else {
      // Reaching f = 0, as in reach.
      from = a0 < 0.0 ? -kInfinity : a0 / f1;
      to = a1 > 0.0 ? kInfinity : a1 / f1;
    }
  };
  tangentRange(uAxis, range.uFrom, range.uTo);
  tangentRange(vAxis, range.vFrom, range.vTo);
  return true;
}

bool DirectionGrid::reach(const Bounds& box, int window, TangentRange& range) const {
  if (cube_) return reachOnCube(box, window, range);
  const GridWindow& win = windows_[window];
  // The box's corners in the window's frame; a / f over a convex body lying
  // in f > 0 is extreme at its corners.
  double fMin = kInfinity, fMax = -kInfinity, aMin = kInfinity, aMax = -kInfinity;
  double bMin = kInfinity, bMax = -kInfinity, size = 0.0;
  double uFrom = kInfinity, uTo = -kInfinity, vFrom = kInfinity, vTo = -kInfinity;
  // The low corner's coordinates and the step to the high side on each
  // axis: each corner is their sum, within a rounding of the box's size,
  // which the margin covers.
  glm::dvec3 low = box.lo - apex_;
  glm::dvec3 extent = box.hi - box.lo;
  size = std::max(largestMagnitude(low), largestMagnitude(box.hi - apex_));
  glm::dvec3 base(glm::dot(win.forward, low), glm::dot(win.uAxis, low), glm::dot(win.vAxis, low));
  glm::dvec3 step[3];
  for (int i = 0; i < 3; ++i) {
    step[i] = glm::dvec3(win.forward[i], win.uAxis[i], win.vAxis[i]) * extent[i];
  }
  for (int k = 0; k < 8; ++k) {
    glm::dvec3 c = base;
    for (int i = 0; i < 3; ++i) {
      if (k >> i & 1) c += step[i];
    }
    double f = c.x, a = c.y, b = c.z;
    fMin = std::min(fMin, f);
    fMax = std::max(fMax, f);
    aMin = std::min(aMin, a);
    aMax = std::max(aMax, a);
    bMin = std::min(bMin, b);
    bMax = std::max(bMax, b);
    if (f > 0.0) {
      double inverse = 1.0 / f;
      uFrom = std::min(uFrom, a * inverse);
      uTo = std::max(uTo, a * inverse);
      vFrom = std::min(vFrom, b * inverse);
      vTo = std::max(vTo, b * inverse);
    }
  }
  if (!(fMax > 0.0)) return false;
  if (fMin <= 1e-9 * size) {
    // The box reaches the plane f = 0 through the apex, where a / f runs
    // off to the side of a's sign. Over the box of the corners' frame
    // coordinates, which holds the body, with 0 < f <= fMax: a / f is
    // unbounded below where a < 0 can be, and at least aMin / fMax
    // otherwise (the smallest a over the largest f); the same above.
    uFrom = aMin < 0.0 ? -kInfinity : aMin / fMax;
    uTo = aMax > 0.0 ? kInfinity : aMax / fMax;
    vFrom = bMin < 0.0 ? -kInfinity : bMin / fMax;
    vTo = bMax > 0.0 ? kInfinity : bMax / fMax;
  }
  range = TangentRange{uFrom, uTo, vFrom, vTo};
  return true;
}

template <typename Visit>
void DirectionGrid::forEachReach(const Bounds& box, Visit&& visit) const {
  // How far the box lies from the apex along each axis (0 where it spans
  // the apex's coordinate).
  glm::dvec3 away = glm::max(glm::max(box.lo - apex_, apex_ - box.hi), glm::dvec3(0.0));
  bool everywhere = !finite(box) || !(largestMagnitude(away) > nearApex_);
  for (int w = 0; w < static_cast<int>(windows_.size()); ++w) {
    if (everywhere) {
      visit(w, TangentRange{-kInfinity, kInfinity, -kInfinity, kInfinity});
      continue;
    }
    if (cube_) {
      // A cube face sees only directions within 45 degrees of its axis (a
      // lookup's |u| and |v| are at most 1, and a shadow ray's direction
      // strays from its lookup's by far less than 1e-5): a box nearer the
      // apex on another axis than its farthest reach along this one lies
      // outside it.
      int axis = w / 2;
      double ahead = w % 2 ? apex_[axis] - box.lo[axis] : box.hi[axis] - apex_[axis];
      double limit = ahead * (1.0 + 1e-5);
      if (!(ahead > 0.0) || away[(axis + 1) % 3] > limit || away[(axis + 2) % 3] > limit) {
        continue;
      }
    }
    TangentRange range;
    if (!reach(box, w, range)) continue;
    widen(range.uFrom, range.uTo);
    widen(range.vFrom, range.vTo);
    visit(w, range);
  }
}

bool DirectionGrid::cover(const TangentRange& range, int window, CellRange& cells) const {
  const GridWindow& win = windows_[window];
  if (win.columns <= 0 || win.rows <= 0) return false;
  cells.window = window;
  return cellSpan(range.uFrom, range.uTo, win.uLow, scales_[window].x, win.columns, cells.columnLow,
                  cells.columnHigh) &&
         cellSpan(range.vFrom, range.vTo, win.vLow, scales_[window].y, win.rows, cells.rowLow,
                  cells.rowHigh);
}

std::array<glm::dvec3, 4> DirectionGrid::cellCorners(std::uint32_t cell) const {
  int w = 0;
  while (w + 1 < static_cast<int>(windows_.size()) &&
         (!windowUsed_[w] || firstCell_[w + 1] <= cell)) {
    ++w;
  }
  const GridWindow& win = windows_[w];
  std::uint32_t local = cell - firstCell_[w];
  int column = static_cast<int>(local % win.columns);
  int row = static_cast<int>(local / win.columns);
  double du = (win.uHigh - win.uLow) / win.columns;
  double dv = (win.vHigh - win.vLow) / win.rows;
  std::array<glm::dvec3, 4> corners;
  if (cell == emptyCell_) corners.fill(glm::dvec3(0.0));
  if (cell == emptyCell_) return corners;
  for (int k = 0; k < 4; ++k) {
    double u = win.uLow + (column + (k & 1)) * du;
    double v = win.vLow + (row + (k >> 1)) * dv;
    corners[k] = win.forward + u * win.uAxis + v * win.vAxis;
  }
  return corners;
}

std::uint64_t DirectionGrid::bytes() const {
  return start_.size() * sizeof(std::uint32_t) + items_.size() * sizeof(std::uint32_t) +
         full_.size() + firstCell_.size() * sizeof(std::uint32_t);
}

}  // namespace render
