// The CAD oracle: a STEP, BREP or IGES model answered exactly by OpenCASCADE.
//
// Reading. `.step/.stp` and `.iges/.igs` go through OpenCASCADE's translators,
// which convert every length to millimetres (the file's own unit is honoured);
// `.brep` has no unit and is read as is. Solids become subdomains 1..n in file
// order (assembly instances expanded), named after their STEP representation item
// when no other solid has that name, else the STEP product of their part ("nut"),
// else their assembly instance, else "solid_<id>"; a name several solids share
// gets _1, _2... in file order. Faces
// (patches) are named after the STEP face's name when it has one (and not every
// face has that same name), else
// "face_<id>", and keep the file's colour (patch_color). A file without solids has its faces
// sewn; every closed shell becomes a solid, open shells are an InputError.
//
// Conformity. With several solids the model is made a conformal complex first
// (OpenCASCADE's general fuse, BOPAlgo_Builder): touching solids then share
// their common faces, which become interface patches between two subdomains.
// Where solids overlap, the overlap belongs to the first solid in file order.
//
// Features. Faces are patches 1..m (ordered by solid, then by the solid's
// face order); a face with the same subdomain on both sides is not a patch.
// Edges of the patches are curves, except seam edges of periodic faces and
// degenerated edges (sphere poles); a curve is closed when its two vertices are
// the same vertex. Corners are the vertices ending open curves, ids in order of
// first appearance. Each curve is the edge's own 3D curve, shifted by a linear
// blend (at most the vertex tolerance) so that it ends exactly at its corners.
//
// Queries. Every face has a tessellation used only to find where to look: an
// adaptive (u, v) grid of flat triangles, each with a measured bound on its
// distance to the surface and a cone of the surface normals over it, in one
// box tree; the (u, v) cells also record whether they are inside the face,
// outside it or on its boundary. intersect() visits the triangles whose
// inflated boxes the segment meets, nearest first, and stops when nothing
// nearer can exist; from each it computes the crossing exactly: in closed form
// on planes, cylinders, cones and spheres, by Newton on the true surface
// otherwise (subdividing triangles the segment grazes, with OpenCASCADE's own
// intersectors as the fallback where Newton cannot decide), and classifies it
// in (u, v). locate() casts a ray from p with the same machinery and reads the
// label from the first face it crosses and the face's orientation (normal out
// of one side), retrying along another ray when the first crossing grazes or
// lies on a face boundary; so locate() and intersect() agree by construction.
// project() runs Newton from the nearest point of the face's tessellation, and
// on the face's edge curves when the foot falls outside the face
// (GeomAPI_ProjectPointOnSurf, then BRepExtrema, when that fails).
// initial_points() evaluates the true surface at a few centroids of the face's
// own (u, v) tessellation that its cells place inside it. Queries are const and
// thread-safe: OpenCASCADE's stateful adaptors, classifiers and intersectors
// are kept in per-thread caches.
//
// Errors. Every OpenCASCADE exception is caught here and rethrown as
// InputError (while loading) or OracleError (in queries).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "rdmesh/input_file.h"  // is_cad_file: the extensions load_cad_file reads
#include "rdmesh/oracle.h"

namespace rdmesh {

/// How a CAD file is loaded.
struct CadOptions {
  /// Run OpenCASCADE shape healing (ShapeFix_Shape) before meshing; what it
  /// changed is reported in CadOracle::log().
  bool heal = false;
  /// Check the B-rep with BRepCheck_Analyzer and reject an invalid one.
  bool check_validity = true;
  /// Read the file in a forked child process (POSIX; elsewhere in this one):
  /// a crash, an endless loop or a runaway allocation of OpenCASCADE's reader
  /// on a malformed file becomes an InputError instead of taking the host
  /// down. The shape comes back in OpenCASCADE's binary format, bit for bit.
  /// false: read in this process (no fork; no protection). With glibc's
  /// malloc the host may have other threads running; under a sanitizer's
  /// allocator, which is not fork-safe, a host thread allocating at the moment
  /// of fork() leaves the child waiting on its lock (until the wall-clock limit
  /// below): keep other threads quiet while reading, or set false.
  bool isolate = true;
  /// Isolated reading: CPU seconds the child may use to read, sew, heal and
  /// check the model (a child waiting without computing gets ten times as long
  /// plus a minute of wall-clock time); 0: 10 s plus 20 s per MB of the file.
  /// Preparing the read model (its surfaces' tessellation), isolated or not,
  /// may use three times as many CPU seconds: past that, an InputError
  /// "preparing the model did not finish within N s of computing". CPU time,
  /// not wall-clock time: whether a file is accepted does not depend on how
  /// loaded the machine is.
  double read_time_limit = 0;
  /// Isolated reading: how much address space the child may add to what it
  /// inherits, MiB; 0 is half the physical memory. Not applied under
  /// AddressSanitizer, which reserves far more address space than it uses.
  std::size_t read_memory_limit_mib = 0;
};

/// A B-rep model as a DomainOracle (see the file comment).
class CadOracle final : public DomainOracle {
 public:
  struct Model;  ///< OpenCASCADE data, defined in cad/src only

  /// Takes ownership of a built model (use load_cad_file or make_cad_test_oracle).
  explicit CadOracle(std::unique_ptr<Model> model);
  ~CadOracle() override;
  CadOracle(const CadOracle&) = delete;
  CadOracle& operator=(const CadOracle&) = delete;

