// rdmesh_cgal_pipeline: a CGAL Mesh_3 user's whole run as one command, the CGAL rows
// of pipeline_bench.py. It reads the domain, meshes it with CGAL::make_mesh_3 and its
// default optimisation (perturb and exude on, lloyd and odt off), writes a Medit .mesh
// file and exits 0; a failure is one line on stderr and a non-zero exit. make_mesh_3's
// defaults limit perturb and exude each to the refinement's time: the mesh depends on
// the load a little, as it does for any CGAL user.
//
//   rdmesh_cgal_pipeline SHAPE|SURFACE.off|SURFACE.stl --size H [--parallel [--threads N]]
//                        -o OUT.mesh
//
// SHAPE is an implicit domain of shapes.h (sphere, torus: the function and the box of
// rdmesh_bench's anchor); a file is a closed triangle surface, meshed with its sharp
// edges (dihedral turn above 60 degrees) protected. The criteria are rdmesh's command
// line defaults at size H: radius-edge 2, facet angle 25, facet distance H / 10, edge,
// facet and cell size H. --parallel meshes with CGAL::Parallel_tag on TBB, at most N
// threads (default: TBB's, all cores); a build without TBB refuses it. --version prints
// CGAL's version and whether --parallel is available (pipeline_bench.py asks it first).
// No rdmesh library here: CGAL, TBB and the standard library only.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_polyhedron_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polyhedral_mesh_domain_with_features_3.h>
#include <CGAL/Random.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/make_mesh_3.h>
#include <CGAL/version_macros.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#include <tbb/version.h>
#endif

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "shapes.h"

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Implicit_domain = CGAL::Labeled_mesh_domain_3<K>;
using Polyhedron = CGAL::Mesh_polyhedron_3<K>::type;
using Surface_domain = CGAL::Polyhedral_mesh_domain_with_features_3<K, Polyhedron>;
static_assert(std::is_same_v<Surface_domain::Corner_index, int> &&
                  std::is_same_v<Surface_domain::Curve_index, int>,
              "Mesh_types' complex takes the default (int) corner and curve indices");

/// The triangulation, complex and criteria types of a domain and a concurrency tag.
template <class Domain, class Tag>
struct Mesh_types {
  using Tr = typename CGAL::Mesh_triangulation_3<Domain, CGAL::Default, Tag>::type;
  // Default corner and curve indices: int, as the domain with features uses.
  using C3t3 = CGAL::Mesh_complex_3_in_triangulation_3<Tr>;
  using Criteria = CGAL::Mesh_criteria_3<Tr>;
};

struct Options {
  std::string input, output;
  double size = 0;
  bool parallel = false;
  int threads = 0;  ///< 0: TBB's default
};

const char* const kUsage =
    "usage: rdmesh_cgal_pipeline SHAPE|SURFACE.off|SURFACE.stl --size H "
    "[--parallel [--threads N]] -o OUT.mesh | --version";

void print_version() {
#ifdef CGAL_LINKED_WITH_TBB
  std::cout << "CGAL " CGAL_VERSION_STR " (--parallel: Parallel_tag on TBB " TBB_VERSION_STRING
               ")\n";
#else
  std::cout << "CGAL " CGAL_VERSION_STR " (--parallel unavailable: built without TBB)\n";
#endif
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw std::invalid_argument(a + " needs a value");
      return argv[++i];
    };
    if (a == "--size") {
      o.size = std::atof(value().c_str());
    } else if (a == "--threads") {
      o.threads = std::atoi(value().c_str());
      if (o.threads < 1) throw std::invalid_argument("--threads needs a positive count");
    } else if (a == "--parallel") {
      o.parallel = true;
    } else if (a == "-o") {
      o.output = value();
    } else if (!a.empty() && a[0] == '-') {
      throw std::invalid_argument("unknown option " + a + "; " + kUsage);
    } else if (o.input.empty()) {
      o.input = a;
    } else {
      throw std::invalid_argument("two inputs: " + o.input + " and " + a);
    }
  }
  if (o.input.empty() || o.output.empty() || !(o.size > 0)) throw std::invalid_argument(kUsage);
  if (o.threads > 0 && !o.parallel) throw std::invalid_argument("--threads needs --parallel");
  return o;
}

