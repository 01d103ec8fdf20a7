// Boxes binned by the direction in which they lie from one point, the apex,
// so that a ray leaving the apex, or aimed at it, tests only the objects of
// its direction's cell instead of walking the BVH: the light buffer of
// Haines and Greenberg (1986) for shadow rays toward a point light, and the
// same for the camera rays of a pinhole, which all leave the eye.
//
// A window is a rectangle of directions in the tangent plane of a frame:
// the directions w with f = forward . w > 0 whose tangent coordinates
// (uAxis . w / f, vAxis . w / f) lie in [uLow, uHigh] x [vLow, vHigh], cut
// into columns x rows cells. Six windows, on the faces of a cube, cover
// every direction from a light, each fitted to the rectangle its boxes
// reach (a lookup elsewhere on the face meets no box); one, the image's,
// covers a camera's rays.
//
// Conservative: a cell lists every box that meets its cone widened by
// kMargin in tangent coordinates (relative above 1), a million times the
// rounding of a lookup or of a box's corners (docs/TRACING.md, "Direction
// grids"). A cell that would list more than its limit lists nothing and is
// full: its rays walk the BVH, as do rays outside every window.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
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

// The boxes a grid is built over: a list, or `count` boxes made one by one
// (box i is boxOf(i), asked for once in each of the build's few passes),
// for a caller that need not hold them all.
class GridBoxes {
 public:
  // Implicit: a list is the usual case.
  GridBoxes(const std::vector<Bounds>& boxes) : list_(&boxes) {}
  GridBoxes(std::uint32_t count, std::function<Bounds(std::uint32_t)> boxOf)
      : count_(count), boxOf_(std::move(boxOf)) {}
  std::size_t size() const { return list_ ? list_->size() : count_; }
  bool empty() const { return size() == 0; }
  Bounds operator[](std::size_t i) const {
    return list_ ? (*list_)[i] : boxOf_(static_cast<std::uint32_t>(i));
  }

 private:
  const std::vector<Bounds>* list_ = nullptr;
  std::uint32_t count_ = 0;
  std::function<Bounds(std::uint32_t)> boxOf_;
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
  /// its direction by more than the margin (docs/TRACING.md).
  static constexpr double kNearApex = 1e-7;
  /// Lookups farther from the apex than this multiple of the farthest box
  /// corner are not answered (the BVH answers them), for the same reason:
  /// kNearApex and kFarLookup keep a shadow ray's direction within 3e-7
  /// (relative) of the lookup's.
  static constexpr double kFarLookup = 100.0;
  /// The most cells a cube face gets, whatever FaceCells asks for.
  static constexpr std::uint64_t kMaxFaceCells = std::uint64_t{1} << 26;
  /// Where a cube's boxes cover more cells than Limits allows, its faces
  /// are cut a quarter as fine, and again, until they fit or no face has
  /// more cells than this: then it has no grid.
  static constexpr std::uint64_t kLeastRetryCells = 1024;

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

  /// How cubeAround cuts each face of its cube: the rectangle of the face
  /// that its boxes reach, in cells about square, `perBox` for each box
  /// that reaches the face, but no more than `perBoxArea` in the area of
  /// the mean box there (boxes that overlap, seen from the apex, need no
  /// more cells than they cover), at least `least` and at most `most`.
  struct FaceCells {
    double perBox = 8.0;
    double perBoxArea = 8.0;
    std::uint64_t least = 1;
    std::uint64_t most = std::uint64_t{1} << 20;
    /// The cells for a face that `boxes` boxes reach, whose tangent areas
    /// (within the face) add up to `boxArea` of the face's `area`.
    std::uint64_t forFace(std::uint64_t boxes, double boxArea, double area) const;
    /// The most cells a face can get where `boxes` boxes reach it.
    std::uint64_t bound(std::uint64_t boxes) const;
  };

