// Private to core/: a refinement lane's cell queue: blocks of space along a
// Morton curve first, then BucketQueue's order (worst bucket, newest first)
// inside a block.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "bucket_queue.h"
#include "element_entry.h"
#include "morton_blocks.h"

namespace rdmesh::detail {

class LaneCellQueue {
 public:
  /// Takes the cells by `blocks` (nullptr: one block), which must outlive
  /// the queue's entries. The queue must be empty.
  void set_blocks(const MortonBlocks* blocks) {
    blocks_ = blocks;
    queues_.clear();
    queues_.resize(blocks == nullptr ? 1 : blocks->count());
    nonempty_.assign((queues_.size() + 63) / 64, 0);
  }
  bool empty() const { return size_ == 0; }
  std::size_t size() const { return size_; }
  /// Queues `e` in `bucket` (BucketQueue's) of the block of its cell's circumcentre.
  void push(std::size_t bucket, const ElementEntry& e) {
    if (queues_.empty()) set_blocks(blocks_);  // the first push, or after release()
    const std::size_t b = blocks_ == nullptr ? 0 : blocks_->block(e.cell->info().circumcenter);
    queues_[b].push(bucket, e);
    nonempty_[b / 64] |= std::uint64_t{1} << (b % 64);
    ++size_;
  }
  /// Removes and returns the next entry: of the first non-empty block in curve
  /// order, BucketQueue's next there. Not empty.
  ElementEntry pop() {
    std::size_t w = 0;
    while (nonempty_[w] == 0) ++w;
    const std::size_t b = w * 64 + static_cast<std::size_t>(std::countr_zero(nonempty_[w]));
    const ElementEntry e = queues_[b].pop();
    if (queues_[b].empty()) {
      queues_[b].release();
      nonempty_[w] &= ~(std::uint64_t{1} << (b % 64));
    }
    --size_;
    return e;
  }
  /// Empties the queue and frees its storage; it keeps its blocks.
  void release() {
    std::vector<BucketQueue<ElementEntry>>().swap(queues_);
    std::vector<std::uint64_t>().swap(nonempty_);
    size_ = 0;
  }

 private:
  const MortonBlocks* blocks_ = nullptr;
  std::vector<BucketQueue<ElementEntry>> queues_;
  std::vector<std::uint64_t> nonempty_;
  std::size_t size_ = 0;
};

}  // namespace rdmesh::detail
