// Numbers and points in messages, printed with %g: tiny values never print as
// 0.000000, huge ones stay short.
#pragma once

#include <cstdio>
#include <string>

#include "rdmesh/geometry.h"

namespace rdmesh {

inline std::string short_number(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", v);
  return buffer;
}

/// "(x, y, z)" with short_number coordinates.
inline std::string point_text(const Point3& p) {
  std::string out = "(";  // appends: GCC 12 warns (-Wrestrict) on "literal" + string
  out.append(short_number(p.x)).append(", ").append(short_number(p.y)).append(", ");
  return out.append(short_number(p.z)).append(")");
}

}  // namespace rdmesh
