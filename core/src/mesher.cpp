#include "rdmesh/mesher.h"

#include <chrono>

#include "refiner.h"

namespace rdmesh {
namespace {

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
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

  t = std::chrono::steady_clock::now();
  MeshResult result;
  result.mesh = refiner.extract_mesh();
  result.stats = refiner.stats();
  result.stats.seconds_initial = initial;
  result.stats.seconds_refine = refine;
  result.stats.seconds_extract = seconds_since(t);
  return result;
}

}  // namespace rdmesh
