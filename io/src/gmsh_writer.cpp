// Gmsh MSH 4.1 writer, ASCII or binary (number_tokens.h).
//
// Layout: one elementary volume per subdomain, one elementary surface per
// patch, one elementary curve per curve and one elementary point per corner,
// each carrying the physical group of the same tag and name. All nodes go in
// one $Nodes block classified on the first volume (allowed by the format: a
// node's entity only matters for CAD reparametrisation, which we do not use).
// Entity topology: a volume is bounded by the patches of TetMesh::patches that
// touch it, a surface by the curves whose CurveInfo::patches list it, an open
// curve by its start (+) and end (-) corner points.
// A partitioned mesh adds $PartitionedEntities: one entity per model entity
// and partition, then the partition-boundary entities (partition_boundaries.h),
// whose elements follow the model's in $Elements.
#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <ostream>
#include <string>

#include "element_nodes.h"
#include "mesh_labels.h"
#include "number_tokens.h"
#include "partition_boundaries.h"
#include "rdmesh/errors.h"
#include "rdmesh/mesh_writers.h"
#include "rdmesh/second_order.h"

namespace rdmesh {
namespace {

using io_detail::Label;

/// The box of the vertices of the given elements (zeros if none).
template <std::size_t N>
std::array<double, 6> bounding_box(const TetMesh& mesh,
                                   const std::vector<std::array<int, N>>& elements,
                                   const std::vector<int>& which) {
  if (which.empty()) return {};
  Box3 box = Box3::empty();
  for (int e : which) {
    for (int v : elements[e]) box.grow(mesh.vertices[v]);
  }
  return {box.lo.x, box.lo.y, box.lo.z, box.hi.x, box.hi.y, box.hi.z};
}

/// The labels and element groups of one dimension.
struct Level {
  std::vector<Label> labels;
  std::vector<std::vector<int>> groups;  ///< element indices per label
};

Level make_level(std::vector<Label> labels, const std::vector<int>& element_labels) {
  Level level{std::move(labels), {}};
  level.groups = io_detail::group_by_label(element_labels, level.labels);
  return level;
}

/// The four levels, indexed by dimension (0 = corners ... 3 = subdomains).
using Levels = std::array<Level, 4>;

void write_physical_names(std::ostream& out, const Levels& levels) {
  out << "$PhysicalNames\n"
      << levels[3].labels.size() + levels[2].labels.size() + levels[1].labels.size() +
             levels[0].labels.size()
      << '\n';
  // Volumes and surfaces first: a mesh without features keeps its historical layout.
  for (int dim : {3, 2, 1, 0}) {
    for (const Label& l : levels[dim].labels) {
      out << dim << ' ' << l.id << ' ' << io_detail::quoted_physical_name(l, dim) << '\n';
    }
  }
  out << "$EndPhysicalNames\n";
}

/// True when the sorted `labels` contain `id`.
bool has_label(const std::vector<Label>& labels, int id) {
  auto it = std::lower_bound(labels.begin(), labels.end(), id,
                             [](const Label& l, int v) { return l.id < v; });
  return it != labels.end() && it->id == id;
}

/// The sorted, unique tags.
std::vector<int> sorted_tags(std::vector<int> tags) {
  std::sort(tags.begin(), tags.end());
  tags.erase(std::unique(tags.begin(), tags.end()), tags.end());
  return tags;
}

/// "n t1 t2 ...": a count, then the tags.
void write_tags(io_detail::NumberTokens& t, const std::vector<int>& tags) {
  t.z(static_cast<long long>(tags.size()));
  for (int tag : tags) t.i(tag);
}

/// Patches bounding subdomain `id` according to TetMesh::patches.
std::vector<int> bounding_patches(const TetMesh& mesh, int id) {
  std::vector<int> tags;
  for (const PatchInfo& p : mesh.patches) {
    if (p.id.value > 0 && (p.side_a.value == id || p.side_b.value == id))
      tags.push_back(p.id.value);
  }
  return tags;
}

/// Curve entities bounding patch `id`: the listed curves that name it as incident.
std::vector<int> bounding_curves(const TetMesh& mesh, int id, const std::vector<Label>& curves) {
  std::vector<int> tags;
  for (const CurveInfo& c : mesh.curves) {
    if (!has_label(curves, c.id.value)) continue;
    for (PatchId p : c.patches) {
      if (p.value == id) tags.push_back(c.id.value);
    }
  }
  return tags;
}

/// Start (+) and end (-) corner of an open listed curve whose corners are point entities.
std::vector<int> bounding_points(const TetMesh& mesh, int id, const std::vector<Label>& points) {
  auto info = std::find_if(mesh.curves.begin(), mesh.curves.end(),
                           [&](const CurveInfo& c) { return c.id.value == id; });
  std::vector<int> tags;
  if (info != mesh.curves.end() && !info->closed) {
    if (has_label(points, info->start.value)) tags.push_back(info->start.value);
    if (has_label(points, info->end.value)) tags.push_back(-info->end.value);
  }
  return tags;
}

/// Corner `id`: its mesh vertex, else its listed point, else the origin.
Point3 corner_position(const TetMesh& mesh, int id, const std::vector<int>& group) {
  if (!group.empty()) return mesh.vertices[mesh.corner_vertices[group.front()]];
  for (const CornerInfo& c : mesh.corners) {
    if (c.id.value == id) return c.point;
  }
  return {};
}

/// One entity: tag, position or box, its physical group (same tag), its boundary.
void write_entity(io_detail::NumberTokens& t, int id, const std::vector<double>& where,
                  const std::vector<int>* boundary) {
  t.i(id);
  for (double c : where) t.d(c);
  t.z(1);
  t.i(id);
  if (boundary) write_tags(t, *boundary);
  t.end_line();
}

void write_entities(std::ostream& out, const TetMesh& mesh, const Levels& levels, bool binary) {
  const Level &points = levels[0], &curves = levels[1], &surfaces = levels[2], &volumes = levels[3];
  out << "$Entities\n";
  io_detail::NumberTokens t(out, binary);
  for (const Level* level : {&points, &curves, &surfaces, &volumes}) {
    t.z(static_cast<long long>(level->labels.size()));
  }
  t.end_line();
  for (std::size_t k = 0; k < points.labels.size(); ++k) {
    const int id = points.labels[k].id;
    const Point3 p = corner_position(mesh, id, points.groups[k]);
    write_entity(t, id, {p.x, p.y, p.z}, nullptr);
  }
  const auto box = [](const std::array<double, 6>& b) {
    return std::vector<double>(b.begin(), b.end());
  };
  for (std::size_t k = 0; k < curves.labels.size(); ++k) {
    const int id = curves.labels[k].id;
    const std::vector<int> ends = bounding_points(mesh, id, points.labels);
    write_entity(t, id, box(bounding_box(mesh, mesh.edges, curves.groups[k])), &ends);
  }
  for (std::size_t k = 0; k < surfaces.labels.size(); ++k) {
    const int id = surfaces.labels[k].id;
    const std::vector<int> around = sorted_tags(bounding_curves(mesh, id, curves.labels));
    write_entity(t, id, box(bounding_box(mesh, mesh.triangles, surfaces.groups[k])), &around);
  }
  for (std::size_t k = 0; k < volumes.labels.size(); ++k) {
    const int id = volumes.labels[k].id;
    const std::vector<int> around = sorted_tags(bounding_patches(mesh, id));
    write_entity(t, id, box(bounding_box(mesh, mesh.tets, volumes.groups[k])), &around);
  }
  t.flush();
  out << (binary ? "\n" : "") << "$EndEntities\n";
}

/// One node's "x y z" line.
void write_point(io_detail::NumberTokens& t, const Point3& p) {
  t.d(p.x);
  t.d(p.y);
  t.d(p.z);
  t.end_line();
}

/// All nodes in one block, on the first volume entity (the first surface one
/// for a surface-only mesh).
void write_nodes(std::ostream& out, const TetMesh& mesh, const Levels& levels, bool binary) {
  const auto n = static_cast<long long>(mesh.vertices.size());
  out << "$Nodes\n";
  io_detail::NumberTokens t(out, binary);
  if (n == 0) {
    for (int k = 0; k < 4; ++k) t.z(0);
    t.end_line();
  } else {
    const int dim = !levels[3].labels.empty() ? 3 : 2;
    if (levels[dim].labels.empty()) {
      throw InternalError(
          "write_gmsh41: the mesh has vertices but no subdomain or patch to "
          "classify them on");
    }
    for (long long v : {1LL, n, 1LL, n}) t.z(v);
    t.end_line();
    t.i(dim);
    t.i(levels[dim].labels.front().id);
    t.i(0);
    t.z(n);
    t.end_line();
    for (long long i = 1; i <= n; ++i) {
      t.z(i);
      t.end_line();
    }
    for (const Point3& p : mesh.vertices) write_point(t, p);
  }
  t.flush();
  out << (binary ? "\n" : "") << "$EndNodes\n";
}

/// One element block per non-empty group; `next_tag` is the running 1-based element tag.
template <std::size_t N>
void write_element_blocks(io_detail::NumberTokens& t, int dim, int gmsh_type,
                          const std::vector<std::array<int, N>>& elements, const Level& level,
                          long long& next_tag) {
  for (std::size_t k = 0; k < level.labels.size(); ++k) {
    if (level.groups[k].empty()) continue;
    t.i(dim);
    t.i(level.labels[k].id);
    t.i(gmsh_type);
    t.z(static_cast<long long>(level.groups[k].size()));
    t.end_line();
    for (int e : level.groups[k]) {
      t.z(next_tag++);
      for (int v : elements[e]) t.z(v + 1);
      t.end_line();
    }
  }
}

std::size_t count_non_empty(const std::vector<std::vector<int>>& groups) {
  return static_cast<std::size_t>(
      std::count_if(groups.begin(), groups.end(), [](const auto& g) { return !g.empty(); }));
}

/// Partition-boundary elements to write after the model's: the entities and
/// the tag of the first one per dimension.
struct BoundaryBlocks {
  const io_detail::PartitionBoundaries* entities = nullptr;
  std::array<int, 4> first_tag{};
};

/// One block per partition-boundary entity of dimension `dim` (Gmsh type `type`).
void write_boundary_blocks(io_detail::NumberTokens& t, int dim, int type, const BoundaryBlocks& b,
                           long long& next_tag) {
  int tag = b.first_tag[dim];
  for (const io_detail::PartitionBoundary& e : (*b.entities)[dim]) {
    t.i(dim);
    t.i(tag++);
    t.i(type);
    t.z(static_cast<long long>(e.elements.size()));
    t.end_line();
    for (const auto& nodes : e.elements) {
      t.z(next_tag++);
      for (int v : nodes) t.z(v + 1);
      t.end_line();
    }
  }
}

/// $Elements: one block per non-empty group of `levels` (model entities, or
/// partitioned entities with their tags as labels), then the partition
/// boundaries' blocks if any.
void write_elements(std::ostream& out, const TetMesh& mesh, const Levels& levels, bool binary,
                    const BoundaryBlocks& boundaries = {}) {
  std::vector<std::array<int, 1>> corner_elements;
  corner_elements.reserve(mesh.corner_vertices.size());
  for (int v : mesh.corner_vertices) corner_elements.push_back({v});
  auto num_elements = static_cast<long long>(mesh.tets.size() + mesh.triangles.size() +
                                             mesh.edges.size() + corner_elements.size());
  std::size_t num_blocks = 0;
  for (const Level& level : levels) num_blocks += count_non_empty(level.groups);
  if (boundaries.entities) {
    for (const auto& dim : *boundaries.entities) {
      num_blocks += dim.size();
      for (const auto& e : dim) num_elements += static_cast<long long>(e.elements.size());
    }
  }
  out << "$Elements\n";
  {
    io_detail::NumberTokens t(out, binary);
    t.z(static_cast<long long>(num_blocks));
    t.z(num_elements);
    t.z(num_elements ? 1 : 0);
    t.z(num_elements);
    t.end_line();
    long long next_tag = 1;
    // Tets and triangles first: a mesh without features keeps its element tags.
    const bool p2 = is_second_order(mesh);
    if (p2) {  // 10-node tets, 6-node triangles, 3-node lines
      write_element_blocks(t, 3, 11, io_detail::tet10_elements(mesh, io_detail::Tet10Order::kGmsh),
                           levels[3], next_tag);
      write_element_blocks(t, 2, 9, io_detail::triangle6_elements(mesh), levels[2], next_tag);
      write_element_blocks(t, 1, 8, io_detail::line3_elements(mesh), levels[1], next_tag);
    } else {
      write_element_blocks(t, 3, 4, mesh.tets, levels[3], next_tag);
      write_element_blocks(t, 2, 2, mesh.triangles, levels[2], next_tag);
      write_element_blocks(t, 1, 1, mesh.edges, levels[1], next_tag);
    }
    write_element_blocks(t, 0, 15, corner_elements, levels[0], next_tag);
    if (boundaries.entities) {
      write_boundary_blocks(t, 2, p2 ? 9 : 2, boundaries, next_tag);
      write_boundary_blocks(t, 1, p2 ? 8 : 1, boundaries, next_tag);
      write_boundary_blocks(t, 0, 15, boundaries, next_tag);
    }
  }
  out << (binary ? "\n" : "") << "$EndElements\n";
}

// --- Partitioned meshes (TetMesh::tet_partition): Gmsh's partitioned entities ---

/// A model entity restricted to one partition, with its elements.
struct PartEntity {
  int tag = 0, parent = 0, partition = 0;
  std::vector<int> elements;
};

/// Per dimension, the partitioned entities: for each model entity (label) its
/// partitions in ascending order, tagged after the largest model tag.
std::array<std::vector<PartEntity>, 4> partitioned_entities(const TetMesh& mesh,
                                                            const Levels& levels) {
  const std::vector<int>* partition_of[4] = {&mesh.corner_partition, &mesh.edge_partition,
                                             &mesh.triangle_partition, &mesh.tet_partition};
  std::array<std::vector<PartEntity>, 4> out;
  for (int dim = 0; dim < 4; ++dim) {
    const Level& level = levels[dim];
    int next_tag = level.labels.empty() ? 1 : level.labels.back().id + 1;
    for (std::size_t k = 0; k < level.labels.size(); ++k) {
      std::map<int, std::vector<int>> by_partition;
      for (int e : level.groups[k]) by_partition[(*partition_of[dim])[e]].push_back(e);
      for (auto& [partition, elements] : by_partition) {
        out[dim].push_back({next_tag++, level.labels[k].id, partition, std::move(elements)});
      }
    }
  }
  return out;
}

/// The tag of each partition-boundary entity: after the partitioned entities
/// of its dimension (after the model's tags when there are none).
std::array<int, 4> first_boundary_tags(const Levels& levels,
                                       const std::array<std::vector<PartEntity>, 4>& parts) {
  std::array<int, 4> first{};
  for (int dim = 0; dim < 4; ++dim) {
    first[dim] = !parts[dim].empty()           ? parts[dim].back().tag + 1
                 : !levels[dim].labels.empty() ? levels[dim].labels.back().id + 1
                                               : 1;
  }
  return first;
}

/// Point entities: the position; others: the box of the elements' nodes.
std::vector<double> boundary_where(const TetMesh& mesh, int dim,
                                   const io_detail::PartitionBoundary& b) {
  if (dim == 0) {
    const Point3& p = mesh.vertices[b.elements.front().front()];
    return {p.x, p.y, p.z};
  }
  std::vector<std::array<int, 1>> nodes;
  std::vector<int> which;
  for (const auto& e : b.elements) {
    for (int v : e) {
      which.push_back(static_cast<int>(nodes.size()));
      nodes.push_back({v});
    }
  }
  const auto box = bounding_box(mesh, nodes, which);
  return std::vector<double>(box.begin(), box.end());
}

void write_partitioned_entities(std::ostream& out, const TetMesh& mesh, const Levels& levels,
                                const std::array<std::vector<PartEntity>, 4>& parts,
                                const io_detail::PartitionBoundaries& boundaries, bool binary) {
  const int num_partitions =
      *std::max_element(mesh.tet_partition.begin(), mesh.tet_partition.end());
  out << "$PartitionedEntities\n";
  io_detail::NumberTokens t(out, binary);
  t.z(num_partitions);
  t.end_line();
  t.z(0);  // no ghost entities
  t.end_line();
  for (int dim = 0; dim < 4; ++dim) {
    t.z(static_cast<long long>(parts[dim].size() + boundaries[dim].size()));
  }
  t.end_line();
  const auto box = [](const std::array<double, 6>& b) {
    return std::vector<double>(b.begin(), b.end());
  };
  const std::array<int, 4> first_boundary = first_boundary_tags(levels, parts);
  for (int dim = 0; dim < 4; ++dim) {
    for (const PartEntity& e : parts[dim]) {
      t.i(e.tag);
      t.i(dim);
      t.i(e.parent);
      t.z(1);
      t.i(e.partition);
      std::vector<double> where;
      if (dim == 0) {
        const Point3 p = corner_position(mesh, e.parent, e.elements);
        where = {p.x, p.y, p.z};
      } else if (dim == 1) {
        where = box(bounding_box(mesh, mesh.edges, e.elements));
      } else if (dim == 2) {
        where = box(bounding_box(mesh, mesh.triangles, e.elements));
      } else {
        where = box(bounding_box(mesh, mesh.tets, e.elements));
      }
      for (double c : where) t.d(c);
      t.z(1);
      t.i(e.parent);
      if (dim > 0) t.z(0);  // no bounding entities
      t.end_line();
    }
    // Partition boundaries: no physical group, no bounding entities.
    int tag = first_boundary[dim];
    for (const io_detail::PartitionBoundary& b : boundaries[dim]) {
      t.i(tag++);
      t.i(b.parent_dim);
      t.i(b.parent);
      write_tags(t, b.partitions);
      for (double c : boundary_where(mesh, dim, b)) t.d(c);
      t.z(0);
      if (dim > 0) t.z(0);
      t.end_line();
    }
  }
  t.flush();
  out << (binary ? "\n" : "") << "$EndPartitionedEntities\n";
}

/// Each node in one block: the partitioned volume of the tetrahedron with the
/// smallest partition (then the smallest index) among those using it.
void write_partitioned_nodes(std::ostream& out, const TetMesh& mesh,
                             const std::vector<PartEntity>& volumes, bool binary) {
  std::vector<int> owner(mesh.vertices.size(), -1);  // a tetrahedron
  auto claim = [&](int v, int t) {
    if (owner[v] < 0 || mesh.tet_partition[t] < mesh.tet_partition[owner[v]]) owner[v] = t;
  };
  const bool p2 = mesh.tet_mid_nodes.size() == mesh.tets.size();
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    for (int v : mesh.tets[t]) claim(v, static_cast<int>(t));
    if (p2) {
      for (int v : mesh.tet_mid_nodes[t]) claim(v, static_cast<int>(t));
    }
  }
  std::map<std::pair<int, int>, std::size_t> entity_of;  // (subdomain, partition) -> index
  for (std::size_t i = 0; i < volumes.size(); ++i) {
    entity_of[{volumes[i].parent, volumes[i].partition}] = i;
  }
  std::vector<std::vector<int>> nodes(volumes.size());
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    if (owner[v] < 0)
      throw InternalError("write_gmsh41: vertex " + std::to_string(v) + " is in no tetrahedron");
    const int t = owner[v];
    nodes[entity_of.at({mesh.tet_subdomain[t].value, mesh.tet_partition[t]})].push_back(
        static_cast<int>(v));
  }
  const auto n = static_cast<long long>(mesh.vertices.size());
  out << "$Nodes\n";
  io_detail::NumberTokens t(out, binary);
  for (long long v : {static_cast<long long>(count_non_empty(nodes)), n, 1LL, n}) t.z(v);
  t.end_line();
  for (std::size_t i = 0; i < volumes.size(); ++i) {
    if (nodes[i].empty()) continue;
    t.i(3);
    t.i(volumes[i].tag);
    t.i(0);
    t.z(static_cast<long long>(nodes[i].size()));
    t.end_line();
    for (int v : nodes[i]) {
      t.z(v + 1);
      t.end_line();
    }
    for (int v : nodes[i]) write_point(t, mesh.vertices[v]);
  }
  t.flush();
  out << (binary ? "\n" : "") << "$EndNodes\n";
}

