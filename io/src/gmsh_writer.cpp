// Gmsh MSH 4.1 ASCII writer.
//
// Layout: one elementary volume per subdomain and one elementary surface per
// patch, each carrying the physical group of the same tag and name. All nodes
// go in one $Nodes block classified on the first volume (allowed by the format:
// a node's entity only matters for CAD reparametrisation, which we do not use).
#include <algorithm>
#include <limits>
#include <ostream>
#include <string>

#include "mesh_labels.h"
#include "rdmesh/errors.h"
#include "rdmesh/mesh_writers.h"

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

void write_physical_names(std::ostream& out, const std::vector<Label>& volumes,
                          const std::vector<Label>& surfaces) {
  out << "$PhysicalNames\n" << volumes.size() + surfaces.size() << '\n';
  for (const Label& l : volumes) out << "3 " << l.id << ' ' << quoted_name(l, "subdomain_") << '\n';
  for (const Label& l : surfaces) out << "2 " << l.id << ' ' << quoted_name(l, "patch_") << '\n';
  out << "$EndPhysicalNames\n";
}

/// Patches bounding subdomain `id` according to TetMesh::patches.
std::vector<int> bounding_patches(const TetMesh& mesh, int id) {
  std::vector<int> tags;
  for (const PatchInfo& p : mesh.patches) {
    if (p.id.value > 0 && (p.side_a.value == id || p.side_b.value == id))
      tags.push_back(p.id.value);
  }
  std::sort(tags.begin(), tags.end());
  tags.erase(std::unique(tags.begin(), tags.end()), tags.end());
  return tags;
}

void write_entities(std::ostream& out, const TetMesh& mesh, const std::vector<Label>& volumes,
                    const std::vector<std::vector<int>>& tets_of,
                    const std::vector<Label>& surfaces,
                    const std::vector<std::vector<int>>& triangles_of) {
  out << "$Entities\n0 0 " << surfaces.size() << ' ' << volumes.size() << '\n';
  for (std::size_t k = 0; k < surfaces.size(); ++k) {
    out << surfaces[k].id << ' ' << bounding_box(mesh, mesh.triangles, triangles_of[k]) << "1 "
        << surfaces[k].id << " 0\n";
  }
  for (std::size_t k = 0; k < volumes.size(); ++k) {
    std::vector<int> bounds = bounding_patches(mesh, volumes[k].id);
    out << volumes[k].id << ' ' << bounding_box(mesh, mesh.tets, tets_of[k]) << "1 "
        << volumes[k].id << ' ' << bounds.size();
    for (int b : bounds) out << ' ' << b;
    out << '\n';
  }
  out << "$EndEntities\n";
}

void write_nodes(std::ostream& out, const TetMesh& mesh, const std::vector<Label>& volumes) {
  const std::size_t n = mesh.vertices.size();
  if (n == 0) {
    out << "$Nodes\n0 0 0 0\n$EndNodes\n";
    return;
  }
  if (volumes.empty()) {
    throw InternalError("write_gmsh41: the mesh has vertices but no subdomain to classify them on");
  }
  out << "$Nodes\n1 " << n << " 1 " << n << "\n3 " << volumes.front().id << " 0 " << n << '\n';
  std::string line;
  for (std::size_t i = 1; i <= n; ++i) {
    line.clear();
    append_int(line, static_cast<long long>(i));
    line += '\n';
    out << line;
  }
  for (const Point3& p : mesh.vertices) {
    line.clear();
    append_double(line, p.x);
    line += ' ';
    append_double(line, p.y);
    line += ' ';
    append_double(line, p.z);
    line += '\n';
    out << line;
  }
  out << "$EndNodes\n";
}

/// One element block per non-empty group; `next_tag` is the running 1-based element tag.
template <std::size_t N>
void write_element_blocks(std::ostream& out, int dim, int gmsh_type,
                          const std::vector<std::array<int, N>>& elements,
                          const std::vector<Label>& labels,
                          const std::vector<std::vector<int>>& groups, long long& next_tag) {
  std::string line;
  for (std::size_t k = 0; k < labels.size(); ++k) {
    if (groups[k].empty()) continue;
    out << dim << ' ' << labels[k].id << ' ' << gmsh_type << ' ' << groups[k].size() << '\n';
    for (int e : groups[k]) {
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

}  // namespace

void write_gmsh41(const TetMesh& mesh, std::ostream& out) {
  io_detail::check_mesh(mesh);
  const std::vector<Label> volumes = io_detail::subdomain_labels(mesh);
  const std::vector<Label> surfaces = io_detail::patch_labels(mesh);
  const auto tets_of = io_detail::group_by_label(io_detail::tet_label_values(mesh), volumes);
  const auto triangles_of =
      io_detail::group_by_label(io_detail::triangle_label_values(mesh), surfaces);

  out << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
  write_physical_names(out, volumes, surfaces);
  write_entities(out, mesh, volumes, tets_of, surfaces, triangles_of);
  write_nodes(out, mesh, volumes);

  const std::size_t num_elements = mesh.tets.size() + mesh.triangles.size();
  out << "$Elements\n"
      << count_non_empty(tets_of) + count_non_empty(triangles_of) << ' ' << num_elements << ' '
      << (num_elements ? 1 : 0) << ' ' << num_elements << '\n';
  long long next_tag = 1;
  write_element_blocks(out, 3, 4, mesh.tets, volumes, tets_of, next_tag);
  write_element_blocks(out, 2, 2, mesh.triangles, surfaces, triangles_of, next_tag);
  out << "$EndElements\n";
  if (!out) throw OutputError("write_gmsh41: the output stream failed");
}

}  // namespace rdmesh
