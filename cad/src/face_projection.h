// Internal to cad/: the closest point of a face to a point (CadOracle::project).
//
// The nearest point of the face's tessellation seeds Newton on the true surface
// (surface_evaluator.h). A foot inside the face (cells or classifier) is the
// answer. A foot outside it means the closest point is on the face's boundary:
// the nearest point of its edge polylines seeds Newton on the edge curves.
// Without a usable seed or foot, GeomAPI_ProjectPointOnSurf searches the whole
// surface; BRepExtrema is the last resort.
#pragma once

#include <array>
#include <optional>

#include "cad_model.h"

namespace rdmesh::cad {

class ThreadState;

/// The point of face `face` closest to p; nullopt when nothing converges.
/// Throws Standard_Failure.
std::optional<Point3> project_on_face(const CadOracle::Model& m, ThreadState& ts, int face,
                                      const Point3& p);

/// The (u, v) of the foot of p on face `face`'s surface (the trimmed face
/// plays no part): Newton from the nearest point of its tessellation, else
/// GeomAPI_ProjectPointOnSurf over the face's (u, v) box; nullopt when
/// neither converges. Throws Standard_Failure.
std::optional<std::array<double, 2>> foot_parameters(const CadOracle::Model& m, ThreadState& ts,
                                                     int face, const Point3& p);

/// min(limit, distance from p to face `face`), by Newton from the tessellation
/// only: the surface's foot when it is inside the face, else the boundary
/// curves. A foot at `limit` or more needs no classification (the face is a
/// part of its surface); `limit` where Newton does not converge. Throws
/// Standard_Failure.
double distance_to_face(const CadOracle::Model& m, ThreadState& ts, int face, const Point3& p,
                        double limit);

}  // namespace rdmesh::cad
