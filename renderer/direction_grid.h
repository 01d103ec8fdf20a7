// Boxes binned by the direction in which they lie from one point, the apex,
// so that a ray leaving the apex, or aimed at it, tests only the objects of
// its direction's cell instead of walking the BVH: the light buffer of
// Haines and Greenberg (1986) for shadow rays toward a point light, and the
// same for the camera rays of a pinhole, which all leave the eye.
//
// A window is a rectangle of directions in the tangent plane of a frame:
// the directions w with f = forward . w > 0 whose tangent coordinates
// (uAxis . w / f, vAxis . w / f) lie in [uLow, uHigh] x [vLow, vHigh], cut
// into columns x rows cells. Six windows, the faces of a cube, cover every
// direction from a light; one, the image's, covers a camera's rays.
//
// Conservative: a cell lists every box that meets its cone widened by
// kMargin in tangent coordinates (relative above 1), a million times the
// rounding of a lookup or of a box's corners (docs/RENDERING.md, "Direction
// grids"). A cell that would list more than its limit lists nothing and is
// full: its rays walk the BVH, as do rays outside every window.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <span>
#include <vector>

#include "renderer/bounds.h"

namespace render {

struct GridWindow {
  glm::dvec3 forward{0.0, 0.0, 1.0};
  glm::dvec3 uAxis{1.0, 0.0, 0.0};
  glm::dvec3 vAxis{0.0, 1.0, 0.0};
  double uLow = -1.0, uHigh = 1.0, vLow = -1.0, vHigh = 1.0;
  int columns = 1, rows = 1;
};

class DirectionGrid {
 public:
  static double largestMagnitude(const glm::dvec3& v) {
    return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
  }
  static constexpr std::uint32_t kNoCell = 0xFFFFFFFF;
  /// The most windows a grid has (a cube's six); more are left out.
  static constexpr int kMaxWindows = 6;
  /// What the build holds for each range of cells a box covers, while it
  /// runs (RenderScene::bytesFor).
  static constexpr std::uint64_t kRangeBytes = 5 * sizeof(int);
  static constexpr double kMargin = 1e-6;
  /// Boxes nearer the apex than this fraction of the farthest box corner
  /// are listed in every cell: near the apex, a shadow ray's rounding moves
  /// its direction by more than the margin (docs/RENDERING.md).
  static constexpr double kNearApex = 1e-7;
  /// Lookups farther from the apex than this multiple of the farthest box
  /// corner are not answered (the BVH answers them), for the same reason:
  /// kNearApex and kFarLookup keep a shadow ray's direction within 3e-7
  /// (relative) of the lookup's.
  static constexpr double kFarLookup = 100.0;

  struct Limits {
    /// The most boxes a cell lists.
    std::uint32_t perCell = 16;
    /// The most cells all boxes may cover together, as a multiple of the
    /// box count (plus the cell count): past it the grid is not built.
    std::uint64_t coverPerBox = 16;
    /// kFarLookup, or infinity for rays that leave the apex itself (camera
    /// rays), whose directions carry no rounding from it.
    double farLookup = kFarLookup;
  };

  DirectionGrid() = default;
  /// Bins `boxes` (item i is boxes[i]) as seen from `apex` in `windows`.
  DirectionGrid(const glm::dvec3& apex, std::vector<GridWindow> windows,
                const std::vector<Bounds>& boxes, const Limits& limits);
  /// Six windows of resolution x resolution cells, the faces of a cube
  /// around `apex`, in the order cubeWindowOf numbers them.
  static DirectionGrid cubeAround(const glm::dvec3& apex, const std::vector<Bounds>& boxes,
                                  int resolution, const Limits& limits);

  /// False when the boxes would cover more cells than the limits allow:
  /// then every lookup answers kNoCell.
  bool built() const { return !start_.empty(); }
  const glm::dvec3& apex() const { return apex_; }
  const std::vector<GridWindow>& windows() const { return windows_; }
  std::uint32_t cellCount() const { return static_cast<std::uint32_t>(full_.size()); }

