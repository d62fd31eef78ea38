// Gmsh MSH 4.1 ASCII writer.
//
// Layout: one elementary volume per subdomain, one elementary surface per
// patch, one elementary curve per curve and one elementary point per corner,
// each carrying the physical group of the same tag and name. All nodes go in
// one $Nodes block classified on the first volume (allowed by the format: a
// node's entity only matters for CAD reparametrisation, which we do not use).
// Entity topology: a volume is bounded by the patches of TetMesh::patches that
// touch it, a surface by the curves whose CurveInfo::patches list it, an open
// curve by its start (+) and end (-) corner points.
#include <algorithm>
#include <array>
#include <limits>
#include <map>
#include <ostream>
#include <string>

#include "element_nodes.h"
#include "mesh_labels.h"
#include "rdmesh/errors.h"
#include "rdmesh/mesh_writers.h"
#include "rdmesh/second_order.h"

namespace rdmesh {
namespace {

using io_detail::append_double;
using io_detail::append_int;
using io_detail::Label;

/// Physical name in double quotes; quotes inside the name become single quotes.
std::string quoted_name(const Label& label, const char* fallback_prefix) {
  std::string name = label.name.empty() ? fallback_prefix + std::to_string(label.id) : label.name;
  std::replace(name.begin(), name.end(), '"', '\'');
  std::replace(name.begin(), name.end(), '\n', ' ');
  return '"' + name + '"';
}

/// "minX minY minZ maxX maxY maxZ" of the vertices of the given elements (zeros if none).
template <std::size_t N>
std::string bounding_box(const TetMesh& mesh, const std::vector<std::array<int, N>>& elements,
                         const std::vector<int>& which) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  Point3 lo{kInf, kInf, kInf}, hi{-kInf, -kInf, -kInf};
  for (int e : which) {
    for (int v : elements[e]) {
      const Point3& p = mesh.vertices[v];
      lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
      hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    }
  }
  if (which.empty()) lo = hi = Point3{};
  std::string s;
  for (double c : {lo.x, lo.y, lo.z, hi.x, hi.y, hi.z}) {
    append_double(s, c);
    s += ' ';
  }
  return s;
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
  const char* prefixes[4] = {"corner_", "curve_", "patch_", "subdomain_"};
  for (int dim : {3, 2, 1, 0}) {
    for (const Label& l : levels[dim].labels) {
      out << dim << ' ' << l.id << ' ' << quoted_name(l, prefixes[dim]) << '\n';
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

/// "n t1 t2 ..." of the sorted, unique tags.
std::string tag_list(std::vector<int> tags) {
  std::sort(tags.begin(), tags.end());
  tags.erase(std::unique(tags.begin(), tags.end()), tags.end());
  std::string s = std::to_string(tags.size());
  for (int t : tags) s += ' ' + std::to_string(t);
  return s;
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

/// "n start -end" for an open listed curve whose corners are point entities; "0" otherwise.
std::string bounding_points(const TetMesh& mesh, int id, const std::vector<Label>& points) {
  auto info = std::find_if(mesh.curves.begin(), mesh.curves.end(),
                           [&](const CurveInfo& c) { return c.id.value == id; });
  std::vector<int> tags;
  if (info != mesh.curves.end() && !info->closed) {
    if (has_label(points, info->start.value)) tags.push_back(info->start.value);
    if (has_label(points, info->end.value)) tags.push_back(-info->end.value);
  }
  std::string s = std::to_string(tags.size());
  for (int t : tags) s += ' ' + std::to_string(t);
  return s;
}

/// "x y z " of corner `id`: its mesh vertex, else its listed point, else the origin.
std::string corner_position(const TetMesh& mesh, int id, const std::vector<int>& group) {
  Point3 p;
  if (!group.empty()) {
    p = mesh.vertices[mesh.corner_vertices[group.front()]];
  } else {
    for (const CornerInfo& c : mesh.corners) {
      if (c.id.value == id) p = c.point;
    }
  }
  std::string s;
  for (double c : {p.x, p.y, p.z}) {
    append_double(s, c);
    s += ' ';
  }
  return s;
}

void write_entities(std::ostream& out, const TetMesh& mesh, const Levels& levels) {
  const Level &points = levels[0], &curves = levels[1], &surfaces = levels[2], &volumes = levels[3];
  out << "$Entities\n"
      << points.labels.size() << ' ' << curves.labels.size() << ' ' << surfaces.labels.size() << ' '
      << volumes.labels.size() << '\n';
  for (std::size_t k = 0; k < points.labels.size(); ++k) {
    const int id = points.labels[k].id;
    out << id << ' ' << corner_position(mesh, id, points.groups[k]) << "1 " << id << '\n';
  }
  for (std::size_t k = 0; k < curves.labels.size(); ++k) {
    const int id = curves.labels[k].id;
    out << id << ' ' << bounding_box(mesh, mesh.edges, curves.groups[k]) << "1 " << id << ' '
        << bounding_points(mesh, id, points.labels) << '\n';
  }
  for (std::size_t k = 0; k < surfaces.labels.size(); ++k) {
    const int id = surfaces.labels[k].id;
    out << id << ' ' << bounding_box(mesh, mesh.triangles, surfaces.groups[k]) << "1 " << id << ' '
        << tag_list(bounding_curves(mesh, id, curves.labels)) << '\n';
  }
  for (std::size_t k = 0; k < volumes.labels.size(); ++k) {
    const int id = volumes.labels[k].id;
    out << id << ' ' << bounding_box(mesh, mesh.tets, volumes.groups[k]) << "1 " << id << ' '
        << tag_list(bounding_patches(mesh, id)) << '\n';
  }
  out << "$EndEntities\n";
}

/// One "x y z" line, through the reused buffer `line`.
void write_point(std::ostream& out, std::string& line, const Point3& p) {
  line.clear();
  append_double(line, p.x);
  line += ' ';
  append_double(line, p.y);
  line += ' ';
  append_double(line, p.z);
  line += '\n';
  out << line;
}

/// All nodes in one block, on the first volume entity (the first surface one
/// for a surface-only mesh).
void write_nodes(std::ostream& out, const TetMesh& mesh, const Levels& levels) {
  const std::size_t n = mesh.vertices.size();
  if (n == 0) {
    out << "$Nodes\n0 0 0 0\n$EndNodes\n";
    return;
  }
  const int dim = !levels[3].labels.empty() ? 3 : 2;
  if (levels[dim].labels.empty()) {
    throw InternalError("write_gmsh41: the mesh has vertices but no subdomain or patch to "
                        "classify them on");
  }
  out << "$Nodes\n1 " << n << " 1 " << n << '\n'
      << dim << ' ' << levels[dim].labels.front().id << " 0 " << n << '\n';
  std::string line;
  for (std::size_t i = 1; i <= n; ++i) {
    line.clear();
    append_int(line, static_cast<long long>(i));
    line += '\n';
    out << line;
  }
  for (const Point3& p : mesh.vertices) write_point(out, line, p);
  out << "$EndNodes\n";
}

/// One element block per non-empty group; `next_tag` is the running 1-based element tag.
template <std::size_t N>
void write_element_blocks(std::ostream& out, int dim, int gmsh_type,
                          const std::vector<std::array<int, N>>& elements, const Level& level,
                          long long& next_tag) {
  std::string line;
  for (std::size_t k = 0; k < level.labels.size(); ++k) {
    if (level.groups[k].empty()) continue;
    out << dim << ' ' << level.labels[k].id << ' ' << gmsh_type << ' ' << level.groups[k].size()
        << '\n';
    for (int e : level.groups[k]) {
      line.clear();
      append_int(line, next_tag++);
      for (int v : elements[e]) {
        line += ' ';
        append_int(line, v + 1);
      }
      line += '\n';
      out << line;
    }
  }
}

std::size_t count_non_empty(const std::vector<std::vector<int>>& groups) {
  return static_cast<std::size_t>(
      std::count_if(groups.begin(), groups.end(), [](const auto& g) { return !g.empty(); }));
}

/// $Elements: one block per non-empty group of `levels` (model entities, or
/// partitioned entities with their tags as labels).
void write_elements(std::ostream& out, const TetMesh& mesh, const Levels& levels) {
  std::vector<std::array<int, 1>> corner_elements;
  corner_elements.reserve(mesh.corner_vertices.size());
  for (int v : mesh.corner_vertices) corner_elements.push_back({v});
  const std::size_t num_elements =
      mesh.tets.size() + mesh.triangles.size() + mesh.edges.size() + corner_elements.size();
  std::size_t num_blocks = 0;
  for (const Level& level : levels) num_blocks += count_non_empty(level.groups);
  out << "$Elements\n"
      << num_blocks << ' ' << num_elements << ' ' << (num_elements ? 1 : 0) << ' ' << num_elements
      << '\n';
  long long next_tag = 1;
  // Tets and triangles first: a mesh without features keeps its element tags.
  if (is_second_order(mesh)) {  // 10-node tets, 6-node triangles, 3-node lines
    write_element_blocks(out, 3, 11, io_detail::tet10_elements(mesh, io_detail::Tet10Order::kGmsh),
                         levels[3], next_tag);
    write_element_blocks(out, 2, 9, io_detail::triangle6_elements(mesh), levels[2], next_tag);
    write_element_blocks(out, 1, 8, io_detail::line3_elements(mesh), levels[1], next_tag);
  } else {
    write_element_blocks(out, 3, 4, mesh.tets, levels[3], next_tag);
    write_element_blocks(out, 2, 2, mesh.triangles, levels[2], next_tag);
    write_element_blocks(out, 1, 1, mesh.edges, levels[1], next_tag);
  }
  write_element_blocks(out, 0, 15, corner_elements, levels[0], next_tag);
  out << "$EndElements\n";
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

void write_partitioned_entities(std::ostream& out, const TetMesh& mesh,
                                const std::array<std::vector<PartEntity>, 4>& parts) {
  const int num_partitions =
      *std::max_element(mesh.tet_partition.begin(), mesh.tet_partition.end());
  out << "$PartitionedEntities\n"
      << num_partitions << "\n0\n"
      << parts[0].size() << ' ' << parts[1].size() << ' ' << parts[2].size() << ' '
      << parts[3].size() << '\n';
  for (int dim = 0; dim < 4; ++dim) {
    for (const PartEntity& e : parts[dim]) {
      out << e.tag << ' ' << dim << ' ' << e.parent << " 1 " << e.partition << ' ';
      switch (dim) {
        case 0:
          out << corner_position(mesh, e.parent, e.elements) << "1 " << e.parent << '\n';
          break;
        case 1:
          out << bounding_box(mesh, mesh.edges, e.elements) << "1 " << e.parent << " 0\n";
          break;
        case 2:
          out << bounding_box(mesh, mesh.triangles, e.elements) << "1 " << e.parent << " 0\n";
          break;
        default:
          out << bounding_box(mesh, mesh.tets, e.elements) << "1 " << e.parent << " 0\n";
      }
    }
  }
  out << "$EndPartitionedEntities\n";
}

/// Each node in one block: the partitioned volume of the tetrahedron with the
/// smallest partition (then the smallest index) among those using it.
void write_partitioned_nodes(std::ostream& out, const TetMesh& mesh,
                             const std::vector<PartEntity>& volumes) {
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
  const std::size_t n = mesh.vertices.size();
  out << "$Nodes\n" << count_non_empty(nodes) << ' ' << n << " 1 " << n << '\n';
  std::string line;
  for (std::size_t i = 0; i < volumes.size(); ++i) {
    if (nodes[i].empty()) continue;
    out << "3 " << volumes[i].tag << " 0 " << nodes[i].size() << '\n';
    for (int v : nodes[i]) {
      line.clear();
      append_int(line, v + 1);
      line += '\n';
      out << line;
    }
    for (int v : nodes[i]) write_point(out, line, mesh.vertices[v]);
  }
  out << "$EndNodes\n";
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

}  // namespace

void write_gmsh41(const TetMesh& mesh, std::ostream& out) {
  io_detail::check_mesh(mesh);
  const Levels levels{
      make_level(io_detail::corner_labels(mesh), io_detail::corner_label_values(mesh)),
      make_level(io_detail::curve_labels(mesh), io_detail::edge_label_values(mesh)),
      make_level(io_detail::patch_labels(mesh), io_detail::triangle_label_values(mesh)),
      make_level(io_detail::subdomain_labels(mesh), io_detail::tet_label_values(mesh))};

  out << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
  write_physical_names(out, levels);
  write_entities(out, mesh, levels);
  if (!mesh.tet_partition.empty()) {
    const auto parts = partitioned_entities(mesh, levels);
    write_partitioned_entities(out, mesh, parts);
    write_partitioned_nodes(out, mesh, parts[3]);
    write_elements(out, mesh,
                   Levels{partitioned_level(parts[0]), partitioned_level(parts[1]),
                          partitioned_level(parts[2]), partitioned_level(parts[3])});
  } else {
    write_nodes(out, mesh, levels);
    write_elements(out, mesh, levels);
  }
  if (!out) throw OutputError("write_gmsh41: the output stream failed");
}

}  // namespace rdmesh
