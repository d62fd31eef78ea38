// Options and statistics of the mesh optimizers that run after Delaunay
// refinement: sliver exudation (RR-7912 section 6, [CDE+00]) on the
// triangulation, then a local improvement of the extracted tetrahedra.
#pragma once

#include <array>
#include <cstddef>

namespace rdmesh {

/// Histogram of the smallest dihedral angle of each tetrahedron, in 5 degree
/// buckets: bucket i counts the tets whose smallest dihedral angle lies in
/// [5i, 5i + 5) degrees. The smallest dihedral angle of a tetrahedron is at
/// most arccos(1/3) = 70.53 degrees (the regular one), hence 15 buckets.
using DihedralHistogram = std::array<std::size_t, 15>;

/// Sliver exudation: every vertex gets a weight, chosen to maximize the
/// smallest dihedral angle of its incident tetrahedra, while the restricted
/// facets (the boundary triangles) and the tet labels stay exactly as refinement
/// left them. Vertices never move.
struct ExudationOptions {
  bool enabled = true;
  /// Stop after this many seconds; 0 = no limit.
  double time_limit_seconds = 0;
  /// Vertices with an incident tetrahedron whose smallest dihedral angle is
  /// below this bound (degrees) are pumped, worst first within blocks of
  /// space taken one after the other.
  double sliver_bound_deg = 25;
  /// Weight bound: a vertex's weight stays <= this fraction of the squared
  /// distance to its nearest neighbour. CDE+00 prove that no vertex gets
  /// hidden for (alpha N(v))^2 with alpha < 1/2 (ratio < 0.25); larger bounds
  /// give more freedom, and a move that would hide a vertex is rejected anyway.
  double max_weight_ratio = 0.4;
  /// At most this many accepted weight changes per vertex.
  int max_moves_per_vertex = 8;
  /// Pumping passes; pass k of n treats the vertices below k/n of the sliver bound.
  int passes = 1;
  /// New tetrahedra must satisfy the refinement rules for cells as the
  /// criteria state them: R5.1 (circumradius <= cell_size at the circumcenter)
  /// when keep_cell_size, R5.2 (radius-edge ratio <= cell_radius_edge) when
  /// keep_radius_edge. Exudation then never creates a tet refinement would split,
  /// at a large cost in quality (the size bound is tight after refinement): off
  /// by default, as in CGAL's exuder.
  bool keep_cell_size = false;
  bool keep_radius_edge = false;
  /// After pumping, move the volume vertices of the remaining slivers along
  /// the gradient of their worst dihedral angle (sliver perturbation), only
  /// where the changed region lies inside one subdomain away from the
  /// boundary, then pump again. A move is made only where the new cells are
  /// the cone from the moved vertex (checked exactly), so the result is the
  /// same on every call and every run.
  bool perturb = false;
  /// The perturbation treats the vertices of tets below this angle (degrees).
  double perturb_bound_deg = 15;
  /// Debug self-check after exudation (slow): the regular triangulation is
  /// valid, both sides of every facet hold the same restricted data, and
  /// labels differ exactly across restricted facets. Throws InternalError.
  bool self_check = false;
};

/// What exudation did, for the report. Angles are over the output tetrahedra
/// (the cells of D|O); 0 when there are none.
struct ExudationStats {
  bool ran = false;
  double min_dihedral_before_deg = 0;
  double min_dihedral_after_deg = 0;
  DihedralHistogram histogram_before{};
  DihedralHistogram histogram_after{};
  std::size_t moves_tried = 0;     ///< vertices whose weight was pumped
  std::size_t moves_accepted = 0;  ///< weight changes applied to the triangulation
  /// Of moves_tried, those tried inside one of two lanes (two halves of space,
  /// pumped side by side on two threads); the others were tried where the
  /// lanes meet, on one thread. The same for any thread count.
  std::size_t moves_tried_in_lanes = 0;
  std::size_t perturb_moves_tried = 0;  ///< volume vertices the perturbation tried to move
  /// (moves_tried / moves_accepted count the pumps of both pumping rounds)
  std::size_t perturb_moves_accepted = 0;     ///< vertex moves kept
  double min_dihedral_after_perturb_deg = 0;  ///< after the first pumping and the perturbation
  double perturb_seconds = 0;                 ///< included in `seconds`
  bool time_limit_reached = false;
  double seconds = 0;
};

/// The final local improvement of the extracted tetrahedra (tet_improvement.h):
/// topological flips inside one subdomain, moves of vertices on no boundary
/// triangle and insertions of new ones, driven by the worst tetrahedra. The boundary triangles,
/// feature edges, corners, labels and each subdomain's volume stay as they
/// are; the mesh is then no longer a (weighted) Delaunay triangulation.
struct TetImprovementOptions {
  bool enabled = true;
  /// Tetrahedra whose smallest dihedral angle is below this (degrees) are treated, worst first.
  double bound_deg = 20;
  /// Passes over the tetrahedra below the bound (each pass treats those left
  /// by the previous one, with the tetrahedra the changes created).
  int max_sweeps = 6;
  /// New vertices: at most this fraction of the tetrahedra (and 10 more),
  /// only for tetrahedra below this angle (degrees; the costliest step).
  double max_insertions = 0.01;
  double insertion_bound_deg = 12;
  /// Vertices on one patch only slide along it, and those inside one chain of
  /// feature edges along their curve (given the surface, see improve_tets).
  bool boundary_moves = true;
  /// Stop after this many seconds; 0 = no limit (the result is then no longer
  /// independent of the machine's speed).
  double time_limit_seconds = 0;
  /// Threads for the measures over all tetrahedra (0: all cores); the result does not depend on it.
  int threads = 1;
};

/// What the improvement did, for the report. Angles over all output tetrahedra.
struct TetImprovementStats {
  bool ran = false;
  double min_dihedral_before_deg = 0;
  double min_dihedral_after_deg = 0;
  DihedralHistogram histogram_before{};
  DihedralHistogram histogram_after{};
  std::size_t tets_before = 0;
  std::size_t tets_after = 0;
  std::size_t face_flips = 0;      ///< 2-3 flips (a face replaced by an edge)
  std::size_t edge_removals = 0;   ///< an edge and its ring of n tets replaced by 2n - 4 tets
  std::size_t vertex_moves = 0;    ///< vertices on no boundary triangle moved
  std::size_t boundary_moves = 0;  ///< vertices moved along their patch
  std::size_t curve_moves = 0;     ///< vertices moved along their curve
  /// Vertices added inside a tetrahedron and its neighbours (numbered after the others).
  std::size_t vertex_insertions = 0;
  int sweeps = 0;
  bool time_limit_reached = false;
  double seconds = 0;
};

}  // namespace rdmesh