/// rdmesh's command line defaults at size h, on shapes.h's criteria: the same facet
/// angle, sizes and facet distance, but radius-edge 2 (rdmesh's default) instead of
/// the anchor's 3. The edge size only matters on a domain with features.
template <class Criteria>
Criteria pipeline_criteria(double h) {
  rdmesh_bench::BenchCriteria c = rdmesh_bench::bench_criteria(h);
  c.cell_radius_edge = 2.0;
  namespace params = CGAL::parameters;
  return Criteria(params::edge_size = h, params::facet_angle = c.facet_angle_deg,
                  params::facet_size = c.facet_size, params::facet_distance = c.facet_distance,
                  params::cell_radius_edge_ratio = c.cell_radius_edge,
                  params::cell_size = c.cell_size);
}

/// make_mesh_3 with its defaults (perturb and exude after refinement), then the
/// Medit file as CGAL 5.5 writes it (coordinates at 17 digits, each boundary
/// triangle once per side).
template <class Tag, class Domain>
void mesh_and_write(const Domain& domain, const Options& o) {
  using Types = Mesh_types<Domain, Tag>;
  const auto criteria = pipeline_criteria<typename Types::Criteria>(o.size);
  const auto c3t3 = CGAL::make_mesh_3<typename Types::C3t3>(domain, criteria);
  if (c3t3.number_of_cells_in_complex() == 0) throw std::runtime_error("empty mesh");
  std::ofstream out(o.output);
  c3t3.output_to_medit(out);
  out.close();
  if (!out) throw std::runtime_error("cannot write " + o.output);
}

template <class Tag>
void run(const Options& o) {
  // Fixed seed for the initial points (CGAL's default generator is seeded from the
  // clock); perturb's and exude's time limits still make the meshes vary a little.
  CGAL::Random rng(0);
  if (const rdmesh_bench::Shape* shape = rdmesh_bench::find_shape(o.input)) {
    const auto f = shape->f;
    const CGAL::Bbox_3 box(shape->lo[0], shape->lo[1], shape->lo[2], shape->hi[0], shape->hi[1],
                           shape->hi[2]);
    const Implicit_domain domain = Implicit_domain::create_implicit_mesh_domain(
        [f](const K::Point_3& p) { return f(p.x(), p.y(), p.z()); }, box,
        CGAL::parameters::p_rng = &rng);
    mesh_and_write<Tag>(domain, o);
    return;
  }
  // Reads the soup, merges duplicate points (an STL repeats them) and orients it.
  // CGAL's reader prints its own line for a missing file: open it first.
  if (!std::ifstream(o.input)) throw std::runtime_error("cannot open " + o.input);
  Polyhedron surface;
  if (!CGAL::Polygon_mesh_processing::IO::read_polygon_mesh(o.input, surface))
    throw std::runtime_error("cannot read " + o.input + " as a triangle surface");
  if (!CGAL::is_triangle_mesh(surface) || !CGAL::is_closed(surface))
    throw std::runtime_error(o.input + " is not a closed triangle surface");
  Surface_domain domain(surface, &rng);
  domain.detect_features(60);  // rdmesh's --feature-angle default
  mesh_and_write<Tag>(domain, o);
}

}  // namespace

int main(int argc, char** argv) {
  try {
    if (argc == 2 && std::string(argv[1]) == "--version") {
      print_version();
      return 0;
    }
    const Options o = parse(argc, argv);
    if (!o.parallel) {
      run<CGAL::Sequential_tag>(o);
      return 0;
    }
#ifdef CGAL_LINKED_WITH_TBB
    // Caps every TBB arena Mesh_3 makes, for as long as it lives.
    std::unique_ptr<tbb::global_control> cap;
    if (o.threads > 0)
      cap = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                  std::size_t(o.threads));
    run<CGAL::Parallel_tag>(o);
    return 0;
#else
    throw std::invalid_argument("--parallel: built without TBB (CGAL_LINKED_WITH_TBB undefined)");
#endif
  } catch (const std::invalid_argument& e) {
    std::cerr << "rdmesh_cgal_pipeline: " << e.what() << '\n';
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "rdmesh_cgal_pipeline: " << e.what() << '\n';
    return 1;
  }
}
