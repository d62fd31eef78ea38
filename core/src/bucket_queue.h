// Private to core/: a worst-first queue that serves buckets, and inside a
// bucket the newest entry first.
//
// A strict worst-first heap visits the refiner's cells (or the exuder's
// vertices) in priority order, which is no order in space: at a million cells
// nearly every pop lands on a cold cell. Here the caller groups the priorities
// in buckets (a fixed width on a log or angle scale), the worst non-empty
// bucket is served first, and inside it the entry pushed last comes first:
// most often one that the previous step has just created, whose cells and
// vertices are still in cache. Push and pop cost O(1) instead of O(log n).
// The order is fixed by the sequence of pushes alone, so runs stay
// deterministic.
#pragma once

#include <cstddef>
#include <vector>

namespace rdmesh::detail {

template <class T>
class BucketQueue {
 public:
  bool empty() const { return size_ == 0; }
  std::size_t size() const { return size_; }

  /// Queues `item` in `bucket` (larger = served earlier).
  void push(std::size_t bucket, const T& item) {
    if (bucket >= buckets_.size()) buckets_.resize(bucket + 1);
    buckets_[bucket].push_back(item);
    if (bucket > top_ || size_ == 0) top_ = bucket;
    ++size_;
  }

  /// Removes and returns the newest entry of the worst non-empty bucket. Not empty.
  T pop() {
    std::vector<T>& bucket = buckets_[top_];
    const T item = bucket.back();
    bucket.pop_back();
    // A drained bucket gives its storage back: buckets peak one after the
    // other, and their capacities would add up.
    if (bucket.empty()) std::vector<T>().swap(bucket);
    --size_;
    while (top_ > 0 && buckets_[top_].empty()) --top_;
    return item;
  }

  /// Empties the queue and frees its storage.
  void release() {
    std::vector<std::vector<T>>().swap(buckets_);
    top_ = 0;
    size_ = 0;
  }

 private:
  std::vector<std::vector<T>> buckets_;
  std::size_t top_ = 0;  ///< the worst non-empty bucket, when size_ > 0
  std::size_t size_ = 0;
};

}  // namespace rdmesh::detail
