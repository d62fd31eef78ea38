// Private to core/: the refiner's queue of bad elements, a 4-ary max-heap.
//
// The cell queue sees millions of pushes and pops per million tetrahedra,
// most of them for cells destroyed before their turn (lazy deletion). A
// 4-ary heap halves the depth of std::priority_queue's binary heap, and with
// it the cache misses of every pop, while popping the very same sequence: the
// order is fixed by `Less` alone whenever entries that compare equal are
// interchangeable (the refiner's entries are: equal priority and stamp means
// the same cell).
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

namespace rdmesh::detail {

template <class T, class Less = std::less<T>>
class WorstFirstHeap {
 public:
  bool empty() const { return items_.empty(); }
  std::size_t size() const { return items_.size(); }
  /// The greatest entry (by Less).
  const T& top() const { return items_.front(); }

  void push(const T& item) {
    std::size_t i = items_.size();
    items_.push_back(item);
    while (i > 0) {
      const std::size_t parent = (i - 1) / kArity;
      if (!less_(items_[parent], item)) break;
      items_[i] = std::move(items_[parent]);
      i = parent;
    }
    items_[i] = item;
  }

  void pop() {
    T last = std::move(items_.back());
    items_.pop_back();
    const std::size_t n = items_.size();
    if (n == 0) return;
    std::size_t i = 0;
    for (;;) {
      const std::size_t first = kArity * i + 1;
      if (first >= n) break;
      std::size_t best = first;
      const std::size_t end = first + kArity < n ? first + kArity : n;
      for (std::size_t c = first + 1; c < end; ++c) {
        if (less_(items_[best], items_[c])) best = c;
      }
      if (!less_(last, items_[best])) break;
      items_[i] = std::move(items_[best]);
      i = best;
    }
    items_[i] = std::move(last);
  }

  /// Frees the storage (the queue is empty at the end of refinement).
  void release() { std::vector<T>().swap(items_); }

 private:
  static constexpr std::size_t kArity = 4;
  std::vector<T> items_;
  Less less_;
};

}  // namespace rdmesh::detail
