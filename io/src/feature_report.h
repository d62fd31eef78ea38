// Internal: the 1D and 0D part of measure_quality (curves and corners).
#pragma once

#include "rdmesh/oracle.h"
#include "rdmesh/quality_report.h"
#include "rdmesh/tet_mesh.h"

namespace rdmesh::io_detail {

/// Fills r.curves, r.corners_present, r.corners_expected and
/// r.feature_max_distance (see measure_quality). `mesh` must have passed check_mesh.
void measure_features(const TetMesh& mesh, const DomainOracle* oracle, QualityReport& r);

}  // namespace rdmesh::io_detail