/// The partitioned entities of one dimension as a Level (tags as labels).
Level partitioned_level(const std::vector<PartEntity>& entities) {
  Level level;
  for (const PartEntity& e : entities) {
    level.labels.push_back({e.tag, {}});
    level.groups.push_back(e.elements);
  }
  return level;
}

void write_msh41(const TetMesh& mesh, std::ostream& out, bool binary) {
  io_detail::check_mesh(mesh);
  const Levels levels{
      make_level(io_detail::corner_labels(mesh), io_detail::corner_label_values(mesh)),
      make_level(io_detail::curve_labels(mesh), io_detail::edge_label_values(mesh)),
      make_level(io_detail::patch_labels(mesh), io_detail::triangle_label_values(mesh)),
      make_level(io_detail::subdomain_labels(mesh), io_detail::tet_label_values(mesh))};

  if (binary) {
    const std::int32_t one = 1;  // tells the reader the byte order
    out << "$MeshFormat\n4.1 1 8\n";
    out.write(reinterpret_cast<const char*>(&one), sizeof one);
    out << "\n$EndMeshFormat\n";
  } else {
    out << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
  }
  write_physical_names(out, levels);
  write_entities(out, mesh, levels, binary);
  if (!mesh.tet_partition.empty()) {
    const auto parts = partitioned_entities(mesh, levels);
    const io_detail::PartitionBoundaries boundaries = io_detail::partition_boundaries(mesh);
    write_partitioned_entities(out, mesh, levels, parts, boundaries, binary);
    write_partitioned_nodes(out, mesh, parts[3], binary);
    write_elements(out, mesh,
                   Levels{partitioned_level(parts[0]), partitioned_level(parts[1]),
                          partitioned_level(parts[2]), partitioned_level(parts[3])},
                   binary, BoundaryBlocks{&boundaries, first_boundary_tags(levels, parts)});
  } else {
    write_nodes(out, mesh, levels, binary);
    write_elements(out, mesh, levels, binary);
  }
  if (!out) throw OutputError("write_gmsh41: the output stream failed");
}

}  // namespace

void write_gmsh41(const TetMesh& mesh, std::ostream& out) { write_msh41(mesh, out, false); }

void write_gmsh41_binary(const TetMesh& mesh, std::ostream& out) { write_msh41(mesh, out, true); }

}  // namespace rdmesh
