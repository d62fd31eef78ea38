// Sizes asked per entity of the domain (a patch, a curve, a subdomain),
// graded away from it, folded into the Criteria's size fields by taking the
// minimum with what they already say.
//
// Near entity e of size h_e the size is h_e + (grade - 1) x distance to e:
// neighbouring elements then differ by at most a factor `grade`. Distances
// are measured to points sampled on the entity: along a curve at h_e / 2 of
// arc length (Curve::parameter_at_length); on a patch at h_e / 2 across the
// triangles of a first, surface-only mesh at the base sizes, projected onto
// the patch (DomainOracle::project). A subdomain's size holds everywhere in
// it (one DomainOracle::locate per evaluation) and grades away from its
// patches. Edge and facet sizes follow patches and curves; the cell size
// follows all three.
#pragma once

#include <string>
#include <vector>

#include "rdmesh/criteria.h"
#include "rdmesh/oracle.h"
#include "rdmesh/tet_mesh.h"

namespace rdmesh {

struct EntitySize {
  enum class Kind { kPatch, kCurve, kSubdomain };
  Kind kind = Kind::kPatch;
  int id = 0;         ///< patch, curve or subdomain id
  double size = 0;    ///< asked size (an absolute length, as Criteria's)
  std::string label;  ///< how the user named it, e.g. "face:12", for messages and reports
};

/// Parses "KIND:WHICH=SIZE": KIND is face (or patch), curve (or edge), solid
/// (or subdomain); WHICH an id or a name (the oracle's, as the .msh physical
/// groups show them; double quotes optional). Throws InputError naming `text`
/// for bad syntax, an unknown entity or a size that is not a positive number.
EntitySize parse_entity_size(const std::string& text, const DomainOracle& oracle);

/// Lowers criteria.edge_size, facet_size and cell_size to the graded entity
/// sizes (see the file comment). `grade` > 1. Throws InputError when a size
/// is below criteria.min_size_for(box) or `grade` is not above 1.
void apply_entity_sizes(const DomainOracle& oracle, const std::vector<EntitySize>& sizes,
                        double grade, Criteria& criteria);

/// What a mesh achieved on each entity: the lengths of the edges of its
/// triangles (patch), feature edges (curve) or tetrahedra (subdomain).
struct AchievedSize {
  EntitySize asked;
  std::size_t edges = 0;
  double mean_edge = 0, max_edge = 0;
};
std::vector<AchievedSize> achieved_sizes(const TetMesh& mesh, const std::vector<EntitySize>& sizes);

}  // namespace rdmesh
