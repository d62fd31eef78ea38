// The writers' output for a mesh WITHOUT sharp features, rebuilt independently
// from the mesh: the layout the writers produced before the 1D/0D levels
// existed, which they must keep producing for such meshes (the .vtu has since
// gained the names as field data). Assumes every
// subdomain and patch id used by an element is listed in the TetMesh, sorted.
#pragma once

#include <algorithm>
#include <array>
#include <charconv>
#include <string>
#include <vector>

#include "rdmesh/tet_mesh.h"

namespace rdmesh::testing {

/// Shortest round-trip text of `v`.
inline std::string num(double v) {
  char buf[32];
  return std::string(buf, std::to_chars(buf, buf + sizeof buf, v).ptr);
}

/// `values` separated by spaces, `per_line` to a line, each line ending in '\n'.
inline std::string rows(const std::vector<long long>& values, std::size_t per_line) {
  std::string s;
  for (std::size_t i = 0; i < values.size(); ++i) {
    s += std::to_string(values[i]);
    s += (i + 1) % per_line == 0 || i + 1 == values.size() ? '\n' : ' ';
  }
  return s;
}

inline std::string reference_medit(const TetMesh& m) {
  std::string s = "MeshVersionFormatted 2\n\nDimension 3\n\nVertices\n" +
                  std::to_string(m.vertices.size()) + "\n";
  for (const Point3& p : m.vertices) s += num(p.x) + ' ' + num(p.y) + ' ' + num(p.z) + " 0\n";
  s += "\nTetrahedra\n" + std::to_string(m.tets.size()) + "\n";
  for (std::size_t t = 0; t < m.tets.size(); ++t) {
    for (int v : m.tets[t]) s += std::to_string(v + 1) + ' ';
    s += std::to_string(m.tet_subdomain[t].value) + '\n';
  }
  s += "\nTriangles\n" + std::to_string(m.triangles.size()) + "\n";
  for (std::size_t f = 0; f < m.triangles.size(); ++f) {
    for (int v : m.triangles[f]) s += std::to_string(v + 1) + ' ';
    s += std::to_string(m.triangle_patch[f].value) + '\n';
  }
  return s + "\nEnd\n";
}

/// "minx miny minz maxx maxy maxz " over the vertices of elements[i] with labels[i] == id.
template <std::size_t N, class LabelT>
std::string reference_box(const TetMesh& m, const std::vector<std::array<int, N>>& elements,
                          const std::vector<LabelT>& labels, int id) {
  bool any = false;
  Point3 lo, hi;
  for (std::size_t e = 0; e < elements.size(); ++e) {
    if (labels[e].value != id) continue;
    for (int v : elements[e]) {
      const Point3& p = m.vertices[v];
      lo = any ? Point3{std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)} : p;
      hi = any ? Point3{std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)} : p;
      any = true;
    }
  }
  return num(lo.x) + ' ' + num(lo.y) + ' ' + num(lo.z) + ' ' + num(hi.x) + ' ' + num(hi.y) + ' ' +
         num(hi.z) + ' ';
}

inline std::string reference_gmsh41(const TetMesh& m) {
  std::string s = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$PhysicalNames\n" +
                  std::to_string(m.subdomains.size() + m.patches.size()) + "\n";
  for (const auto& d : m.subdomains)
    s += "3 " + std::to_string(d.id.value) + " \"" + d.name + "\"\n";
  for (const auto& p : m.patches) s += "2 " + std::to_string(p.id.value) + " \"" + p.name + "\"\n";
  s += "$EndPhysicalNames\n$Entities\n0 0 " + std::to_string(m.patches.size()) + ' ' +
       std::to_string(m.subdomains.size()) + '\n';
  for (const auto& p : m.patches) {
    const std::string id = std::to_string(p.id.value);
    s +=
        id + ' ' + reference_box(m, m.triangles, m.triangle_patch, p.id.value) + "1 " + id + " 0\n";
  }
  for (const auto& d : m.subdomains) {
    std::vector<int> bounds;
    for (const auto& p : m.patches) {
      if (p.side_a == d.id || p.side_b == d.id) bounds.push_back(p.id.value);
    }
    const std::string id = std::to_string(d.id.value);
    s += id + ' ' + reference_box(m, m.tets, m.tet_subdomain, d.id.value) + "1 " + id + ' ' +
         std::to_string(bounds.size());
    for (int b : bounds) s += ' ' + std::to_string(b);
    s += '\n';
  }
  const std::string n = std::to_string(m.vertices.size());
  s += "$EndEntities\n$Nodes\n1 " + n + " 1 " + n + "\n3 " +
       std::to_string(m.subdomains.front().id.value) + " 0 " + n + "\n";
  for (std::size_t i = 1; i <= m.vertices.size(); ++i) s += std::to_string(i) + '\n';
  for (const Point3& p : m.vertices) s += num(p.x) + ' ' + num(p.y) + ' ' + num(p.z) + '\n';
  const std::string ne = std::to_string(m.tets.size() + m.triangles.size());
  s += "$EndNodes\n$Elements\n" + std::to_string(m.subdomains.size() + m.patches.size()) + ' ' +
       ne + " 1 " + ne + '\n';
  long long tag = 1;
  for (const auto& d : m.subdomains) {
    std::string block;
    std::size_t count = 0;
    for (std::size_t t = 0; t < m.tets.size(); ++t) {
      if (m.tet_subdomain[t] != d.id) continue;
      ++count;
      block += std::to_string(tag++);
      for (int v : m.tets[t]) block += ' ' + std::to_string(v + 1);
      block += '\n';
    }
    s += "3 " + std::to_string(d.id.value) + " 4 " + std::to_string(count) + '\n' + block;
  }
  for (const auto& p : m.patches) {
    std::string block;
    std::size_t count = 0;
    for (std::size_t f = 0; f < m.triangles.size(); ++f) {
      if (m.triangle_patch[f] != p.id) continue;
      ++count;
      block += std::to_string(tag++);
      for (int v : m.triangles[f]) block += ' ' + std::to_string(v + 1);
      block += '\n';
    }
    s += "2 " + std::to_string(p.id.value) + " 2 " + std::to_string(count) + '\n' + block;
  }
  return s + "$EndElements\n";
}

