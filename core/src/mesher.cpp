#include "rdmesh/mesher.h"

#include <chrono>
#include <set>
#include <string>

#include "rdmesh/errors.h"

#include "optimize/sliver_exuder.h"
#include "refiner.h"

namespace rdmesh {
namespace {

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

/// An empty mesh is an error, a patch without triangles a warning in the stats.
void check_output(const DomainOracle& oracle, MeshResult& result) {
  if (result.mesh.tets.empty()) {
    throw OracleError("refinement produced no tetrahedron: the oracle's " +
                      std::to_string(result.stats.initial_points) +
                      " initial points do not capture the domain");
  }
  std::set<int> present;
  for (const PatchId& p : result.mesh.triangle_patch) present.insert(p.value);
  for (const PatchInfo& patch : oracle.patches()) {
    if (!present.count(patch.id.value)) result.stats.missing_patches.push_back(patch.id);
  }
}

}  // namespace

MeshResult generate_mesh(const DomainOracle& oracle, const Criteria& criteria,
                         const MeshOptions& options) {
  criteria.validate();
  detail::Refiner refiner(oracle, criteria, options);
  auto t = std::chrono::steady_clock::now();
  refiner.insert_initial_points();
  const double initial = seconds_since(t);

  t = std::chrono::steady_clock::now();
  refiner.refine();
  const double refine = seconds_since(t);

  MeshResult result;
  if (options.exudation.enabled) {
    result.exudation = detail::exude_slivers(refiner.triangulation(), criteria, options.exudation);
  }

  t = std::chrono::steady_clock::now();
  result.mesh = refiner.extract_mesh();
  result.stats = refiner.stats();
  result.stats.seconds_initial = initial;
  result.stats.seconds_refine = refine;
  result.stats.seconds_extract = seconds_since(t);
  check_output(oracle, result);
  return result;
}

}  // namespace rdmesh
