// From a read shape to the oracle's data: general fuse of touching solids,
// subdomains, patches (faces with their two sides), curves (non-seam,
// non-degenerated edges) and corners (vertices ending open curves).
#include <BOPAlgo_Builder.hxx>
#include <BRepBndLib.hxx>
#include <BRepGProp.hxx>
#include <BRepLib.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <GProp_GProps.hxx>
#include <GeomAdaptor_Curve.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <Geom_BSplineCurve.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_DataMapOfShapeInteger.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Vertex.hxx>
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <set>

#include "cad_model.h"
#include "rdmesh/feature_name.h"
#include "rdmesh/number_text.h"

namespace rdmesh::cad {
namespace {

Point3 to_point(const gp_Pnt& p) { return {p.X(), p.Y(), p.Z()}; }

Box3 box_of(const TopoDS_Shape& s, double margin) {
  Bnd_Box b;
  BRepBndLib::Add(s, b, false);
  if (b.IsVoid()) return {};
  double x0, y0, z0, x1, y1, z1;
  b.Get(x0, y0, z0, x1, y1, z1);
  return {{x0 - margin, y0 - margin, z0 - margin}, {x1 + margin, y1 + margin, z1 + margin}};
}

/// Shapes closer than this fraction of the solids' bounding-box diagonal are
/// fused as touching: 1/100 of the default minimum size (1e-4 of the diagonal),
/// so nothing the mesh could show is merged.
constexpr double kFuzzyPerDiagonal = 1e-6;

// Solids in file order with their subdomain ids, after the general fuse.
void fuse_solids(const ReadShape& read, CadOracle::Model& m, const std::string& source) {
  std::vector<TopoDS_Solid> input;
  for (TopExp_Explorer ex(read.shape, TopAbs_SOLID); ex.More(); ex.Next()) {
    input.push_back(TopoDS::Solid(ex.Current()));
  }
  m.input_solids = static_cast<int>(input.size());
  if (input.empty()) throw InputError(source, "the model holds no solid");
  // A solid stored inside out (its faces' normals pointing in: a negative
  // volume) would make locate() call all the space around it inside; one
  // without volume (an open or flat shell) made the general fuse hand the
  // space around the other solids to it (occt_Axis_of_bearing.brep).
  std::vector<double> volume(input.size());
  double largest = 0;
  for (std::size_t i = 0; i < input.size(); ++i) {
    GProp_GProps props;
    BRepGProp::VolumeProperties(input[i], props);
    volume[i] = props.Mass();
    largest = std::max(largest, std::fabs(volume[i]));
    if (volume[i] < 0) {
      input[i] = TopoDS::Solid(input[i].Reversed());
      m.log.push_back("solid " + std::to_string(i + 1) +
                      " was inside out (negative volume): reversed");
    }
  }
  std::vector<char> empty(input.size(), 0);
  for (std::size_t i = 0; i < input.size(); ++i) {
    if (!(std::fabs(volume[i]) > 1e-12 * largest)) empty[i] = 1;
  }
  for (std::size_t i = 0; i < input.size(); ++i) {
    std::string name = "solid_" + std::to_string(i + 1);
    for (const auto& [shape, n] : read.solid_names) {
      if (shape.IsSame(input[i])) name = n;
    }
    m.subdomains.push_back({SubdomainId(static_cast<int>(i) + 1), name});
  }
  if (std::count(empty.begin(), empty.end(), 1) == static_cast<long>(input.size())) {
    throw InputError(source, "the model's solids have no volume (open or flat shells)");
  }
  if (input.size() == 1) {
    m.pieces.push_back({input[0], SubdomainId(1), {}, std::fabs(volume[0])});
    m.shape = input[0];
    m.face_styles = read.face_styles;
    return;
  }
  // Parts of an assembly placed a hair's breadth apart or into each other
  // (occtdata_as1_motor: cylinders and planes 0.01 apart in a 300,000-unit
  // model; occt_Axis_of_bearing: balls touching their races) make the exact
  // fuse cut faces a hair's breadth wide along whole circles. No mesh at the
  // model's scale can follow such a face: protection and refinement spent
  // minutes on it. Within kFuzzyPerDiagonal of the model's size shapes are
  // taken as touching (BOPAlgo's fuzzy value), as the designer meant; where
  // the fuzzy fuse fails, the exact one is used.
  Bnd_Box solids_box;
  for (std::size_t i = 0; i < input.size(); ++i) {
    if (!empty[i]) BRepBndLib::Add(input[i], solids_box);
  }
  const double fuzzy =
      solids_box.IsVoid() ? 0.0 : kFuzzyPerDiagonal * std::sqrt(solids_box.SquareExtent());
  auto fuse = [&](double fuzzy_value) {
    auto b = std::make_unique<BOPAlgo_Builder>();
    for (std::size_t i = 0; i < input.size(); ++i) {
      if (!empty[i]) b->AddArgument(input[i]);
    }
    b->SetRunParallel(false);
    b->SetNonDestructive(true);
    if (fuzzy_value > 0) b->SetFuzzyValue(fuzzy_value);
    b->Perform();
    return b;
  };
  std::unique_ptr<BOPAlgo_Builder> fused = fuse(fuzzy);
  if (fused->HasErrors() && fuzzy > 0) {
    m.log.push_back("the general fuse with a fuzzy value of " + std::to_string(fuzzy) +
                    " failed: fused exactly");
    fused = fuse(0);
  }
  BOPAlgo_Builder& builder = *fused;
  if (builder.HasErrors()) {
    throw InputError(source, "the general fuse of the " + std::to_string(input.size()) +
                                 " solids failed (BOPAlgo_Builder); try --heal");
  }
  // Names and colours follow the faces the fuse split or kept.
  for (const auto& [face, style] : read.face_styles) {
    const TopTools_ListOfShape& images = builder.Modified(face);
    if (images.IsEmpty() && !builder.IsDeleted(face)) m.face_styles.emplace_back(face, style);
    for (const TopoDS_Shape& image : images) m.face_styles.emplace_back(image, style);
  }
  TopTools_IndexedMapOfShape taken;
  for (std::size_t i = 0; i < input.size(); ++i) {
    if (empty[i]) continue;
    const TopTools_ListOfShape& images = builder.Modified(input[i]);
    std::vector<TopoDS_Shape> parts;
    if (images.IsEmpty()) {
      if (!builder.IsDeleted(input[i])) parts.push_back(input[i]);
    } else {
      for (const TopoDS_Shape& s : images) parts.push_back(s);
    }
    for (const TopoDS_Shape& s : parts) {
      if (s.ShapeType() != TopAbs_SOLID || taken.Contains(s)) continue;  // overlap: first wins
      taken.Add(s);
      GProp_GProps props;
      BRepGProp::VolumeProperties(s, props);
      m.pieces.push_back(
          {TopoDS::Solid(s), SubdomainId(static_cast<int>(i) + 1), {}, props.Mass()});
    }
  }
  std::set<int> kept;
  for (const SolidPiece& p : m.pieces) kept.insert(p.id.value);
  for (std::size_t i = 0; i < input.size(); ++i) {
    if (kept.count(static_cast<int>(i) + 1)) continue;
    m.warnings.push_back(
        "solid " + std::to_string(i + 1) + " (" + m.subdomains[i].name + ") " +
        (empty[i] ? "has no volume (an open or flat shell)"
                  : "lies inside earlier solids (where solids overlap, the first in file order "
                    "keeps the overlap)") +
        ": it gets no tetrahedra");
  }
  TopoDS_Compound all;
  BRep_Builder b;
  b.MakeCompound(all);
  for (const SolidPiece& p : m.pieces) b.Add(all, p.solid);
  m.shape = all;
  m.log.push_back("general fuse of " + std::to_string(input.size()) +
                  " solids: " + std::to_string(m.pieces.size()) + " conformal pieces");
}

// Planes, cylinders, cones and spheres are intersected in closed form.
void set_kind(FacePatch& f) {
  const GeomAdaptor_Surface adaptor(f.surface);
  switch (adaptor.GetType()) {
    case GeomAbs_Plane:
      f.kind = SurfaceKind::plane;
      f.plane = adaptor.Plane();
      break;
    case GeomAbs_Cylinder:
      f.kind = SurfaceKind::cylinder;
      f.cylinder = adaptor.Cylinder();
      break;
    case GeomAbs_Cone:
      f.kind = SurfaceKind::cone;
      f.cone = adaptor.Cone();
      break;
    case GeomAbs_Sphere:
      f.kind = SurfaceKind::sphere;
      f.sphere = adaptor.Sphere();
      break;
    default:
      f.kind = SurfaceKind::parametric;
      break;
  }
}

/// Patch names: the file's face name, else "face_<id>"; a name several faces
/// share gets "_<id>" appended. Colours as the file gives them.
void name_patches(CadOracle::Model& m) {
  TopTools_DataMapOfShapeInteger style_of;
  for (std::size_t k = 0; k < m.face_styles.size(); ++k) {
    style_of.Bind(m.face_styles[k].first, static_cast<int>(k));
  }
  std::map<std::string, int> uses;
  std::vector<std::string> names(m.faces.size());
  m.patch_colors.assign(m.faces.size(), std::string());
  for (std::size_t i = 0; i < m.faces.size(); ++i) {
    if (!style_of.IsBound(m.faces[i].face)) continue;
    const ShapeStyle& style =
        m.face_styles[static_cast<std::size_t>(style_of(m.faces[i].face))].second;
    names[i] = style.name;
    m.patch_colors[i] = style.color;
    if (!names[i].empty()) ++uses[names[i]];
  }
  // One name on every face (often the body's, "PartBody") names no face.
  const bool one_name = uses.size() == 1 && m.faces.size() > 1 &&
                        uses.begin()->second == static_cast<int>(m.faces.size());
  for (std::size_t i = 0; i < m.faces.size(); ++i) {
    const std::string id = std::to_string(i + 1);
    if (names[i].empty() || one_name) continue;
    m.patches[i].name = uses[names[i]] > 1 ? names[i] + "_" + id : names[i];
  }
}

void collect_faces(CadOracle::Model& m, TopTools_IndexedMapOfShape& patch_faces) {
  TopTools_IndexedDataMapOfShapeListOfShape face_solids;
  for (const SolidPiece& p : m.pieces) {
    TopExp::MapShapesAndAncestors(p.solid, TopAbs_FACE, TopAbs_SOLID, face_solids);
  }
  TopTools_IndexedMapOfShape ordered;
  for (const SolidPiece& p : m.pieces) TopExp::MapShapes(p.solid, TopAbs_FACE, ordered);
  for (int i = 1; i <= ordered.Extent(); ++i) {
    const TopoDS_Face face = TopoDS::Face(ordered(i));
    std::vector<int> labels;
    int first_owner = -1;  // the piece whose orientation the map kept
    for (const SolidPiece& p : m.pieces) {
      // Count each side: a face used twice by one solid (a crack), or once as
      // INTERNAL (a crack face inside the solid, gmsh_crack1.brep), separates nothing.
      for (TopExp_Explorer ex(p.solid, TopAbs_FACE); ex.More(); ex.Next()) {
        if (!ex.Current().IsSame(face)) continue;
        labels.push_back(p.id.value);
        const TopAbs_Orientation o = ex.Current().Orientation();
        if (o == TopAbs_INTERNAL || o == TopAbs_EXTERNAL) labels.push_back(p.id.value);
        if (first_owner < 0) first_owner = p.id.value;
      }
    }
    if (labels.size() == 1) labels.insert(labels.begin(), 0);
    std::sort(labels.begin(), labels.end());
    if (labels.size() != 2 || labels[0] == labels[1]) continue;
    FacePatch fp;
    fp.face = face;
    fp.surface = BRep_Tool::Surface(face);
    if (fp.surface.IsNull()) continue;
    BRepTools::UVBounds(face, fp.u0, fp.u1, fp.v0, fp.v1);
    if (!std::isfinite(fp.u0) || !std::isfinite(fp.u1) || !std::isfinite(fp.v0) ||
        !std::isfinite(fp.v1)) {
      // A mutated STEP file (fuzz/): the tessellation's cut counts were NaN.
      throw InputError("face " + std::to_string(m.faces.size() + 1) +
                       " has a non-finite parameter range");
    }
    fp.box = box_of(face, 0);
    if (GeomAdaptor_Surface(fp.surface).GetType() == GeomAbs_Plane) {
      // STEP files often give a planar face's edges no (u, v) curve: OpenCASCADE
      // then projects every edge onto the plane again in each classification
      // near the boundary. Stored once here instead.
      for (TopExp_Explorer ex(face, TopAbs_EDGE); ex.More(); ex.Next()) {
        BRepLib::BuildPCurveForEdgeOnPlane(TopoDS::Edge(ex.Current()), face);
      }
    }
    fp.classifier = std::make_unique<BRepTopAdaptor_FClass2d>(face, BRep_Tool::Tolerance(face));
    set_kind(fp);
    fp.outward_of = SubdomainId(first_owner);
    fp.inward_of = SubdomainId(labels[0] == first_owner ? labels[1] : labels[0]);
    const int id = static_cast<int>(m.faces.size()) + 1;
    m.patches.push_back({PatchId(id), "face_" + std::to_string(id), SubdomainId(labels[0]),
                         SubdomainId(labels[1])});
    m.faces.push_back(std::move(fp));
    patch_faces.Add(face);
  }
  if (m.faces.empty()) throw InputError("the model's solids have no boundary face");
}

int curve_samples(const Handle(Geom_Curve) & c, double t0, double t1) {
  GeomAdaptor_Curve a(c, t0, t1);
  switch (a.GetType()) {
    case GeomAbs_Line:
      return 4;
    case GeomAbs_Circle:
    case GeomAbs_Ellipse:
      return 8 + static_cast<int>(32 * (t1 - t0) / (2 * M_PI));
    case GeomAbs_BSplineCurve:
    case GeomAbs_BezierCurve:
      return std::clamp(4 * a.NbIntervals(GeomAbs_C2) * std::max(a.Degree(), 2), 16, 512);
    default:
      return 48;
  }
}

void collect_curves(CadOracle::Model& m, const TopTools_IndexedMapOfShape& patch_faces) {
  TopTools_IndexedDataMapOfShapeListOfShape edge_faces;
  TopExp::MapShapesAndAncestors(m.shape, TopAbs_EDGE, TopAbs_FACE, edge_faces);
  TopTools_IndexedMapOfShape vertices;  // corner ids
  std::map<int, std::set<int>> corner_curves, corner_patches;
  for (int i = 1; i <= edge_faces.Extent(); ++i) {
    const TopoDS_Edge edge = TopoDS::Edge(edge_faces.FindKey(i));
    if (BRep_Tool::Degenerated(edge)) continue;
    std::set<int> patches;
    bool seam = false;
    for (const TopoDS_Shape& f : edge_faces(i)) {
      const int id = patch_faces.FindIndex(f);
      if (id > 0) patches.insert(id);
      if (BRep_Tool::IsClosed(edge, TopoDS::Face(f))) seam = true;
    }
    if (patches.empty() || (seam && patches.size() == 1)) continue;
    double t0 = 0, t1 = 0;
    Handle(Geom_Curve) c = BRep_Tool::Curve(edge, t0, t1);  // with the edge's location
    if (c.IsNull() || !(t1 > t0)) continue;
    TopoDS_Vertex v0, v1;
    TopExp::Vertices(TopoDS::Edge(edge.Oriented(TopAbs_FORWARD)), v0, v1);
    if (v0.IsNull() || v1.IsNull()) continue;
    const bool closed = v0.IsSame(v1);
    const Point3 q0 = to_point(BRep_Tool::Pnt(v0)), q1 = to_point(BRep_Tool::Pnt(v1));
    const int id = m.features.next_curve_id().value;
    CurveInfo info;
    info.id = CurveId(id);
    info.name = "edge_" + std::to_string(id);
    info.closed = closed;
    info.t_begin = t0;
    info.t_end = t1;
    for (int p : patches) info.patches.push_back(PatchId(p));
    auto curve = std::make_unique<EdgeCurve>(c, t0, t1, q0, q1, curve_samples(c, t0, t1));
    const double length = curve->length(t0, t1);
    if (!std::isfinite(length)) {
      throw InputError(feature_name(info.id, info.name) +
                       " has no finite length (malformed file?)");
    }
    // An edge of no length that OpenCASCADE does not flag as degenerated (a
    // malformed file whose edge lost a vertex's point) is a point, like the
    // degenerated edges skipped above: no curve to protect or to mesh.
    if (!(length > 0)) continue;
    if (!closed) {
      const int a = vertices.Add(v0), b = vertices.Add(v1);
      info.start = CornerId(a);
      info.end = CornerId(b);
      for (int q : {a, b}) {
        corner_curves[q].insert(id);
        corner_patches[q].insert(patches.begin(), patches.end());
      }
    }
    m.features.add_curve(std::move(info), std::move(curve));
  }
  // Two distinct vertices at the very same point (an unsewn model, or a
  // malformed file whose vertex moved onto another) would be two corners on
  // one mesh vertex: the mesh cannot tell them apart, so the model is refused.
  std::map<std::array<double, 3>, int> corner_at;
  for (int q = 1; q <= vertices.Extent(); ++q) {
    const Point3 point = to_point(BRep_Tool::Pnt(TopoDS::Vertex(vertices(q))));
    const auto [it, fresh] = corner_at.emplace(std::array<double, 3>{point.x, point.y, point.z}, q);
    if (!fresh) {
      throw InputError("vertices " + std::to_string(it->second) + " and " + std::to_string(q) +
                       " of the model's edges are distinct but at the same point " +
                       point_text(point) + " (an unsewn or malformed model)");
    }
    CornerInfo& corner = m.features.add_corner(point);
    for (int c : corner_curves[q]) corner.curves.push_back(CurveId(c));
    for (int p : corner_patches[q]) corner.patches.push_back(PatchId(p));
  }
}

double max_tolerance(const TopoDS_Shape& s) {
  double t = 0;
  for (TopExp_Explorer ex(s, TopAbs_FACE); ex.More(); ex.Next()) {
    t = std::max(t, BRep_Tool::Tolerance(TopoDS::Face(ex.Current())));
  }
  for (TopExp_Explorer ex(s, TopAbs_EDGE); ex.More(); ex.Next()) {
    t = std::max(t, BRep_Tool::Tolerance(TopoDS::Edge(ex.Current())));
  }
  return t;
}

}  // namespace

std::unique_ptr<CadOracle::Model> build_model(ReadShape read, const std::string& source,
                                              const PrepDeadline& deadline) {
  auto m = std::make_unique<CadOracle::Model>();
  m->log = std::move(read.log);
  try {
    BRepLib::BuildCurves3d(read.shape);
    fuse_solids(read, *m, source);
    const Box3 tight = box_of(m->shape, 0);
    const double diag = tight.diagonal();
    if (!(diag > 0) || !std::isfinite(diag))
      throw InputError(source, "the model is empty or degenerate");
    m->tolerance = std::clamp(max_tolerance(m->shape), 1e-9 * diag, 1e-5 * diag);
    m->box = box_of(m->shape, 0.01 * diag);
    for (SolidPiece& p : m->pieces) p.box = box_of(p.solid, m->tolerance);
    TopTools_IndexedMapOfShape patch_faces;
    collect_faces(*m, patch_faces);
    name_patches(*m);
    for (FacePatch& f : m->faces) {
      f.box.lo = f.box.lo - Point3{m->tolerance, m->tolerance, m->tolerance};
      f.box.hi = f.box.hi + Point3{m->tolerance, m->tolerance, m->tolerance};
    }
    collect_curves(*m, patch_faces);
    build_accelerator(*m, deadline);
    compute_seeds(*m);  // from the accelerator's tessellation
  } catch (const InputError& e) {
    if (!e.file().empty() || source.empty()) throw;
    throw InputError(source, e.what());
  } catch (const Standard_Failure& e) {
    throw InputError(source, "OpenCASCADE failed while preparing the model: " + describe(e));
  }
  return m;
}

}  // namespace rdmesh::cad