  DirectionGrid() = default;
  /// Bins `boxes` (item i is boxes[i]) as seen from `apex` in `windows`.
  DirectionGrid(const glm::dvec3& apex, std::vector<GridWindow> windows, const GridBoxes& boxes,
                const Limits& limits);
  /// Six windows on the faces of a cube around `apex`, in the order
  /// cubeWindowOf numbers them, each the rectangle of its face that the
  /// boxes reach, cut as `cells` says. Box k is listed as item labels[k]
  /// (as item k where `labels` is empty or of another size): boxes in a
  /// BVH's order, labelled by its items, cover cells near those of the
  /// box before, which makes the build quicker than boxes at random.
  static DirectionGrid cubeAround(const glm::dvec3& apex, const GridBoxes& boxes,
                                  const FaceCells& cells, const Limits& limits,
                                  std::span<const std::uint32_t> labels = {});
  /// cubeAround with about resolution x resolution cells on each face
  /// that a box reaches.
  static DirectionGrid cubeAround(const glm::dvec3& apex, const GridBoxes& boxes, int resolution,
                                  const Limits& limits);

  /// False when the boxes would cover more cells than the limits allow:
  /// then every lookup answers kNoCell.
  bool built() const { return !start_.empty(); }
  const glm::dvec3& apex() const { return apex_; }
  const std::vector<GridWindow>& windows() const { return windows_; }
  std::uint32_t cellCount() const { return static_cast<std::uint32_t>(full_.size()); }

