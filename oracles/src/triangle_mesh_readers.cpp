// Readers of OFF, STL and OBJ triangle meshes (PLY: triangle_mesh_ply.cpp), the
// extension dispatch and duplicate-vertex merging.
#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <unordered_map>

#include "rdmesh/errors.h"
#include "rdmesh/input_file.h"
#include "rdmesh/triangle_mesh_io.h"
#include "triangle_mesh_text.h"

namespace rdmesh {
namespace {

/// Adds the polygon `ids` (already 0-based) as a fan of triangles.
void add_polygon(TriangleSoup& soup, const std::vector<long long>& ids, const LineReader& r) {
  if (ids.size() < 3) r.fail("a face needs at least 3 vertices, got " + std::to_string(ids.size()));
  const long long n = static_cast<long long>(soup.points.size());
  for (long long id : ids) {
    if (id < 0 || id >= n) {
      r.fail("vertex index " + std::to_string(id) + " out of range [0, " + std::to_string(n) + ")");
    }
  }
  for (std::size_t i = 1; i + 1 < ids.size(); ++i) {
    soup.triangles.push_back(
        {static_cast<int>(ids[0]), static_cast<int>(ids[i]), static_cast<int>(ids[i + 1])});
  }
}

float read_le_float(const unsigned char* p) {
  std::uint32_t u = std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 |
                    std::uint32_t(p[3]) << 24;
  float f;
  std::memcpy(&f, &u, 4);
  return f;
}

TriangleSoup parse_binary_stl(const std::string& data, const std::string& file) {
  const auto* bytes = reinterpret_cast<const unsigned char*>(data.data());
  const std::uint64_t count = std::uint64_t(bytes[80]) | std::uint64_t(bytes[81]) << 8 |
                              std::uint64_t(bytes[82]) << 16 | std::uint64_t(bytes[83]) << 24;
  const std::uint64_t expected = 84 + 50 * count;
  if (data.size() < expected) {
    throw InputError(file, "truncated binary STL: " + std::to_string(count) + " triangles need " +
                               std::to_string(expected) + " bytes, the file has " +
                               std::to_string(data.size()));
  }
  if (data.size() > expected) {
    throw InputError(file, "binary STL with " + std::to_string(data.size() - expected) +
                               " bytes after its " + std::to_string(count) + " triangles");
  }
  TriangleSoup soup;
  soup.points.reserve(3 * count);
  soup.triangles.reserve(count);
  for (std::uint64_t t = 0; t < count; ++t) {
    const unsigned char* rec = bytes + 84 + 50 * t + 12;  // skip the normal
    for (int v = 0; v < 3; ++v) {
      const unsigned char* c = rec + 12 * v;
      soup.points.push_back({read_le_float(c), read_le_float(c + 4), read_le_float(c + 8)});
    }
    const int base = static_cast<int>(3 * t);
    soup.triangles.push_back({base, base + 1, base + 2});
  }
  return soup;
}

TriangleSoup parse_ascii_stl(const std::string& data, const std::string& file) {
  std::istringstream in(data);
  LineReader r(in, file);
  TriangleSoup soup;
  std::vector<std::string_view> tok;
  int in_loop = -1;  // vertices seen in the current loop, -1 outside a loop
  bool solid = false;
  while (r.next(tok)) {
    const std::string_view key = tok[0];
    if (key == "solid") {
      solid = true;
    } else if (key == "outer") {
      if (in_loop >= 0) r.fail("'outer loop' inside a loop");
      in_loop = 0;
    } else if (key == "vertex") {
      if (in_loop < 0) r.fail("'vertex' outside 'outer loop'");
      if (tok.size() != 4) r.fail("'vertex' needs 3 coordinates");
      soup.points.push_back({r.real(tok[1]), r.real(tok[2]), r.real(tok[3])});
      ++in_loop;
    } else if (key == "endloop") {
      if (in_loop < 3) r.fail("a loop needs at least 3 vertices");
      const long long n = static_cast<long long>(soup.points.size());
      std::vector<long long> ids;
      for (long long i = n - in_loop; i < n; ++i) ids.push_back(i);
      add_polygon(soup, ids, r);
      in_loop = -1;
    } else if (key == "facet" || key == "endfacet" || key == "endsolid") {
    } else {
      r.fail("unexpected '" + std::string(key) + "' in ASCII STL");
    }
  }
  if (!solid) throw InputError(file, "not an STL file (no 'solid')");
  if (in_loop >= 0) throw InputError(file, "file ends inside a loop");
  return soup;
}

}  // namespace

TriangleSoup parse_off(std::istream& in, const std::string& file) {
  LineReader r(in, file);
  std::vector<std::string_view> tok;
  if (!r.next(tok)) throw InputError(file, "empty OFF file");
  if (tok[0].size() >= 3 && tok[0].substr(tok[0].size() - 3) == "OFF") {
    if (tok[0] != "OFF") r.fail("unsupported OFF variant '" + std::string(tok[0]) + "'");
    if (tok.size() > 1) {
      tok.erase(tok.begin());  // counts on the header line
    } else if (!r.next(tok)) {
      throw InputError(file, "OFF file ends before its counts");
    }
  }
  if (tok.size() < 2) r.fail("expected vertex and face counts");
  const long long nv = r.integer(tok[0]), nf = r.integer(tok[1]);
  if (nv < 0 || nf < 0) r.fail("negative count");
  TriangleSoup soup;
  soup.points.reserve(static_cast<std::size_t>(std::min(nv, 1LL << 24)));
  for (long long i = 0; i < nv; ++i) {
    if (!r.next(tok))
      throw InputError(
          file, "file ends after " + std::to_string(i) + " of " + std::to_string(nv) + " vertices");
    if (tok.size() < 3) r.fail("a vertex needs 3 coordinates");
    soup.points.push_back({r.real(tok[0]), r.real(tok[1]), r.real(tok[2])});
  }
  std::vector<long long> ids;
  for (long long i = 0; i < nf; ++i) {
    if (!r.next(tok))
      throw InputError(
          file, "file ends after " + std::to_string(i) + " of " + std::to_string(nf) + " faces");
    const long long k = r.integer(tok[0]);
    if (k < 0 || k > static_cast<long long>(tok.size()) - 1) {  // k + 1 overflows for huge k
      r.fail("face with " + std::to_string(tok.size() - 1) + " indices, expected " +
             std::to_string(k));
    }
    ids.clear();
    for (long long j = 1; j <= k; ++j) ids.push_back(r.integer(tok[j]));
    add_polygon(soup, ids, r);
  }
  return soup;
}

TriangleSoup parse_stl(std::istream& in, const std::string& file) {
  std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::size_t start = 0;
  while (start < data.size() && std::isspace(static_cast<unsigned char>(data[start]))) ++start;
  const bool says_solid = data.compare(start, 5, "solid") == 0;
  if (data.size() >= 84) {
    const auto* b = reinterpret_cast<const unsigned char*>(data.data());
    const std::uint64_t count = std::uint64_t(b[80]) | std::uint64_t(b[81]) << 8 |
                                std::uint64_t(b[82]) << 16 | std::uint64_t(b[83]) << 24;
    const bool has_nul = data.find('\0') != std::string::npos;  // never in ASCII STL
    if (data.size() == 84 + 50 * count || !says_solid || has_nul) {
      return parse_binary_stl(data, file);
    }
  }
  if (says_solid) return parse_ascii_stl(data, file);
  throw InputError(file, "truncated binary STL: " + std::to_string(data.size()) +
                             " bytes, shorter than its 84-byte header");
}

TriangleSoup parse_obj(std::istream& in, const std::string& file) {
  LineReader r(in, file);
  TriangleSoup soup;
  std::vector<std::string_view> tok;
  std::vector<long long> ids;
  while (r.next(tok)) {
    if (tok[0] == "v") {
      if (tok.size() < 4) r.fail("a vertex needs 3 coordinates");
      soup.points.push_back({r.real(tok[1]), r.real(tok[2]), r.real(tok[3])});
    } else if (tok[0] == "f") {
      ids.clear();
      const long long n = static_cast<long long>(soup.points.size());
      for (std::size_t j = 1; j < tok.size(); ++j) {
        const std::string_view s = tok[j].substr(0, tok[j].find('/'));
        const long long id = r.integer(s);
        if (id == 0) r.fail("vertex index 0 (OBJ indices start at 1)");
        ids.push_back(id > 0 ? id - 1 : n + id);
      }
      add_polygon(soup, ids, r);
    }
  }
  return soup;
}

void merge_duplicate_vertices(TriangleSoup& soup) {
  struct Hash {
    std::size_t operator()(const Point3& p) const {
      auto h = [](double d) {
        d = d == 0 ? 0.0 : d;  // -0 == 0
        std::uint64_t u;
        std::memcpy(&u, &d, 8);
        return u * 0x9E3779B97F4A7C15ull;
      };
      return h(p.x) ^ (h(p.y) >> 1) ^ (h(p.z) << 1);
    }
  };
  std::unordered_map<Point3, int, Hash> index;
  std::vector<int> remap(soup.points.size(), -1);
  std::vector<Point3> kept;
  for (auto& t : soup.triangles) {
    for (int& v : t) {
      if (v < 0 || v >= static_cast<int>(soup.points.size())) continue;  // validate_soup reports
      if (remap[v] < 0) {
        auto [it, inserted] = index.try_emplace(soup.points[v], static_cast<int>(kept.size()));
        if (inserted) kept.push_back(soup.points[v]);
        remap[v] = it->second;
      }
      v = remap[v];
    }
  }
  soup.points = std::move(kept);
}

TriangleSoup read_triangle_mesh(const std::string& path) {
  const std::string ext = lower_extension(path);
  TriangleSoup (*parse)(std::istream&, const std::string&) = nullptr;
  if (ext == ".off") parse = parse_off;
  if (ext == ".stl") parse = parse_stl;
  if (ext == ".obj") parse = parse_obj;
  if (ext == ".ply") parse = parse_ply;
  if (!parse) {
    throw InputError(
        path, "unknown triangle mesh extension '" + ext + "' (expected .off, .stl, .obj or .ply)");
  }
  check_input_file(path);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "cannot open the file");
  TriangleSoup soup = parse(in, path);
  merge_duplicate_vertices(soup);
  validate_soup(soup, path);
  return soup;
}

}  // namespace rdmesh
