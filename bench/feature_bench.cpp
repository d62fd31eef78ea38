// rdmesh_feature_bench: sharp features (RR-7912 rules R1, R2) against CGAL
// Mesh_3 with polyline features, same domains and criteria, same run.
//
//   rdmesh_feature_bench [--repeat N] [--optimize]
// --optimize: rdmesh with sliver exudation against Mesh_3 with perturb() and
// exude(); otherwise refinement only on both sides.
// Prints a Markdown table: tets, seconds, time ratio, min dihedral, and the
// number of guard rejections (rdmesh's termination guard).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "cgal_features_anchor.h"
#include "rdmesh/domain_file.h"
#include "rdmesh/mesher.h"
#include "tet_quality.h"

namespace {

struct Side {
  rdmesh_bench::MeshQuality quality;
  double seconds = 0;
  std::size_t guard = 0;
};

Side run_rdmesh(const std::string& shape, double h, bool optimize) {
  const rdmesh::LoadedDomain d =
      rdmesh::load_domain_file(std::string(RDMESH_SOURCE_DIR) + "/samples/" + shape + ".json");
  rdmesh::Criteria c;
  c.edge_size = c.facet_size = c.cell_size = rdmesh::ScalarField::uniform(h);
  c.facet_distance = h / 10;
  c.facet_angle_deg = 25;
  c.cell_radius_edge = 3;
  rdmesh::MeshOptions options;
  options.exudation.enabled = optimize;
  const auto t0 = std::chrono::steady_clock::now();
  const rdmesh::MeshResult r = rdmesh::generate_mesh(*d.oracle, c, options);
  Side s;
  s.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  s.guard = r.stats.guard_rejections;
  std::vector<rdmesh_bench::Vec3> v;
  for (const auto& p : r.mesh.vertices) v.push_back({p.x, p.y, p.z});
  std::vector<rdmesh_bench::Tet> t(r.mesh.tets.begin(), r.mesh.tets.end());
  s.quality = rdmesh_bench::mesh_quality(v, t);
  return s;
}

template <class T>
T median(std::vector<T> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  int repeat = 1;
  bool optimize = false;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--repeat") && i + 1 < argc) {
      repeat = std::max(1, std::atoi(argv[++i]));
    } else if (!std::strcmp(argv[i], "--optimize")) {
      optimize = true;
    } else {
      std::fprintf(stderr, "usage: %s [--repeat N] [--optimize]\n", argv[0]);
      return 2;
    }
  }
  std::printf(
      "| case | h | rdmesh tets | rdmesh s | CGAL tets | CGAL s | time ratio r/C | "
      "min dihedral (r / C) | rdmesh guard |\n|---|---|---|---|---|---|---|---|---|\n");
  struct Case {
    const char* shape;
    double h;
  };
  for (const Case& c : {Case{"capped_cylinder", 0.05}, Case{"capped_cylinder", 0.025},
                        Case{"cube", 0.05}, Case{"cube", 0.025}}) {
    std::vector<double> rt, ct;
    Side r;
    rdmesh_bench::FeatureAnchorResult a;
    for (int k = 0; k < repeat; ++k) {
      r = run_rdmesh(c.shape, c.h, optimize);
      a = rdmesh_bench::run_cgal_features(c.shape, c.h, optimize);
      rt.push_back(r.seconds);
      ct.push_back(a.seconds);
    }
    const double rs = median(rt), cs = median(ct);
    std::printf("| %s | %g | %zu | %.3f | %zu | %.3f | %.2f | %.2f / %.2f | %zu |\n", c.shape, c.h,
                r.quality.tets, rs, a.quality.tets, cs, rs / cs, r.quality.min_dihedral_deg,
                a.quality.min_dihedral_deg, r.guard);
    std::fflush(stdout);
  }
  return 0;
}
