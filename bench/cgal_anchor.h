// CGAL Mesh_3 run on the benchmark domains: the anchor rdmesh is measured against.
// No CGAL here: Mesh_3 is instantiated only in cgal_anchor.cpp.
#pragma once

#include <cstddef>
#include <string>

struct AnchorResult {
  std::size_t tets = 0;      ///< cells in the complex
  std::size_t vertices = 0;  ///< vertices of those cells
  double seconds = 0;        ///< wall time of make_mesh_3 only
  double min_dihedral_deg = 0;
  double max_radius_edge = 0;
  double volume = 0;             ///< total volume of the cells, a sanity check
  std::size_t non_positive = 0;  ///< cells that are not positively oriented (expected 0)
  std::size_t below_10_deg = 0;  ///< cells with a dihedral angle < 10 degrees
  // --optimize only: make_mesh_3's perturb() and exude() as separate, timed steps.
  double min_dihedral_before_deg = 0;     ///< after refinement
  std::size_t below_10_deg_before = 0;    ///< after refinement
  double min_dihedral_perturbed_deg = 0;  ///< after perturb_mesh_3
  double refine_seconds = 0;              ///< make_mesh_3 with no_perturb(), no_exude()
  double perturb_seconds = 0;  ///< perturb_mesh_3 (time limit = refine time, as make_mesh_3)
  double exude_seconds = 0;    ///< exude_mesh_3 (time limit = refine time, as make_mesh_3)
};

/// Meshes `shape` ("sphere" | "torus", see shapes.h) with make_mesh_3, sequential,
/// criteria: facet angle 25 deg, facet size = cell size = h, facet distance h/10,
/// cell radius-edge 3, no perturbation, no exudation.
/// `relative_error_bound` is Labeled_mesh_domain_3's accuracy of surface
/// intersections, relative to the box diagonal (CGAL's default 1e-3).
/// Throws std::invalid_argument for an unknown shape.
/// With `optimize`, the mesh is then perturbed and exuded exactly as
/// make_mesh_3(..., perturb(), exude()) does (default bounds, each step's time
/// limit = the refinement time), each step timed and measured; `seconds` is
/// then the total.
AnchorResult run_cgal_anchor(const std::string& shape, double h, double relative_error_bound = 1e-3,
                             bool optimize = false);

/// CGAL version the anchor was compiled against, e.g. "5.5.1".
std::string cgal_anchor_version();
