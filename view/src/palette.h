// Colours: labels to colours, and flat shading.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

#include "rdmesh/picture.h"

namespace rdmesh::view::detail {

/// `colour` scaled by `intensity` (0..1), rounded.
Rgb shade(Rgb colour, double intensity);

/// The distinct labels of one kind, sorted: a label's rank picks its colour,
/// so the same labels always get the same colours.
class LabelRanks {
 public:
  explicit LabelRanks(std::vector<int> labels);
  std::size_t rank(int label) const {
    return static_cast<std::size_t>(std::lower_bound(sorted_.begin(), sorted_.end(), label) -
                                    sorted_.begin());
  }
  const std::vector<int>& labels() const { return sorted_; }

 private:
  std::vector<int> sorted_;
};

}  // namespace rdmesh::view::detail
