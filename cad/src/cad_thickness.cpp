// The thickness of the model behind its curved faces, for sizes that resolve
// slender parts (see CadOracle::curved_thickness).
//
// A rod 25 mm thick meshed at the default size of a 10 m part (500 mm) has no
// cell inside it whose circumcentre lies inside it: the restricted Delaunay
// mesh loses the rod (72% of bm2_ec_leverrod's volume). Rules R3-R5 cannot see
// that: the rod's few facets satisfy them. What the size must follow is the
// thickness of the material behind a face that bends towards it about as
// strongly as the material is thick (a rod, a pin, a bolt's shank), measured
// here along the surface normal at the face's seeds: the distance to the first
// face crossed, on each side that is inside a solid. Holes (the face bends
// away from the material), thin shells (they bend far less than they are
// thin) and planar faces are left out: the cells between two close, nearly
// parallel sheets of facets have their circumcentres between them, so rules
// R3-R5 resolve them.
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <Standard_Failure.hxx>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "cad_model.h"
#include "cpu_time.h"
#include "rdmesh/errors.h"

namespace rdmesh {
namespace {

// How long measuring one face's thickness may take before the face is called malformed.
constexpr int kThicknessSeconds = 10;

/// The surface of face f at the point nearest to p: its unit normal and the
/// normal curvatures along the u and v directions, signed positive where the
/// surface bends towards the normal; nullopt where undefined (a pole, a
/// failed projection).
struct LocalShape {
  Point3 normal;
  double curvature_u = 0, curvature_v = 0;
};

std::optional<LocalShape> local_shape(const cad::FacePatch& f, const Point3& p) {
  GeomAPI_ProjectPointOnSurf projection(gp_Pnt(p.x, p.y, p.z), f.surface);
  if (!projection.IsDone() || projection.NbPoints() == 0) return std::nullopt;
  double u = 0, v = 0;
  projection.LowerDistanceParameters(u, v);
  gp_Pnt q;
  gp_Vec du, dv, duu, dvv, duv;
  f.surface->D2(u, v, q, du, dv, duu, dvv, duv);
  const gp_Vec n = du.Crossed(dv);
  if (n.Magnitude() < 1e-300 || du.SquareMagnitude() < 1e-300 || dv.SquareMagnitude() < 1e-300)
    return std::nullopt;
  const gp_Vec m = n.Normalized();
  return LocalShape{
      {m.X(), m.Y(), m.Z()}, duu.Dot(m) / du.SquareMagnitude(), dvv.Dot(m) / dv.SquareMagnitude()};
}

}  // namespace

std::optional<double> CadOracle::curved_thickness(PatchId id) const {
  const Model& m = *model_;
  if (id.value < 1 || id.value > static_cast<int>(m.faces.size())) return std::nullopt;
  const cad::FacePatch& f = m.faces[static_cast<std::size_t>(id.value) - 1];
  if (f.kind == cad::SurfaceKind::plane) return std::nullopt;
  const double reach = m.box.diagonal();
  const double step = 10 * m.tolerance;
  // The largest over the seeds: a seed near the face's boundary may see the
  // neighbouring face right away (a fillet's edge), which says nothing of the
  // material behind the face.
  double thickness = 0;
  // A few rays take microseconds on a valid face; on a surface a corrupt
  // control point sent far from its edges (a fuzzed STEP file) each took
  // OpenCASCADE's slow intersection path, for minutes in all.
  // CPU time of this thread, so that a loaded machine does not refuse a valid face.
  const double start = cad::thread_cpu_seconds();
  try {
    for (const Point3& s : m.features.initial_points(id)) {
      if (cad::thread_cpu_seconds() - start > kThicknessSeconds) {
        throw InputError(
            "face " + std::to_string(id.value) + ": measuring the material behind it took over " +
            std::to_string(kThicknessSeconds) + " s of computing (a malformed surface?)");
      }
      const std::optional<LocalShape> shape = local_shape(f, s);
      if (!shape) continue;
      for (const double side : {1.0, -1.0}) {
        const Point3 d = side * shape->normal;
        const std::optional<Crossing> c = first_crossing(s + step * d, s + reach * d);
        if (!c || c->tangent) continue;
        // The side the ray starts in: it leaves the solid the normal points out of.
        const cad::FacePatch& hit = m.faces[static_cast<std::size_t>(c->patch.value) - 1];
        const SubdomainId inside = c->cosine > 0 ? hit.outward_of : hit.inward_of;
        if (inside == kOutside) continue;
        // Slender: the face bends towards the material, with a radius of
        // curvature at most the material's thickness (a rod: the diameter is
        // twice the radius). A hole bends away from it; a shell bends less
        // than it is thin (a sheet's bend of radius 2 mm in 1 mm of metal).
        const double t = c->distance + step;
        const double bend = std::max(side * shape->curvature_u, side * shape->curvature_v);
        if (bend * t >= 1) thickness = std::max(thickness, t);
      }
    }
  } catch (const Standard_Failure&) {
    return std::nullopt;  // a size hint only: no thickness where OpenCASCADE fails
  }
  if (!(thickness > 0)) return std::nullopt;
  return thickness;
}

Box3 CadOracle::patch_box(PatchId id) const {
  const Model& m = *model_;
  if (id.value < 1 || id.value > static_cast<int>(m.faces.size())) return {};
  return m.faces[static_cast<std::size_t>(id.value) - 1].box;
}

}  // namespace rdmesh
