// The order in which exudation takes its vertices: space is cut into blocks
// along a Morton curve, the blocks are taken in curve order and, within a
// block, its vertices worst first. A block's stars fit in the cache, so the
// pumps of a block read memory that the ones before brought in, instead of
// jumping across the whole mesh as one worst-first queue over everything does
// once the mesh outgrows the cache.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "../triangulation_types.h"

namespace rdmesh::detail {

class SliverQueueOrder {
 public:
  /// Vertices per block, at least (and fewer than 8 times as many), measured
  /// on the unit sphere, one thread: blocks of 390 vertices (4096 blocks at
  /// 9.4 M tets) cut exudation from 19.5 to 14-16 s for 6% more pumps; 8
  /// times larger blocks gave 16.1-16.6 s, 64 times larger 17.5-19.0 s;
  /// blocks of 50 or 6 vertices pumped 11% and 22% more for no gain. At
  /// 1.2 M tets: 1.6-1.8 s against 2.0-2.1 s; at 146 k: 0.18 against 0.21 s.
  static constexpr std::size_t kVerticesPerBlock = 256;

  /// Blocks for `vertices` vertices in the box [lo, hi]: as many as the
  /// Morton curve's subdivisions allow with kVerticesPerBlock in each, one
  /// (plain worst first) for the smallest meshes.
  SliverQueueOrder(const Point3& lo, const Point3& hi, std::size_t vertices) : lo_(lo) {
    const double extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
    scale_ = extent > 0 ? static_cast<double>(kCells - 1) / extent : 0.0;
    std::size_t blocks = 1;
    while (block_bits_ < kMortonBits && vertices / (blocks * 8) >= kVerticesPerBlock) {
      blocks *= 8;
      block_bits_ += 3;
    }
  }

  /// The key of a vertex at p whose worst cell has cosine `cosine` (of its
  /// smallest dihedral angle; positive): larger keys are taken first.
  std::uint64_t key(double cosine, const Point3& p) const {
    const std::uint64_t block = morton(p) >> (kMortonBits - block_bits_);
    const std::uint64_t first = (std::uint64_t{1} << block_bits_) - 1 - block;
    // A positive double's bits grow with it: its top 40 rank the cosines.
    const std::uint64_t rank = std::bit_cast<std::uint64_t>(std::max(cosine, 0.0)) >> 24;
    return block_bits_ == 0 ? rank : first << 40 | rank;
  }

  /// log2 of the number of blocks (a multiple of 3: each halves every axis).
  int block_bits() const { return block_bits_; }

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
  int block_bits_ = 0;
};

}  // namespace rdmesh::detail
