#include "node_tags.h"

#include <algorithm>

namespace rdmesh::view::detail {

bool NodeTags::build(const std::vector<std::int64_t>& tags) {
  dense_.clear();
  sorted_.clear();
  std::int64_t max_tag = 0;
  for (std::int64_t t : tags) {
    if (t < 1) return false;
    max_tag = std::max(max_tag, t);
  }
  const auto n = static_cast<std::int64_t>(tags.size());
  if (max_tag <= 4 * n + 1024) {
    dense_.assign(static_cast<std::size_t>(max_tag) + 1, -1);
    for (std::size_t i = 0; i < tags.size(); ++i) {
      int& slot = dense_[static_cast<std::size_t>(tags[i])];
      if (slot != -1) return false;
      slot = static_cast<int>(i);
    }
    return true;
  }
  sorted_.reserve(tags.size());
  for (std::size_t i = 0; i < tags.size(); ++i) sorted_.emplace_back(tags[i], static_cast<int>(i));
  std::sort(sorted_.begin(), sorted_.end());
  return std::adjacent_find(sorted_.begin(), sorted_.end(), [](const auto& a, const auto& b) {
           return a.first == b.first;
         }) == sorted_.end();
}

int NodeTags::find(std::int64_t tag) const {
  if (!dense_.empty() || sorted_.empty()) {
    return tag >= 0 && static_cast<std::uint64_t>(tag) < dense_.size()
               ? dense_[static_cast<std::size_t>(tag)]
               : -1;
  }
  auto it = std::lower_bound(sorted_.begin(), sorted_.end(), std::pair<std::int64_t, int>(tag, -1));
  return it != sorted_.end() && it->first == tag ? it->second : -1;
}

}  // namespace rdmesh::view::detail
