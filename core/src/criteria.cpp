#include "rdmesh/criteria.h"

#include <cmath>
#include <string>

#include "rdmesh/errors.h"

namespace rdmesh {
namespace {

void require_positive(double v, const char* what) {
  if (!(v > 0.0) || !std::isfinite(v)) {
    throw InputError(std::string(what) + " must be a positive finite number, got " +
                     std::to_string(v));
  }
}

void require_positive(const ScalarField& f, const char* what) {
  if (f.is_uniform()) require_positive(f.constant, what);
}

}  // namespace

void Criteria::validate() const {
  require_positive(edge_size, "edge size");
  require_positive(facet_size, "facet size");
  require_positive(cell_size, "cell size");
  require_positive(facet_distance, "facet distance");
  require_positive(cell_radius_edge, "radius-edge bound");
  if (!(facet_angle_deg > 0.0 && facet_angle_deg < 60.0)) {
    throw InputError("facet angle must be in (0, 60) degrees, got " +
                     std::to_string(facet_angle_deg));
  }
  if (!(min_size >= 0.0) || !std::isfinite(min_size)) {
    throw InputError("minimum size must be >= 0, got " + std::to_string(min_size));
  }
}

Criteria default_criteria(const Box3& box) {
  Criteria c;
  const double h = box.diagonal() / 20.0;
  c.edge_size = ScalarField::uniform(h);
  c.facet_size = ScalarField::uniform(h);
  c.cell_size = ScalarField::uniform(h);
  c.facet_distance = h / 10.0;
  return c;
}

}  // namespace rdmesh
