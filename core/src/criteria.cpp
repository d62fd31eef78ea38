#include "rdmesh/criteria.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "rdmesh/errors.h"
#include "rdmesh/number_text.h"

namespace rdmesh {
namespace {

void require_positive(double v, const char* what) {
  if (!(v > 0.0) || !std::isfinite(v)) {
    throw InputError(std::string(what) + " must be a positive finite number, got " +
                     short_number(v));
  }
}

void require_positive(const ScalarField& f, const char* what) {
  if (f.is_uniform()) require_positive(f.constant, what);
}

constexpr int kSamples = 16;  // per axis, nodes of a regular grid over the box

/// Calls visit(p) on the kSamples^3 grid nodes over `box` (its corners included).
template <class Visit>
void for_each_sample(const Box3& box, Visit&& visit) {
  auto at = [](double lo, double hi, int i) {
    return i == kSamples - 1 ? hi : lo + (hi - lo) * i / (kSamples - 1);
  };
  for (int k = 0; k < kSamples; ++k) {
    for (int j = 0; j < kSamples; ++j) {
      for (int i = 0; i < kSamples; ++i) {
        visit(Point3{at(box.lo.x, box.hi.x, i), at(box.lo.y, box.hi.y, j),
                     at(box.lo.z, box.hi.z, k)});
      }
    }
  }
}

/// A size field positive, finite and not below `min_size` at every sample.
void check_field(const ScalarField& f, const char* what, const Box3& box, double min_size) {
  auto check = [&](const Point3& p) {
    const double v = f(p);
    const std::string at = f.is_uniform() ? "" : " at " + point_text(p);
    if (!(v > 0.0) || !std::isfinite(v)) {
      throw InputError(std::string(what) + " is " + short_number(v) + at +
                       "; it must be positive and finite everywhere in the box");
    }
    if (v < min_size) {
      throw InputError(std::string(what) + " " + short_number(v) + at +
                       " is below the minimum size " + short_number(min_size) +
                       " (no two vertices come closer): the run could not reach it");
    }
  };
  if (f.is_uniform()) {
    check(box.center());
  } else {
    for_each_sample(box, check);
  }
}

/// mean over the samples of 1 / f^power (f positive: check_field first).
double mean_inverse_power(const ScalarField& f, const Box3& box, int power) {
  if (f.is_uniform()) return std::pow(f.constant, -power);
  double sum = 0;
  for_each_sample(box, [&](const Point3& p) { sum += std::pow(f(p), -power); });
  return sum / (kSamples * kSamples * kSamples);
}

}  // namespace

double Criteria::min_size_for(const Box3& box) const {
  // The default when min_size is 0, as a fraction of the bounding-box diagonal.
  constexpr double kDefaultMinSizeFraction = 1e-4;
  return min_size > 0 ? min_size : kDefaultMinSizeFraction * box.diagonal();
}

void Criteria::validate() const {
  require_positive(edge_size, "edge size");
  require_positive(facet_size, "facet size");
  require_positive(cell_size, "cell size");
  require_positive(facet_distance, "facet distance");
  require_positive(cell_radius_edge, "radius-edge bound");
  if (cell_radius_edge < 2.0) {
    throw InputError("radius-edge bound " + short_number(cell_radius_edge) +
                     " is below 2, RR-7912's bound for termination: refinement might not end");
  }
  if (!(facet_angle_deg > 0.0 && facet_angle_deg <= 30.0)) {
    throw InputError(
        "facet angle must be in (0, 30] degrees (above 30 refinement might not "
        "end), got " +
        short_number(facet_angle_deg));
  }
  if (!(min_size >= 0.0) || !std::isfinite(min_size)) {
    throw InputError("minimum size must be >= 0, got " + short_number(min_size));
  }
}

ElementEstimate estimate_elements(const Criteria& c, const Box3& box, double curve_length) {
  const Point3 e = box.hi - box.lo;
  const double volume = e.x * e.y * e.z, area = 2 * (e.x * e.y + e.y * e.z + e.z * e.x);
  const double curvature_size = std::sqrt(box.diagonal() * c.facet_distance(box.center()));
  ScalarField surface = c.facet_size;
  if (surface.is_uniform()) {
    surface.constant = std::min(surface.constant, curvature_size);
  } else {
    surface.field = [f = c.facet_size.field, curvature_size](const Point3& p) {
      return std::min(f(p), curvature_size);
    };
  }
  ElementEstimate out;
  out.tetrahedra = 5 * volume * mean_inverse_power(c.cell_size, box, 3);
  out.triangles = 2 * area * mean_inverse_power(surface, box, 2);
  out.edges = curve_length * mean_inverse_power(c.edge_size, box, 1);
  return out;
}

void check_feasible(const Criteria& c, const Box3& box, double curve_length, double max_elements) {
  c.validate();
  const double min_size = c.min_size_for(box);
  check_field(c.edge_size, "edge size", box, min_size);
  check_field(c.facet_size, "facet size", box, min_size);
  check_field(c.cell_size, "cell size", box, min_size);
  check_field(c.facet_distance, "facet distance", box, min_size);
  const ElementEstimate n = estimate_elements(c, box, curve_length);
  if (!(n.total() <= max_elements)) {
    throw InputError("the sizes imply about " + short_number(n.total()) + " elements (" +
                     short_number(n.tetrahedra) + " tetrahedra, " + short_number(n.triangles) +
                     " boundary triangles, " + short_number(n.edges) +
                     " curve edges), above the limit of " + short_number(max_elements) +
                     ": coarsen the sizes, or raise the limit with --max-elements N");
  }
}

Criteria default_criteria(const Box3& box) {
  Criteria c;
  const double h = box.diagonal() / 20.0;
  c.edge_size = ScalarField::uniform(h);
  c.facet_size = ScalarField::uniform(h);
  c.cell_size = ScalarField::uniform(h);
  c.facet_distance = ScalarField::uniform(h / 10.0);
  return c;
}

}  // namespace rdmesh
