// Triangle-mesh inputs in the benchmark: rdmesh's TriangleMeshOracle against
// CGAL Mesh_3's Polyhedral_mesh_domain_with_features_3 (feature angle 60 degrees),
// same criteria (edge, facet and cell size h, facet distance h / 10, facet angle
// 25, radius-edge 2); with `optimize`, rdmesh's exudation against CGAL's
// perturb_mesh_3 + exude_mesh_3, else no optimizer on either side.
#pragma once

#include <string>

#include "cgal_anchor.h"
#include "rdmesh_side.h"

/// Whether a benchmark shape names a triangle mesh file ("mesh:FILE", FILE in
/// the shared data's mesh/ folder, $RDMESH_DATA_DIR or ../shared/data).
bool is_polyhedral_shape(const std::string& shape);

/// rdmesh on the mesh file of `shape`, h = `h_fraction` of the mesh box diagonal.
RdmeshResult run_rdmesh_polyhedral(const std::string& shape, double h_fraction, bool optimize);

/// CGAL Mesh_3 with features on the same file and criteria.
AnchorResult run_cgal_polyhedral(const std::string& shape, double h_fraction, bool optimize);
