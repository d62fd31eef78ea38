// The benchmark domains and criteria, shared by the rdmesh side and the CGAL anchor so that
// both mesh exactly the same implicit function inside exactly the same box.
#pragma once

#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace rdmesh_bench {

inline constexpr double kPi = 3.14159265358979323846;

struct Shape {
  std::string name;
  std::array<double, 3> lo, hi;         ///< bounding box, identical for both meshers
  double (*f)(double, double, double);  ///< negative inside
  double exact_volume;                  ///< of the smooth domain, to check the meshes
};

/// Unit sphere x^2 + y^2 + z^2 - 1.
inline double sphere_function(double x, double y, double z) { return x * x + y * y + z * z - 1.0; }

/// Torus around the z axis, major radius R = 1, minor radius r = 0.35.
inline double torus_function(double x, double y, double z) {
  const double q = std::sqrt(x * x + y * y) - 1.0;
  return q * q + z * z - 0.35 * 0.35;
}

/// Boxes leave a margin of 0.2-0.25 around the surface on every side.
inline const std::vector<Shape>& shapes() {
  static const std::vector<Shape> all = {
      {"sphere", {-1.2, -1.2, -1.2}, {1.2, 1.2, 1.2}, &sphere_function, 4.0 / 3.0 * kPi},
      {"torus",
       {-1.6, -1.6, -0.6},
       {1.6, 1.6, 0.6},
       &torus_function,
       2.0 * kPi * kPi * 1.0 * 0.35 * 0.35},
  };
  return all;
}

/// The criteria of every benchmark case, as a function of the size h. Both
/// meshers get exactly these values.
struct BenchCriteria {
  double facet_angle_deg;
  double facet_size;
  double facet_distance;
  double cell_size;
  double cell_radius_edge;
};
inline BenchCriteria bench_criteria(double h) { return {25.0, h, h / 10.0, h, 3.0}; }

/// nullptr when unknown.
inline const Shape* find_shape(const std::string& name) {
  for (const Shape& s : shapes())
    if (s.name == name) return &s;
  return nullptr;
}

}  // namespace rdmesh_bench
