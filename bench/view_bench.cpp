// rdmesh_view_bench: the cost of a picture of a ~1M-tetrahedron mesh.
//
// The mesh is a cube of n^3 cells, each split into the 6 Kuhn tetrahedra
// (n = 55: 998,250 tetrahedra), its inner vertices moved by a fixed pseudo-random
// 20 % of a cell so that faces are not aligned; the tetrahedra inside the
// central ball are subdomain 2, the others 1; the boundary triangles carry one
// patch per cube side and one for the ball's interface.
// Timed, best of --repeat runs (default 3):
//   anchor   writing the same mesh as Gmsh 4.1 (rdmesh::write_gmsh41 into
//            memory): what every run already pays for its output;
//   picture  render_picture + encode_png at 1600x900 (what --picture adds);
//   read     read_view_mesh of that .msh file (what `rdmesh view` adds).
// Prints one Markdown table with seconds and the ratios picture/anchor and
// read/anchor. The goal: a picture of 1M tetrahedra in under 3 s.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "rdmesh/mesh_writers.h"
#include "rdmesh/picture.h"
#include "rdmesh/view_conversion.h"
#include "rdmesh/view_mesh.h"

namespace {

using rdmesh::Point3;

/// Kuhn-subdivided jittered cube with a labelled inner ball (see the file comment).
rdmesh::TetMesh grid_mesh(int n) {
  rdmesh::TetMesh m;
  auto index = [n](int i, int j, int k) { return i + (n + 1) * (j + (n + 1) * k); };
  std::uint64_t state = 12345;
  auto random = [&state] {  // deterministic LCG in [0, 1)
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(state >> 11) / 9007199254740992.0;
  };
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        const bool inner = i > 0 && j > 0 && k > 0 && i < n && j < n && k < n;
        const double jitter = inner ? 0.2 : 0;
        m.vertices.push_back({(i + jitter * (random() - 0.5)) / n,
                              (j + jitter * (random() - 0.5)) / n,
                              (k + jitter * (random() - 0.5)) / n});
      }
  const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const double dx = (i + 0.5) / n - 0.5, dy = (j + 0.5) / n - 0.5, dz = (k + 0.5) / n - 0.5;
        const int subdomain = dx * dx + dy * dy + dz * dz < 0.09 ? 2 : 1;
        for (const auto& perm : perms) {
          int c[3] = {i, j, k};
          std::array<int, 4> tet{index(i, j, k), 0, 0, 0};
          for (int s = 0; s < 3; ++s) {
            ++c[perm[s]];
            tet[s + 1] = index(c[0], c[1], c[2]);
          }
          m.tets.push_back(tet);
          m.tet_subdomain.push_back(rdmesh::SubdomainId(subdomain));
        }
      }
  // Faces seen once are on the cube's sides; faces between labels are the interface.
  struct Face {
    std::array<int, 3> key, face;
    int subdomain;
  };
  std::vector<Face> faces;
  faces.reserve(4 * m.tets.size());
  for (std::size_t t = 0; t < m.tets.size(); ++t) {
    for (int f = 0; f < 4; ++f) {
      std::array<int, 3> face{m.tets[t][(f + 1) % 4], m.tets[t][(f + 2) % 4],
                              m.tets[t][(f + 3) % 4]};
      std::array<int, 3> key = face;
      std::sort(key.begin(), key.end());
      faces.push_back({key, face, m.tet_subdomain[t].value});
    }
  }
  std::sort(faces.begin(), faces.end(), [](const Face& a, const Face& b) { return a.key < b.key; });
  for (std::size_t f = 0; f < faces.size();) {
    const bool pair = f + 1 < faces.size() && faces[f + 1].key == faces[f].key;
    if (!pair || faces[f].subdomain != faces[f + 1].subdomain) {
      int patch = 7;
      if (!pair) {
        const Point3& p = m.vertices[faces[f].key[0]];
        const Point3 c =
            (1.0 / 3) * (p + m.vertices[faces[f].key[1]] + m.vertices[faces[f].key[2]]);
        patch = c.x == 0 ? 1 : c.x == 1 ? 2 : c.y == 0 ? 3 : c.y == 1 ? 4 : c.z == 0 ? 5 : 6;
      }
      m.triangles.push_back(faces[f].face);
      m.triangle_patch.push_back(rdmesh::PatchId(patch));
    }
    f += pair ? 2 : 1;
  }
  m.subdomains = {{rdmesh::SubdomainId(1), "cube"}, {rdmesh::SubdomainId(2), "ball"}};
  return m;
}

template <class F>
double best_seconds(int repeat, F f) {
  double best = 1e300;
  for (int r = 0; r < repeat; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    best = std::min(best,
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  int n = 55, repeat = 3;
  std::string keep;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--cells" && i + 1 < argc) {
      n = std::atoi(argv[++i]);
    } else if (a == "--repeat" && i + 1 < argc) {
      repeat = std::max(1, std::atoi(argv[++i]));
    } else if (a == "--keep" && i + 1 < argc) {
      keep = argv[++i];  // also write the picture there, to look at it
    } else {
      std::fprintf(stderr, "usage: rdmesh_view_bench [--cells N] [--repeat R] [--keep FILE.png]\n");
      return 2;
    }
  }
  std::fprintf(stderr, "building the %d^3 x 6 grid...\n", n);
  const rdmesh::TetMesh mesh = grid_mesh(n);
  const rdmesh::view::ViewMesh view = rdmesh::to_view_mesh(mesh);
  rdmesh::view::PictureOptions options;
  options.title = "kuhn grid " + std::to_string(n) + "^3";

  std::string msh;
  const double anchor = best_seconds(repeat, [&] {
    std::ostringstream out;
    rdmesh::write_gmsh41(mesh, out);
    msh = std::move(out).str();
  });
  std::size_t png_bytes = 0;
  const double picture = best_seconds(repeat, [&] {
    png_bytes = rdmesh::view::encode_png(rdmesh::view::render_picture(view, options)).size();
  });
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / "rdmesh_view_bench.msh";
  std::ofstream(file, std::ios::binary) << msh;
  const double read =
      best_seconds(repeat, [&] { (void)rdmesh::view::read_view_mesh(file.string()); });
  std::filesystem::remove(file);
  if (!keep.empty()) rdmesh::view::render_png(view, options, keep);

  std::printf(
      "| tetrahedra | triangles | anchor: write .msh (s) | picture 1600x900 (s) | picture / anchor "
      "| "
      "read .msh (s) | read / anchor | PNG bytes |\n|---|---|---|---|---|---|---|---|\n");
  std::printf("| %zu | %zu | %.3f | %.3f | %.2f | %.3f | %.2f | %zu |\n", mesh.tets.size(),
              mesh.triangles.size(), anchor, picture, picture / anchor, read, read / anchor,
              png_bytes);
  return 0;
}
