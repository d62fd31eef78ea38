// Internal to cad/: which cells of a regular grid over the model's box meet a
// candidate box of the query accelerator. A segment whose bounding box meets
// no occupied cell meets no candidate box, so first_hit() answers "no
// crossing" without walking the candidate tree; most dual edges of cells away
// from the surface are such short segments.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "rdmesh/geometry.h"

namespace rdmesh::cad {

class OccupancyGrid {
 public:
  static constexpr int kCells = 128;  ///< per axis

  OccupancyGrid() = default;
  /// Marks every cell meeting one of `boxes` (the grid spans `box`). A box
  /// spanning more than kLargeBox fine cells is marked in the coarse grid
  /// (kCoarse^3 blocks of fine cells) instead: marking it cell by cell would
  /// cost up to kCells^3 operations.
  OccupancyGrid(const Box3& box, const std::vector<Box3>& boxes) : box_(box) {
    const Point3 size = box.hi - box.lo;
    const double s[3] = {size.x, size.y, size.z};
    for (int k = 0; k < 3; ++k) scale_[k] = s[k] > 0 ? kCells / s[k] : 0;
    fine_.assign(static_cast<std::size_t>(kCells) * kCells * kCells / 64, 0);
    coarse_.assign(static_cast<std::size_t>(kCoarse) * kCoarse * kCoarse, 0);
    for (const Box3& b : boxes) {
      int lo[3], hi[3];
      range(b, lo, hi);
      if (volume(lo, hi) > kLargeBox) {
        for (int k = 0; k < 3; ++k) lo[k] /= kBlock, hi[k] /= kBlock;
        for_each(lo, hi, [&](int i, int j, int k) {
          coarse_[(static_cast<std::size_t>(i) * kCoarse + j) * kCoarse + k] = 1;
          return false;
        });
        continue;
      }
      for_each(lo, hi, [&](int i, int j, int k) {
        const std::size_t n = index(i, j, k);
        fine_[n >> 6] |= std::uint64_t{1} << (n & 63);
        return false;
      });
    }
  }

  /// False when no occupied cell meets the box of segment [a, b] (then the
  /// segment meets no marked box); true when one does, or when the segment's
  /// box spans more than kMaxCells cells (not worth scanning).
  bool may_meet(const Point3& a, const Point3& b) const {
    if (fine_.empty()) return true;
    const Box3 s{{std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)},
                 {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)}};
    int lo[3], hi[3];
    range(s, lo, hi);
    if (volume(lo, hi) > kMaxCells) return true;
    const bool fine = for_each(lo, hi, [&](int i, int j, int k) {
      const std::size_t n = index(i, j, k);
      return ((fine_[n >> 6] >> (n & 63)) & 1) != 0;
    });
    if (fine) return true;
    for (int k = 0; k < 3; ++k) lo[k] /= kBlock, hi[k] /= kBlock;
    return for_each(lo, hi, [&](int i, int j, int k) {
      return coarse_[(static_cast<std::size_t>(i) * kCoarse + j) * kCoarse + k] != 0;
    });
  }

 private:
  static constexpr long kMaxCells = 64;
  static constexpr int kBlock = 8;  ///< fine cells per coarse cell, per axis
  static constexpr int kCoarse = kCells / kBlock;
  static constexpr long kLargeBox = 512;

  static long volume(const int lo[3], const int hi[3]) {
    return static_cast<long>(hi[0] - lo[0] + 1) * (hi[1] - lo[1] + 1) * (hi[2] - lo[2] + 1);
  }
  // Calls f(i, j, k) over the cells [lo, hi] until it returns true; whether it did.
  template <class F>
  static bool for_each(const int lo[3], const int hi[3], F&& f) {
    for (int i = lo[0]; i <= hi[0]; ++i) {
      for (int j = lo[1]; j <= hi[1]; ++j) {
        for (int k = lo[2]; k <= hi[2]; ++k) {
          if (f(i, j, k)) return true;
        }
      }
    }
    return false;
  }

  // The cells [lo, hi] (per axis, clamped to the grid) that box b meets. A box
  // reaching outside the grid is clamped to its border cells: whatever lies
  // there is conservatively in them.
  void range(const Box3& b, int lo[3], int hi[3]) const {
    const double l[3] = {b.lo.x - box_.lo.x, b.lo.y - box_.lo.y, b.lo.z - box_.lo.z};
    const double h[3] = {b.hi.x - box_.lo.x, b.hi.y - box_.lo.y, b.hi.z - box_.lo.z};
    for (int k = 0; k < 3; ++k) {
      lo[k] = clamp_cell(std::floor(l[k] * scale_[k]));
      hi[k] = clamp_cell(std::floor(h[k] * scale_[k]));
    }
  }
  static int clamp_cell(double c) {
    if (!(c > 0)) return 0;  // NaN too
    return c >= kCells - 1 ? kCells - 1 : static_cast<int>(c);
  }
  std::size_t index(int i, int j, int k) const {
    return (static_cast<std::size_t>(i) * kCells + j) * kCells + k;
  }
  Box3 box_{};
  double scale_[3] = {0, 0, 0};
  std::vector<std::uint64_t> fine_;   ///< a bit per fine cell
  std::vector<std::uint8_t> coarse_;  ///< a byte per coarse cell
};

}  // namespace rdmesh::cad
