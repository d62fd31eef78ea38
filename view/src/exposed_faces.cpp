#include "exposed_faces.h"

#include <algorithm>
#include <array>

namespace rdmesh::view::detail {
namespace {

/// The face's two larger vertices and its (tet, local) code, in its smallest vertex's bucket.
struct Entry {
  int b, c;
  std::uint32_t code;  ///< 4 * tet + local
  bool operator<(const Entry& o) const {
    return b != o.b ? b < o.b : c != o.c ? c < o.c : code < o.code;
  }
};

std::array<int, 3> sorted_face(const std::array<int, 4>& tet, int local) {
  std::array<int, 3> f{tet[(local + 1) % 4], tet[(local + 2) % 4], tet[(local + 3) % 4]};
  if (f[0] > f[1]) std::swap(f[0], f[1]);
  if (f[1] > f[2]) std::swap(f[1], f[2]);
  if (f[0] > f[1]) std::swap(f[0], f[1]);
  return f;
}

}  // namespace

std::vector<TetFace> exposed_faces(const ViewMesh& mesh, const std::vector<char>& keep) {
  auto kept = [&](std::size_t t) { return keep.empty() || keep[t] != 0; };
  std::vector<std::uint32_t> start(mesh.points.size() + 1, 0);
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    if (!kept(t)) continue;
    for (int k = 0; k < 4; ++k) ++start[sorted_face(mesh.tets[t], k)[0] + 1];
  }
  for (std::size_t v = 0; v < mesh.points.size(); ++v) start[v + 1] += start[v];
  std::vector<Entry> entries(start.back());
  std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    if (!kept(t)) continue;
    for (int k = 0; k < 4; ++k) {
      const std::array<int, 3> f = sorted_face(mesh.tets[t], k);
      entries[fill[f[0]]++] = {f[1], f[2], static_cast<std::uint32_t>(4 * t + k)};
    }
  }
  std::vector<TetFace> out;
  for (std::size_t v = 0; v < mesh.points.size(); ++v) {
    const auto first = entries.begin() + start[v], last = entries.begin() + start[v + 1];
    std::sort(first, last);
    for (auto e = first; e != last;) {
      auto next = e + 1;
      while (next != last && next->b == e->b && next->c == e->c) ++next;
      if (next - e == 1) out.push_back({e->code / 4, e->code % 4});
      e = next;
    }
  }
  std::sort(out.begin(), out.end(), [](const TetFace& a, const TetFace& b) {
    return a.tet != b.tet ? a.tet < b.tet : a.local < b.local;
  });
  return out;
}

}  // namespace rdmesh::view::detail
