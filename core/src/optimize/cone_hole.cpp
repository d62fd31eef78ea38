#include "cone_hole.h"

#include "rdmesh/errors.h"

namespace rdmesh::detail {

void CellPool::fill(std::size_t n) {
  while (cells_.size() < n) cells_.push_back(tr_.tds().create_cell());
}

void CellPool::release() {
  for (const Cell_handle& c : cells_) tr_.tds().delete_cell(c);
  cells_.clear();
}

Cell_handle CellPool::take() {
  if (cells_.empty()) throw InternalError("cone_hole: a cell pool ran out");
  const Cell_handle c = cells_.back();
  cells_.pop_back();
  return c;
}

void ConeBuilder::build(Triangulation& tr, const std::vector<Cell_handle>& hole,
                        const std::vector<HoleFacet>& boundary, Vertex_handle v, CellPool* pool,
                        std::vector<Cell_handle>& created) {
  // Everything read from the hole first: its cells are overwritten below.
  planned_.resize(boundary.size());
  edges_.reset(3 * boundary.size());
  const Vertex_handle infinite = tr.infinite_vertex();
  bool touches_infinite = false;
  for (std::size_t k = 0; k < boundary.size(); ++k) {
    const Cell_handle c = boundary[k].inner;
    const int i = boundary[k].index;
    Planned& p = planned_[k];
    for (int j = 0; j < 4; ++j) p.vertices[j] = j == i ? v : c->vertex(j);
    p.outer = c->neighbor(i);
    p.outer_index = p.outer->index(c);
    p.apex = i;
    const Vertex_handle w[3] = {c->vertex((i + 1) & 3), c->vertex((i + 2) & 3),
                                c->vertex((i + 3) & 3)};
    for (int j = 0; j < 3; ++j) {
      edges_.add(w[j], w[(j + 1) % 3], static_cast<int>(k));
      touches_infinite = touches_infinite || w[j] == infinite;
    }
  }
  // The infinite vertex's cell is rewritten only when the hole held it: two
  // lanes never both do (the exuder points it at a cell neither lane owns).
  bool infinite_cell_in_hole = false;
  if (touches_infinite)
    for (const Cell_handle& c : hole) infinite_cell_in_hole |= c == infinite->cell();

  created.resize(boundary.size());
  for (std::size_t k = 0; k < boundary.size(); ++k) {
    if (k < hole.size()) {
      created[k] = hole[k];
    } else {
      created[k] = pool != nullptr ? pool->take() : tr.tds().create_cell();
    }
  }
  for (std::size_t k = boundary.size(); k < hole.size(); ++k) {
    if (pool != nullptr) {
      hole[k]->info() = CellInfo();
      hole[k]->tds_data().clear();
      pool->give(hole[k]);
    } else {
      tr.tds().delete_cell(hole[k]);
    }
  }
  for (std::size_t k = 0; k < boundary.size(); ++k) {
    const Planned& p = planned_[k];
    const Cell_handle c = created[k];
    c->set_vertices(p.vertices[0], p.vertices[1], p.vertices[2], p.vertices[3]);
    c->info() = CellInfo();
    c->tds_data().clear();
    c->set_neighbor(p.apex, p.outer);
    p.outer->set_neighbor(p.outer_index, c);
  }
  // Across each boundary edge ab, the two new cells v + (a, b, x) share the facet
  // (v, a, b): in each, the facet opposite its vertex x.
  for (std::size_t e = 0; e < edges_.size(); ++e) {
    const EdgeTable::Edge& edge = edges_[e];
    if (edge.count != 2) throw InternalError("cone_hole: the hole's boundary is not closed");
    const Cell_handle cells[2] = {created[edge.facet[0]], created[edge.facet[1]]};
    for (int s = 0; s < 2; ++s) {
      const Planned& p = planned_[edge.facet[s]];
      int opposite = -1;
      for (int j = 0; j < 4; ++j)
        if (j != p.apex && p.vertices[j] != edge.a && p.vertices[j] != edge.b) opposite = j;
      cells[s]->set_neighbor(opposite, cells[1 - s]);
    }
  }
  for (std::size_t k = 0; k < boundary.size(); ++k) {
    const Planned& p = planned_[k];
    for (int j = 0; j < 4; ++j) {
      const Vertex_handle u = p.vertices[j];
      if (u != infinite || infinite_cell_in_hole) u->set_cell(created[k]);
    }
  }
}

}  // namespace rdmesh::detail
