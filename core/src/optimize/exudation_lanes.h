// Private to core/: the two parts of space in which exudation pumps weights on
// two threads at once, with a result that does not depend on the threads.
//
// A plane through the median of the vertices to be pumped cuts space in two
// lanes; every vertex carries its lane (VertexInfo::lane). A lane owns the
// cells whose finite vertices are all its own: it reads the marks of, and
// writes, only those, and leaves a vertex whose star, zone or zone neighbours
// reach past them to a later round. Two lanes never share a cell they own, nor
// a cell next to one (a facet has three vertices, at least two of them finite:
// a cell next to one a lane owns has vertices of that lane, so the other lane
// does not own it), and nobody writes a cell neither owns. So each lane does
// exactly what it would do alone, whatever the other does at the same time.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "../triangulation_types.h"

namespace rdmesh::detail {

/// Lanes of one round.
inline constexpr int kExudationLanes = 2;
/// VertexInfo::lane holds a set of lanes, one bit each: a finite vertex's is
/// its own lane's bit; the infinite vertex holds every lane when infinite cells
/// may be owned (those whose finite vertices share a lane), none otherwise.
inline constexpr std::uint8_t kAnyLane = 0xff;
inline constexpr std::uint8_t kNoLane = 0;
inline constexpr std::uint8_t lane_bit(int lane) { return static_cast<std::uint8_t>(1u << lane); }

/// Whether cell c lies in lane `lane` (all its vertices hold it).
inline bool in_lane(Cell_handle c, int lane) {
  const unsigned lanes = c->vertex(0)->info().lane & c->vertex(1)->info().lane &
                         c->vertex(2)->info().lane & c->vertex(3)->info().lane;
  return (lanes >> lane) & 1u;
}

/// Cuts space at the median of `work`'s coordinates along `axis` (0: x, 1: y,
/// 2: z): every finite vertex gets lane 0 below it, 1 at or above. The
/// infinite vertex gets kAnyLane when some infinite cell has finite vertices
/// in both lanes (its cell() then becomes that cell, so no lane rewrites it),
/// else kNoLane.
void assign_lanes(Triangulation& tr, const std::vector<Vertex_handle>& work, int axis);
/// The same cut at `split` on `axis`: lane 0 below, 1 at or above.
void assign_lanes_at(Triangulation& tr, int axis, double split);
/// A point's coordinate along `axis` (0: x, 1: y, 2: z).
inline double coordinate(const Point3& p, int axis) {
  return axis == 0 ? p.x : axis == 1 ? p.y : p.z;
}
/// The extent of `box` along `axis`.
inline double extent(const Box3& box, int axis) {
  return coordinate(box.hi, axis) - coordinate(box.lo, axis);
}
/// The median of `values` (the upper one of an even count; 0 when empty),
/// where a cut goes. Reorders them.
double median(std::vector<double>& values);

/// The box of the triangulation's finite vertices.
Box3 vertex_box(const Triangulation& tr);
/// The three axes by decreasing extent of `box` (equal extents in x, y, z order).
std::array<int, 3> axes_by_extent(const Box3& box);

}  // namespace rdmesh::detail