  Box3 bounding_box() const override;
  /// Without a hint, rays from p (the first transversal one decides). With
  /// one, the face crossed last on the way from the hint's point to p decides,
  /// and is returned as the crossing; no crossing keeps the hint's label; a
  /// grazing crossing falls back to the rays.
  Located locate(const Point3& p,
                 const std::optional<LocateHint>& hint = std::nullopt) const override;
  /// The transversal crossing nearest to a; when none is found but the end
  /// labels differ, the label change is bracketed by bisection on locate().
  std::optional<SurfaceHit> intersect(const Point3& a, const Point3& b) const override;
  std::vector<SubdomainInfo> subdomains() const override;
  std::vector<PatchInfo> patches() const override;
  std::vector<Point3> initial_points(PatchId patch) const override;
  std::optional<Point3> project(const Point3& p, PatchId patch) const override;
  /// project() onto each other face whose tessellation boxes come within `limit`.
  double distance_to_other_patches(const Point3& p, const std::vector<PatchId>& patches,
                                   double limit) const override;
  /// OpenCASCADE's principal curvatures (GeomLProp_SLProps) at the foot of p
  /// on the face's surface (Newton from the face's tessellation); in closed
  /// form on planes (0), cylinders and spheres (1 / radius), without a
  /// projection. nullopt where the curvature is undefined (a pole) or the
  /// projection fails.
  std::optional<double> curvature(const Point3& p, PatchId patch) const override;
  /// max(1e-9 x box diagonal, largest face/edge tolerance), at most 1e-5 x diagonal.
  double tolerance() const override;
  std::vector<CornerInfo> corners() const override;
  std::vector<CurveInfo> curves() const override;
  const Curve& curve(CurveId id) const override;

  /// OpenCASCADE's exact volume (BRepGProp) of subdomain `id`; all subdomains when id is 0.
  double exact_volume(SubdomainId id = kOutside) const;
  /// OpenCASCADE's exact area (BRepGProp) of patch `id`'s face; of all patches when id is 0.
  double exact_area(PatchId id = PatchId(0)) const;
  /// The colour the file gives patch `id`'s face (its own, else its part's), as
  /// "#rrggbb"; empty when it gives none (STEP only).
  std::string patch_color(PatchId id) const;
  /// Number of solids read from the file (before the general fuse).
  int input_solids() const;
  /// What loading did (units, fuse, healing), one line per entry.
  const std::vector<std::string>& log() const;
  /// What the user should know about the model: solids that lie inside
  /// earlier ones and so get no tetrahedra. One line per entry.
  const std::vector<std::string>& warnings() const;

  /// The crossing of segment [a, b] with a face that is nearest to a, as the
  /// intersector finds it (intersect() adds a bisection when it is tangent or
  /// missing). `cosine` is between b - a and the face's normal, which points
  /// out of the first solid (in file order) bounded by the face; `tangent` when
  /// the crossing grazes the face or lies on the face's boundary.
  struct Crossing {
    Point3 point;
    PatchId patch;
    double distance = 0;  ///< from a
    double cosine = 0;
    bool tangent = false;
  };
  std::optional<Crossing> first_crossing(const Point3& a, const Point3& b) const;

  /// For a face that bends towards the material behind it with a radius at
  /// most the material's thickness (a rod, a pin; not a hole, not a thin
  /// shell), that thickness: from each of the face's initial points, the
  /// distance along the surface normal to the next face on a side that is
  /// inside a solid (a rod's diameter); the largest over the points. nullopt for planar faces and
  /// where no such crossing is found (cad_thickness.cpp). Throws InputError when the rays of one
  /// face take over 10 s (microseconds on a valid face; a corrupt surface far from its edges sends
  /// them down OpenCASCADE's slow paths).
  std::optional<double> curved_thickness(PatchId id) const;
  /// The box of patch `id`'s face (OpenCASCADE's, with the model's tolerance).
  Box3 patch_box(PatchId id) const;

  /// The model's OpenCASCADE data (complete in cad/src only).
  const Model& model() const { return *model_; }

 private:
  std::unique_ptr<Model> model_;
  std::uint64_t serial_;  // identifies this oracle in the per-thread caches
};

/// Reads a CAD file and builds its oracle. Throws InputError naming the file for
/// a missing, unreadable, corrupt or truncated file, a file without solids or
/// faces, an open shell, an invalid B-rep (BRepCheck) or a failed fuse/healing.
std::unique_ptr<CadOracle> load_cad_file(const std::string& path, const CadOptions& options = {});

/// Small models built with OpenCASCADE itself, for tests and samples (millimetres).
enum class CadTestShape {
  box,                 ///< [0,10] x [0,20] x [0,30]
  cylinder,            ///< radius 5, height 12, axis z
  box_minus_cylinder,  ///< 20 x 20 x 10 box minus a radius-4 hole through its middle
  two_boxes,           ///< [0,10]^3 and [10,20] x [0,10]^2: one shared face
  sphere,              ///< radius 10 at the origin
};

/// The oracle of a test shape (the same pipeline as a file: fuse, features, seeds).
std::unique_ptr<CadOracle> make_cad_test_oracle(CadTestShape shape);

/// Writes a test shape to `path` as STEP, BREP or IGES (by extension); throws OutputError.
void write_cad_test_shape(CadTestShape shape, const std::string& path);

}  // namespace rdmesh
