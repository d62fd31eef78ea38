#include "edge_table.h"

#include <utility>

namespace rdmesh::detail {

void EdgeTable::reset(std::size_t edges) {
  std::size_t size = 64;
  while (size < 2 * edges) size *= 2;  // at most half full
  if (slots_.size() < size) slots_.resize(size);
  if (++gen_ == 0) {  // wrapped: empty every slot
    for (Edge& e : slots_) e.gen = 0;
    gen_ = 1;
  }
  used_.clear();
}

std::size_t EdgeTable::slot(Vertex_handle a, Vertex_handle b) const {
  // Any hash gives the same answers: it only decides where an edge is kept.
  const auto x = reinterpret_cast<std::uintptr_t>(&*a) >> 4;
  const auto y = reinterpret_cast<std::uintptr_t>(&*b) >> 4;
  const std::uint64_t h = x * 0x9E3779B97F4A7C15ull ^ y * 0xC2B2AE3D27D4EB4Full;
  const std::size_t mask = slots_.size() - 1;
  std::size_t i = static_cast<std::size_t>(h >> 32) & mask;
  while (slots_[i].gen == gen_ && (slots_[i].a != a || slots_[i].b != b)) i = (i + 1) & mask;
  return i;
}

void EdgeTable::add(Vertex_handle a, Vertex_handle b, int facet) {
  if (vertex_less(b, a)) std::swap(a, b);
  Edge& e = slots_[slot(a, b)];
  if (e.gen != gen_) {
    e = {a, b, {facet, -1}, 1, gen_};
    used_.push_back(static_cast<std::uint32_t>(&e - slots_.data()));
    return;
  }
  if (e.count < 2) e.facet[e.count] = facet;
  ++e.count;
}

bool EdgeTable::contains(Vertex_handle a, Vertex_handle b) const {
  if (vertex_less(b, a)) std::swap(a, b);
  return slots_[slot(a, b)].gen == gen_;
}

}  // namespace rdmesh::detail
