// Links rdmesh::cad from the installed package: reads a CAD model and prints
// each solid's exact volume. Exit 1 unless every solid has a positive volume.
#include <cstdio>
#include <exception>

#include "rdmesh/cad_oracle.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: cad_volumes MODEL.step\n");
    return 2;
  }
  try {
    const auto cad = rdmesh::load_cad_file(argv[1]);
    const auto solids = cad->subdomains();
    bool ok = !solids.empty();
    for (const rdmesh::SubdomainInfo& s : solids) {
      const double v = cad->exact_volume(s.id);
      std::printf("%s: %.6g\n", s.name.c_str(), v);
      ok = ok && v > 0;
    }
    return ok ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cad_volumes: %s\n", e.what());
    return 1;
  }
}
