// Invariant checks shared by the core tests: each asserts a property of
// RR-7912's output (orientation, conformity, labels, approximation).
#pragma once

#include <array>
#include <map>
#include <set>
#include <vector>

#include "rdmesh/oracle.h"
#include "rdmesh/tet_mesh.h"

namespace rdmesh::test {

/// Every tetrahedron has positive signed volume.
void expect_positive_orientation(const TetMesh& mesh);

/// Face matching: every tet face is shared by at most two tets, and the faces
/// that separate two labels (or a tet from the outside) are exactly the
/// labelled triangles, each present once. Also every vertex is used.
void expect_conforming(const TetMesh& mesh);

/// The label of each tet is the oracle's label at its circumcenter (D|O).
void expect_labels_match_oracle(const TetMesh& mesh, const DomainOracle& oracle);

/// Triangles of `patch` (all patches when patch.value == 0).
std::vector<std::array<int, 3>> patch_triangles(const TetMesh& mesh, PatchId patch = PatchId{0});

/// Number of edge-connected components of a triangle set.
int connected_components(const std::vector<std::array<int, 3>>& triangles);

/// Degree of each vertex in the feature edges of `curve`; `count` receives the number of edges.
std::map<int, int> curve_degrees(const TetMesh& mesh, CurveId curve, std::size_t& count);

/// Total volume of the tets labelled `sub` (all labels when sub.value == 0).
double volume(const TetMesh& mesh, SubdomainId sub = SubdomainId{0});

/// The smallest dihedral angle of the tetrahedra, in degrees (180 for none).
double min_dihedral_deg(const TetMesh& mesh);

}  // namespace rdmesh::test
