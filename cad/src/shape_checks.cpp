// Checks of a file's structure, numbers and geometry that OpenCASCADE's readers
// and its validity check let through, and that make them loop (nearly) forever
// or leave the mesher without a volume: BREP sections announcing more entries
// than the file holds, non-finite coordinates, degenerate analytic surfaces.
#include <BRepBndLib.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <Interface_InterfaceModel.hxx>
#include <StepData_StepModel.hxx>
#include <StepGeom_CartesianPoint.hxx>
#include <StepGeom_Direction.hxx>
#include <StepGeom_Vector.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <cctype>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>
#include <vector>

#include "cad_model.h"

namespace rdmesh::cad {
namespace {

std::string number(double v) {
  std::ostringstream o;
  o.precision(17);
  o << v;
  return o.str();
}

// The first non-finite value of `count` values at(1..count), as its index (0: none).
template <typename At>
int first_non_finite(int count, At at) {
  for (int i = 1; i <= count; ++i) {
    if (!std::isfinite(at(i))) return i;
  }
  return 0;
}

// Why a face's surface is degenerate ("" when it is not): an analytic surface
// with a radius that is not positive and finite.
std::string degenerate_surface(const TopoDS_Face& face) {
  const GeomAdaptor_Surface s(BRep_Tool::Surface(face));
  const auto bad = [](double r) { return !(r > 0) || !std::isfinite(r); };
  switch (s.GetType()) {
    case GeomAbs_Cylinder:
      if (bad(s.Cylinder().Radius()))
        return "a cylinder of radius " + number(s.Cylinder().Radius());
      break;
    case GeomAbs_Sphere:
      if (bad(s.Sphere().Radius())) return "a sphere of radius " + number(s.Sphere().Radius());
      break;
    case GeomAbs_Torus:
      if (bad(s.Torus().MajorRadius()) || bad(s.Torus().MinorRadius())) {
        return "a torus of major radius " + number(s.Torus().MajorRadius()) + " and minor radius " +
               number(s.Torus().MinorRadius());
      }
      break;
    default:
      break;
  }
  return {};
}

}  // namespace

void check_brep_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) {
    while (!line.empty() && std::isspace(static_cast<unsigned char>(line.back()))) line.pop_back();
    lines.push_back(std::move(line));
  }
  static const std::set<std::string> sections = {
      "Locations", "Curve2ds",       "Curves", "Polygon3D", "PolygonOnTriangulations",
      "Surfaces",  "Triangulations", "TShapes"};
  bool shapes_seen = false;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    std::istringstream words(lines[i]);
    std::string name;
    long long count = -1;
    if (!(words >> name >> count) || !sections.count(name) || !words.eof()) continue;
    // Every entry takes a line at least; a TShape ends with a line ending in '*'.
    long long entries = static_cast<long long>(lines.size() - i - 1);
    if (name == "TShapes") {
      shapes_seen = true;
      entries = 0;
      for (std::size_t k = i + 1; k < lines.size(); ++k) {
        const std::string& l = lines[k];
        if (!l.empty() && l.back() == '*' && (l.size() == 1 || l[l.size() - 2] == ' ')) ++entries;
      }
    }
    if (count < 0 || count > entries) {
      throw InputError(path, "line " + std::to_string(i + 1) + " announces " +
                                 std::to_string(count) + " " + name + ", the file holds at most " +
                                 std::to_string(entries) + " (truncated or corrupt BREP file)");
    }
  }
  if (!shapes_seen) {
    throw InputError(path, "no TShapes section (not a BREP file, or a truncated one)");
  }
}

void check_step_numbers(const Handle(StepData_StepModel) & model, const std::string& path) {
  for (int i = 1; i <= model->NbEntities(); ++i) {
    const Handle(Standard_Transient) entity = model->Value(i);
    std::string what;
    if (const auto p = Handle(StepGeom_CartesianPoint)::DownCast(entity); !p.IsNull()) {
      if (first_non_finite(p->NbCoordinates(), [&](int k) { return p->CoordinatesValue(k); })) {
        what = "CARTESIAN_POINT";
      }
    } else if (const auto d = Handle(StepGeom_Direction)::DownCast(entity); !d.IsNull()) {
      if (first_non_finite(d->NbDirectionRatios(),
                           [&](int k) { return d->DirectionRatiosValue(k); })) {
        what = "DIRECTION";
      }
    } else if (const auto v = Handle(StepGeom_Vector)::DownCast(entity); !v.IsNull()) {
      if (!std::isfinite(v->Magnitude())) what = "VECTOR";
    }
    if (!what.empty()) {
      throw InputError(path, "entity #" + std::to_string(model->IdentLabel(entity)) + " (" + what +
                                 ") has a non-finite number (INF or NaN)");
    }
  }
}

void check_shape_geometry(const TopoDS_Shape& shape, const std::string& path) {
  TopTools_IndexedMapOfShape vertices, faces;
  TopExp::MapShapes(shape, TopAbs_VERTEX, vertices);
  for (int i = 1; i <= vertices.Extent(); ++i) {
    const gp_Pnt p = BRep_Tool::Pnt(TopoDS::Vertex(vertices(i)));
    if (!std::isfinite(p.X()) || !std::isfinite(p.Y()) || !std::isfinite(p.Z())) {
      throw InputError(path, "vertex " + std::to_string(i) + " has a non-finite coordinate");
    }
  }
  TopExp::MapShapes(shape, TopAbs_FACE, faces);
  for (int i = 1; i <= faces.Extent(); ++i) {
    const std::string why = degenerate_surface(TopoDS::Face(faces(i)));
    if (!why.empty()) {
      throw InputError(path,
                       "face " + std::to_string(i) + " lies on a degenerate surface (" + why + ")");
    }
  }
  Bnd_Box box;
  BRepBndLib::Add(shape, box, false);
  if (!box.IsVoid() && !std::isfinite(box.SquareExtent())) {
    throw InputError(path, "the model's bounding box is not finite");
  }
  // (A test of each solid's volume, BRepGProp, would cost up to a tenth of a
  // second on the shared parts, as much again as the whole isolation: the
  // degenerate surfaces above are what gave the known zero-volume solids.)
}

}  // namespace rdmesh::cad
