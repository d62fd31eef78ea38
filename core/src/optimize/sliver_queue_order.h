// The order in which exudation takes its vertices: space is cut into blocks
// along a Morton curve, the blocks are taken in curve order and, within a
// block, its vertices worst first. A block's stars fit in the cache, so the
// pumps of a block read memory that the ones before brought in, instead of
// jumping across the whole mesh as one worst-first queue over everything does
// once the mesh outgrows the cache.
#pragma once

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>

#include "../morton_blocks.h"

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
  SliverQueueOrder(const Point3& lo, const Point3& hi, std::size_t vertices)
      : blocks_(lo, hi,
                MortonBlocks::bits_for(static_cast<double>(vertices),
                                       static_cast<double>(kVerticesPerBlock))) {}

  /// The key of a vertex at p whose worst cell has cosine `cosine` (of its
  /// smallest dihedral angle; positive): larger keys are taken first.
  std::uint64_t key(double cosine, const Point3& p) const {
    const std::uint64_t first = blocks_.count() - 1 - blocks_.block(p);
    // A positive double's bits grow with it: its top 40 rank the cosines.
    const std::uint64_t rank = std::bit_cast<std::uint64_t>(std::max(cosine, 0.0)) >> 24;
    return first << 40 | rank;
  }

  /// log2 of the number of blocks (a multiple of 3: each halves every axis).
  int block_bits() const { return blocks_.bits(); }

 private:
  MortonBlocks blocks_;
};

}  // namespace rdmesh::detail
