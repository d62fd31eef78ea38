// Private to core/: blocks of a box along a Morton curve, for queues that
// take their elements block by block so that consecutive steps read nearby
// cells (lane_cell_queue.h, optimize/sliver_queue_order.h). Each
// subdivision halves the three axes: 8^k blocks of the box's cube.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>

#include "rdmesh/geometry.h"

namespace rdmesh::detail {

class MortonBlocks {
 public:
  /// log2 of the block count (a multiple of 3) for `items` spread over the box
  /// with at least `per_block` of them in a block (one block for fewer than
  /// 8 per_block items); at most 2^max_bits blocks (max_bits <= 24).
  static int bits_for(double items, double per_block, int max_bits = kMortonBits) {
    int bits = 0;
    double blocks = 1;
    while (bits + 3 <= std::min(max_bits, kMortonBits) && items / (blocks * 8) >= per_block) {
      blocks *= 8;
      bits += 3;
    }
    return bits;
  }

  MortonBlocks() = default;
  /// 2^bits blocks of the cube of the box [lo, hi] (anchored at lo).
  MortonBlocks(const Point3& lo, const Point3& hi, int bits) : lo_(lo), bits_(bits) {
    const double extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
    scale_ = extent > 0 ? static_cast<double>(kCells - 1) / extent : 0.0;
  }

  int bits() const { return bits_; }
  std::size_t count() const { return std::size_t{1} << bits_; }
  /// The block of p, in curve order (points outside the box: the nearest block).
  std::uint64_t block(const Point3& p) const { return morton(p) >> (kMortonBits - bits_); }

 private:
  static constexpr int kAxisBits = 8;
  static constexpr int kMortonBits = 3 * kAxisBits;
  static constexpr std::uint64_t kCells = std::uint64_t{1} << kAxisBits;

  /// Spreads the low 8 bits of x two bits apart.
  static std::uint64_t spread(std::uint64_t x) {
    x &= 0xff;
    x = (x | x << 8) & 0x00f00fULL;
    x = (x | x << 4) & 0x0c30c3ULL;
    x = (x | x << 2) & 0x249249ULL;
    return x;
  }

  std::uint64_t cell(double value, double lo) const {
    const double c = std::clamp((value - lo) * scale_, 0.0, static_cast<double>(kCells - 1));
    return static_cast<std::uint64_t>(c);
  }

  std::uint64_t morton(const Point3& p) const {
    return spread(cell(p.x, lo_.x)) | spread(cell(p.y, lo_.y)) << 1 | spread(cell(p.z, lo_.z)) << 2;
  }

  Point3 lo_;
  double scale_ = 0;
  int bits_ = 0;
};

}  // namespace rdmesh::detail