  /// The cell of window `window` that the direction w from the apex falls
  /// in, or kNoCell where the grid cannot answer (w outside the window,
  /// for a cube outside the face, too long, not a number, or the grid not
  /// built).
  std::uint32_t cellOf(int window, const glm::dvec3& w) const {
    if (start_.empty() || !(largestMagnitude(w) <= farLookup_)) return kNoCell;
    const GridWindow& win = windows_[window];
    double f = glm::dot(win.forward, w);
    if (!(f > 0.0)) return kNoCell;
    // One division for both coordinates: a rounding apart from a / f,
    // within the margin.
    double inverse = 1.0 / f;
    return cellAt(window, glm::dot(win.uAxis, w) * inverse, glm::dot(win.vAxis, w) * inverse);
  }
  /// The cube face of cubeAround that holds w: 2 * axis of its largest
  /// component (the lowest axis on a tie), plus 1 where that is negative.
  static int cubeWindowOf(const glm::dvec3& w) {
    int axis = std::abs(w.y) > std::abs(w.x) ? 1 : 0;
    if (std::abs(w.z) > std::abs(w[axis])) axis = 2;
    return 2 * axis + (w[axis] < 0.0 ? 1 : 0);
  }
  /// cellOf(cubeWindowOf(w), w) for a grid made by cubeAround, in fewer
  /// steps: the frame's dot products are its components, the same values.
  std::uint32_t cubeCellOf(const glm::dvec3& w) const {
    double ax = std::abs(w.x), ay = std::abs(w.y), az = std::abs(w.z);
    int axis = ay > ax ? 1 : 0;
    double f = axis ? ay : ax;
    if (az > f) {
      axis = 2;
      f = az;
    }
    // Not a number fails both tests, as does every lookup before the grid
    // is built (farLookup_ below 0).
    if (!(f <= farLookup_ && f > 0.0)) return kNoCell;
    double inverse = 1.0 / f;
    return cellAt(2 * axis + (w[axis] < 0.0 ? 1 : 0), w[axis == 2 ? 0 : axis + 1] * inverse,
                  w[axis == 0 ? 2 : axis - 1] * inverse);
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
  // The tangent coordinates a box reaches on a window, widened by the
  // margin; infinite on the sides where it is unbounded.
  struct TangentRange {
    double uFrom, uTo, vFrom, vTo;
  };
  // With `cubeCells`: the windows are the faces of cubeAround, each fitted
  // to what its boxes reach.
  DirectionGrid(const glm::dvec3& apex, std::vector<GridWindow> windows, const GridBoxes& boxes,
                const Limits& limits, const FaceCells* cubeCells,
                std::span<const std::uint32_t> labels);
  // The cell of tangent point (u, v) on window `window`: kNoCell outside
  // the window (a cube's face: outside the face), the empty cell on a
  // cube's face outside the rectangle its boxes reach.
  std::uint32_t cellAt(int window, double u, double v) const {
    const WindowLookup& w = lookups_[window];
    if (u >= w.uLow && u <= w.uHigh && v >= w.vLow && v <= w.vHigh) {
      // The same formula as a box's cells (cellSpan), which only grows
      // with u, clamped as they are.
      int column = std::min(static_cast<int>((u - w.uLow) * w.uScale), w.columns - 1);
      int row = std::min(static_cast<int>((v - w.vLow) * w.vScale), w.rows - 1);
      return w.firstCell + static_cast<std::uint32_t>(row) * w.columns +
             static_cast<std::uint32_t>(column);
    }
    // Not a number fails both tests.
    bool answered = u >= w.openULow && u <= w.openUHigh && v >= w.openVLow && v <= w.openVHigh;
    return answered ? emptyCell_ : kNoCell;
  }
  // The cells each box covers: per box, its first range, and per window
  // whether any box covers it.
  struct BoxCells {
    std::vector<CellRange> ranges;
    std::vector<std::uint32_t> firstRange;
    std::array<bool, kMaxWindows> used{};
  };
  // The boxes that reach a cube face, and the sum of their tangent areas
  // there.
  struct FaceReach {
    std::uint64_t boxes = 0;
    double area = 0.0;
  };
  // Fits each cube face to the rectangle its boxes reach.
  std::array<FaceReach, kMaxWindows> fitCubeFaces(const GridBoxes& boxes);
  // Cuts each fitted face as `cells` says for the boxes that reach it.
  void cutCubeFaces(const std::array<FaceReach, kMaxWindows>& reaching, const FaceCells& cells);
  // Bins the boxes into `binned` with the windows as they are, or false
  // where they cover more cells than `limits` allows.
  bool coverBoxes(const GridBoxes& boxes, const Limits& limits, BoxCells& binned) const;
  // Cuts a cube's faces (fitted, then coarser while the boxes cover too
  // much) and bins the boxes; false where they cannot be binned.
  bool binBoxes(const GridBoxes& boxes, const Limits& limits, const FaceCells* cubeCells,
                BoxCells& binned);
  // Fills lookups_ from the windows, once their cells are numbered.
  void setLookups();
  // What a box reaches on one window, or false for nothing.
  bool reach(const Bounds& box, int window, TangentRange& range) const;
  bool reachOnCube(const Bounds& box, int window, TangentRange& range) const;
  // Calls visit(window, range) for each window the box reaches.
  template <typename Visit>
  void forEachReach(const Bounds& box, Visit&& visit) const;
  // The cells of `range` on window `window`, or false for none.
  bool cover(const TangentRange& range, int window, CellRange& cells) const;

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
  // What a lookup on a window reads, side by side: the rectangle cut into
  // cells (none where no box reaches the window), its scales and cells,
  // and where lookups are answered (the window's own rectangle, or for a
  // cube the face).
  struct WindowLookup {
    double uLow = 1.0, uHigh = -1.0, vLow = 1.0, vHigh = -1.0;
    double uScale = 0.0, vScale = 0.0;
    std::uint32_t firstCell = 0;
    int columns = 0, rows = 0;
    double openULow = 1.0, openUHigh = -1.0, openVLow = 1.0, openVHigh = -1.0;
  };
  std::array<WindowLookup, kMaxWindows> lookups_{};
  bool cube_ = false;
  std::vector<std::uint32_t> start_;  // per cell, then the end
  std::vector<std::uint32_t> items_;
  std::vector<std::uint8_t> full_;
};

}  // namespace render