  /// The cell of window `window` that the direction w from the apex falls
  /// in, or kNoCell where the grid cannot answer (w outside the window, too
  /// long, not a number, or the grid not built).
  std::uint32_t cellOf(int window, const glm::dvec3& w) const {
    if (start_.empty() || !(largestMagnitude(w) <= farLookup_)) return kNoCell;
    const GridWindow& win = windows_[window];
    double f = glm::dot(win.forward, w);
    if (!(f > 0.0)) return kNoCell;
    // One division for both coordinates: a rounding apart from a / f,
    // within the margin.
    double inverse = 1.0 / f;
    double x = (glm::dot(win.uAxis, w) * inverse - win.uLow) * scales_[window].x;
    double y = (glm::dot(win.vAxis, w) * inverse - win.vLow) * scales_[window].y;
    if (!(x >= 0.0 && x < win.columns && y >= 0.0 && y < win.rows)) return kNoCell;
    if (!windowUsed_[window]) return emptyCell_;
    return firstCell_[window] + static_cast<std::uint32_t>(y) * win.columns +
           static_cast<std::uint32_t>(x);
  }
  /// The cube face of cubeAround that holds w: 2 * axis of its largest
  /// component (the lowest axis on a tie), plus 1 where that is negative.
  static int cubeWindowOf(const glm::dvec3& w) {
    int axis = std::abs(w.y) > std::abs(w.x) ? 1 : 0;
    if (std::abs(w.z) > std::abs(w[axis])) axis = 2;
    return 2 * axis + (w[axis] < 0.0 ? 1 : 0);
  }
  /// cellOf(cubeWindowOf(w), w) for a grid made by cubeAround, in fewer
  /// steps: the frame's dot products are its components, and one division
  /// serves both coordinates (a rounding apart from cellOf's, within the
  /// margin).
  std::uint32_t cubeCellOf(const glm::dvec3& w) const {
    double ax = std::abs(w.x), ay = std::abs(w.y), az = std::abs(w.z);
    int axis = ay > ax ? 1 : 0;
    double f = axis ? ay : ax;
    if (az > f) {
      axis = 2;
      f = az;
    }
    // Not a number fails both tests.
    if (!(f <= farLookup_ && f > 0.0)) return kNoCell;
    double inverse = 1.0 / f;
    double x = (w[axis == 2 ? 0 : axis + 1] * inverse + 1.0) * cubeScale_;
    double y = (w[axis == 0 ? 2 : axis - 1] * inverse + 1.0) * cubeScale_;
    if (!(x >= 0.0 && x < cubeResolution_ && y >= 0.0 && y < cubeResolution_)) return kNoCell;
    int window = 2 * axis + (w[axis] < 0.0 ? 1 : 0);
    if (!windowUsed_[window]) return emptyCell_;
    return firstCell_[window] + static_cast<std::uint32_t>(y) * cubeResolution_ +
           static_cast<std::uint32_t>(x);
  }

  bool full(std::uint32_t cell) const { return full_[cell] != 0; }
  /// The items a cell lists (none for a full cell).
  std::span<const std::uint32_t> items(std::uint32_t cell) const {
    return {items_.data() + start_[cell], items_.data() + start_[cell + 1]};
  }
  std::span<std::uint32_t> mutableItems(std::uint32_t cell) {
    return {items_.data() + start_[cell], items_.data() + start_[cell + 1]};
  }
  /// The directions through the four corners of a cell.
  std::array<glm::dvec3, 4> cellCorners(std::uint32_t cell) const;

  /// What the grid holds, in bytes.
  std::uint64_t bytes() const;

 private:
  struct CellRange {
    int window;
    int columnLow, columnHigh, rowLow, rowHigh;
  };
  static_assert(sizeof(CellRange) <= kRangeBytes);
  // cubeResolution > 0: the windows are the faces of cubeAround.
  DirectionGrid(const glm::dvec3& apex, std::vector<GridWindow> windows,
                const std::vector<Bounds>& boxes, const Limits& limits, int cubeResolution);
  // The cells a box covers on one window, or false for none.
  bool cover(const Bounds& box, int window, CellRange& range) const;
  bool coverOnCube(const Bounds& box, int window, CellRange& range) const;
  template <typename Visit>
  void forEachCover(const Bounds& box, Visit&& visit) const;

  glm::dvec3 apex_{0.0};
  std::vector<GridWindow> windows_;
  // Per window, its first cell, then the total; a window that no box
  // reaches has no cells of its own, and its lookups get emptyCell_.
  std::vector<std::uint32_t> firstCell_;
  std::array<bool, kMaxWindows> windowUsed_{};
  // Per window, cells per unit of u and of v: the one factor by which both
  // a box's range and a lookup become cells.
  std::array<glm::dvec2, kMaxWindows> scales_{};
  std::uint32_t emptyCell_ = 0;
  double nearApex_ = 0.0;
  double farLookup_ = -1.0;  // no lookup succeeds until the grid is built
  int cubeResolution_ = 0;
  double cubeScale_ = 0.0;
  std::vector<std::uint32_t> start_;  // per cell, then the end
  std::vector<std::uint32_t> items_;
  std::vector<std::uint8_t> full_;
};

}  // namespace render