inline std::string reference_vtu(const TetMesh& m) {
  const std::size_t nt = m.tets.size(), nf = m.triangles.size();
  auto array = [](const char* type, const char* name, const std::string& rows_text,
                  const char* extra = "") {
    return std::string("        <DataArray type=\"") + type + "\" Name=\"" + name + "\"" + extra +
           " format=\"ascii\">\n" + rows_text + "        </DataArray>\n";
  };
  std::string points;
  for (const Point3& p : m.vertices) points += num(p.x) + ' ' + num(p.y) + ' ' + num(p.z) + '\n';
  std::vector<long long> connectivity, offsets, types, subdomain, patch;
  for (std::size_t t = 0; t < nt; ++t) {
    connectivity.insert(connectivity.end(), m.tets[t].begin(), m.tets[t].end());
    offsets.push_back(static_cast<long long>(connectivity.size()));
    types.push_back(10);
    subdomain.push_back(m.tet_subdomain[t].value);
    patch.push_back(0);
  }
  for (std::size_t f = 0; f < nf; ++f) {
    connectivity.insert(connectivity.end(), m.triangles[f].begin(), m.triangles[f].end());
    offsets.push_back(static_cast<long long>(connectivity.size()));
    types.push_back(5);
    subdomain.push_back(0);
    patch.push_back(m.triangle_patch[f].value);
  }
  // The names as field data: "<name>" -> id and dimension, each name once.
  std::string names;
  std::vector<std::string> seen;
  auto field = [&](const std::string& name, int id, int dim) {
    if (std::find(seen.begin(), seen.end(), name) != seen.end()) return;
    seen.push_back(name);
    names += "      <DataArray type=\"Int32\" Name=\"" + name +
             "\" NumberOfTuples=\"1\" format=\"ascii\">" + std::to_string(id) + ' ' +
             std::to_string(dim) + "</DataArray>\n";
  };
  for (const SubdomainInfo& d : m.subdomains) {
    field(d.name.empty() ? "subdomain_" + std::to_string(d.id.value) : d.name, d.id.value, 3);
  }
  for (const PatchInfo& p : m.patches) {
    field(p.name.empty() ? "patch_" + std::to_string(p.id.value) : p.name, p.id.value, 2);
  }
  if (!names.empty()) names = "    <FieldData>\n" + names + "    </FieldData>\n";
  return "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" "
         "byte_order=\"LittleEndian\" header_type=\"UInt64\">\n  <UnstructuredGrid>\n" +
         names + "    <Piece NumberOfPoints=\"" + std::to_string(m.vertices.size()) +
         "\" NumberOfCells=\"" + std::to_string(nt + nf) + "\">\n      <Points>\n" +
         array("Float64", "Points", points, " NumberOfComponents=\"3\"") +
         "      </Points>\n      <Cells>\n" +
         array("Int64", "connectivity", rows(connectivity, 12)) +
         array("Int64", "offsets", rows(offsets, 12)) + array("UInt8", "types", rows(types, 24)) +
         "      </Cells>\n      <CellData Scalars=\"subdomain\">\n" +
         array("Int32", "subdomain", rows(subdomain, 24)) +
         array("Int32", "patch", rows(patch, 24)) +
         "      </CellData>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
}

}  // namespace rdmesh::testing
