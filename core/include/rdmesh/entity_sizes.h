// Sizes asked per entity of the domain (a patch, a curve, a subdomain) and by
// curvature (rdmesh/curvature_sizes.h), graded away from where they are asked,
// folded into the Criteria's size fields by taking the minimum with what they
// already say. The library's entry point is apply_sizes(); a SizeSpec (the
// JSON sizing object of rdmesh/size_spec.h) resolves into its SizeRequests.
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
#include "rdmesh/curvature_sizes.h"
#include "rdmesh/oracle.h"
#include "rdmesh/size_spec.h"
#include "rdmesh/tet_mesh.h"

namespace rdmesh {

struct EntitySize {
  enum class Kind { kPatch, kCurve, kSubdomain };
  Kind kind = Kind::kPatch;
  int id = 0;         ///< patch, curve or subdomain id
  double size = 0;    ///< asked size (an absolute length, as Criteria's)
  std::string label;  ///< how the user named it, e.g. "face:12", for messages and reports
};

/// The entity `key` names ("KIND:WHICH", as in a sizing file) with `size`.
/// Throws InputError "KEY: problem" for a bad kind, an unknown entity or a
/// size that is not a positive number.
EntitySize entity_size(const std::string& key, double size, const DomainOracle& oracle);

/// Parses "KIND:WHICH=SIZE": KIND is face (or patch), curve (or edge), solid
/// (or subdomain); WHICH an id or a name (the oracle's, as the .msh physical
/// groups show them; double quotes optional). Throws InputError naming `text`
/// for bad syntax, an unknown entity or a size that is not a positive number.
EntitySize parse_entity_size(const std::string& text, const DomainOracle& oracle);

/// Everything asked of the sizes beyond the criteria's own fields.
struct SizeRequests {
  std::vector<EntitySize> entities;
  double grade = 1.4;    ///< sizes grow by grade - 1 per unit of distance from where asked
  double curvature = 0;  ///< elements per full turn (rdmesh/curvature_sizes.h); 0: none
};

/// The requests a sizing object makes of `oracle` (entity_size for each key;
/// grade and curvature when given, the defaults above otherwise). Throws InputError.
SizeRequests resolve_size_spec(const SizeSpec& spec, const DomainOracle& oracle);

/// Appends `from`'s entities to `into`'s; `from`'s grade and curvature win when set.
void merge_size_spec(SizeSpec& into, const SizeSpec& from);

struct SizesApplied {
  CurvatureStats curvature;  ///< all zero without curvature sizes
  double seconds = 0;        ///< sampling the entities and curvatures (not meshing)
};

/// Lowers criteria.edge_size, facet_size and cell_size to the graded entity
/// and curvature sizes (see the file comment; a first surface-only mesh at
/// the criteria's sizes samples the patches when a patch, a subdomain or the
/// curvature is asked). Call it after the criteria are final (the minimum
/// size among them). Throws InputError when an entity's size is below
/// criteria.min_size_for(box), the grade is not above 1 or the curvature not
/// positive.
SizesApplied apply_sizes(const DomainOracle& oracle, const SizeRequests& requests,
                         Criteria& criteria);

/// apply_sizes with entity sizes only.
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
