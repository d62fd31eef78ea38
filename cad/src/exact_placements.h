// The placements of a shape's analytic curves and surfaces, bit for bit.
//
// OpenCASCADE's BREP formats, text and binary alike, write an axis system as
// its vectors and rebuild it with gp_Ax3(P, N, Vx), which orthonormalizes
// again: an axis that a STEP transfer left orthonormal only to the last bit
// comes back a bit different (seen on drill's cones, lines and circles), and
// the mesh then differs in the last digits. The child of an isolated read
// sends the exact placements beside the binary shape; the parent writes them
// back into the same geometry, found by the same walk over faces and edges.
#pragma once

#include <TopoDS_Shape.hxx>
#include <string>

namespace rdmesh::cad {

/// The placements (gp_Ax3, gp_Ax2, gp_Ax1, gp_Ax22d, gp_Ax2d) of the
/// elementary surfaces, conics and lines under `shape`'s faces and edges
/// (through trimmed and offset geometry), tagged, in walk order, as raw bytes.
std::string save_placements(const TopoDS_Shape& shape);

/// Writes placements saved from the original of `shape` back into `shape`'s
/// geometry. False, and `shape` untouched, when the walk meets other kinds of
/// geometry than were saved.
bool restore_placements(const TopoDS_Shape& shape, const std::string& saved);

}  // namespace rdmesh::cad
