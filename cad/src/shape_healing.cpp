#include "shape_healing.h"

#include <BRep_Tool.hxx>
#include <Message_ListOfMsg.hxx>
#include <Message_Msg.hxx>
#include <ShapeBuild_ReShape.hxx>
#include <ShapeExtend_DataMapOfShapeListOfMsg.hxx>
#include <ShapeExtend_MsgRegistrator.hxx>
#include <ShapeFix_Shape.hxx>
#include <TCollection_AsciiString.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <algorithm>
#include <cstdio>
#include <map>
#include <vector>

namespace rdmesh::cad {
namespace {

constexpr std::pair<TopAbs_ShapeEnum, const char*> kKinds[] = {
    {TopAbs_SOLID, "solids"}, {TopAbs_SHELL, "shells"}, {TopAbs_FACE, "faces"},
    {TopAbs_WIRE, "wires"},   {TopAbs_EDGE, "edges"},   {TopAbs_VERTEX, "vertices"}};

std::string counts(const TopoDS_Shape& s) {
  std::string out;
  for (const auto& [kind, name] : kKinds) {
    TopTools_IndexedMapOfShape map;
    TopExp::MapShapes(s, kind, map);
    out += (out.empty() ? "" : ", ") + std::to_string(map.Extent()) + " " + name;
  }
  return out;
}

double max_tolerance(const TopoDS_Shape& s) {
  double t = 0;
  TopTools_IndexedMapOfShape map;
  TopExp::MapShapes(s, TopAbs_VERTEX, map);
  for (int i = 1; i <= map.Extent(); ++i)
    t = std::max(t, BRep_Tool::Tolerance(TopoDS::Vertex(map(i))));
  map.Clear();
  TopExp::MapShapes(s, TopAbs_EDGE, map);
  for (int i = 1; i <= map.Extent(); ++i)
    t = std::max(t, BRep_Tool::Tolerance(TopoDS::Edge(map(i))));
  return t;
}

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

/// "3 faces, 12 edges replaced; 1 edge removed" from the healing's history.
std::string replaced(const TopoDS_Shape& before, const Handle(ShapeBuild_ReShape) & context) {
  std::string changed, removed;
  for (const auto& [kind, name] : kKinds) {
    TopTools_IndexedMapOfShape map;
    TopExp::MapShapes(before, kind, map);
    int n_changed = 0, n_removed = 0;
    for (int i = 1; i <= map.Extent(); ++i) {
      const TopoDS_Shape now = context->Value(map(i));
      if (now.IsNull()) {
        ++n_removed;
      } else if (!now.IsSame(map(i))) {
        ++n_changed;
      }
    }
    if (n_changed)
      changed += (changed.empty() ? "" : ", ") + std::to_string(n_changed) + " " + name;
    if (n_removed)
      removed += (removed.empty() ? "" : ", ") + std::to_string(n_removed) + " " + name;
  }
  std::string out = changed.empty() ? "no entity replaced" : changed + " replaced";
  if (!removed.empty()) out += "; " + removed + " removed";
  return out;
}

double tolerance_of(const TopoDS_Shape& s) {
  switch (s.ShapeType()) {
    case TopAbs_VERTEX:
      return BRep_Tool::Tolerance(TopoDS::Vertex(s));
    case TopAbs_EDGE:
      return BRep_Tool::Tolerance(TopoDS::Edge(s));
    case TopAbs_FACE:
      return BRep_Tool::Tolerance(TopoDS::Face(s));
    default:
      return 0;
  }
}

/// The tolerances of the faces, edges and vertices before healing (healing may
/// change them in place, in the same TShape).
std::vector<std::pair<TopoDS_Shape, double>> tolerances(const TopoDS_Shape& shape) {
  std::vector<std::pair<TopoDS_Shape, double>> out;
  for (TopAbs_ShapeEnum kind : {TopAbs_FACE, TopAbs_EDGE, TopAbs_VERTEX}) {
    TopTools_IndexedMapOfShape map;
    TopExp::MapShapes(shape, kind, map);
    for (int i = 1; i <= map.Extent(); ++i) out.emplace_back(map(i), tolerance_of(map(i)));
  }
  return out;
}

/// "3 edges, 2 vertices had their tolerance changed", or empty.
std::string tolerance_changes(const std::vector<std::pair<TopoDS_Shape, double>>& before,
                              const Handle(ShapeBuild_ReShape) & context) {
  std::map<TopAbs_ShapeEnum, int> changed;
  for (const auto& [shape, tolerance] : before) {
    const TopoDS_Shape now = context->Value(shape);
    if (!now.IsNull() && tolerance_of(now) != tolerance) ++changed[shape.ShapeType()];
  }
  std::string out;
  for (const auto& [kind, name] : kKinds) {
    if (changed.count(kind)) {
      out += (out.empty() ? "" : ", ") + std::to_string(changed[kind]) + " " + name;
    }
  }
  return out.empty() ? out : out + " had their tolerance changed";
}

/// The fixes ShapeFix recorded, by kind ("FixAdvWire.FixSmall.MSG0" x 3).
std::string fixes(const Handle(ShapeExtend_MsgRegistrator) & messages) {
  std::map<std::string, int> kinds;
  for (ShapeExtend_DataMapOfShapeListOfMsg::Iterator it(messages->MapShape()); it.More();
       it.Next()) {
    for (Message_ListOfMsg::Iterator m(it.Value()); m.More(); m.Next()) {
      const TCollection_AsciiString text(m.Value().Original(), '?');
      ++kinds[text.ToCString()];
    }
  }
  std::string out;
  for (const auto& [kind, n] : kinds) {
    out += (out.empty() ? "" : ", ") + kind + (n > 1 ? " x " + std::to_string(n) : "");
  }
  return out;
}

}  // namespace

void heal_shape(ReadShape& r, const std::string& path) {
  const TopoDS_Shape before = r.shape;
  const std::string counts_before = counts(before);
  const double tolerance_before = max_tolerance(before);
  const std::vector<std::pair<TopoDS_Shape, double>> tolerances_before = tolerances(before);
  ShapeFix_Shape fix(before);
  Handle(ShapeExtend_MsgRegistrator) messages = new ShapeExtend_MsgRegistrator;
  fix.SetMsgRegistrator(messages);
  fix.Perform();
  if (fix.Status(ShapeExtend_FAIL)) throw InputError(path, "shape healing (ShapeFix_Shape) failed");
  if (!fix.Status(ShapeExtend_DONE)) {
    r.log.push_back("healing: nothing to fix (" + counts_before + ")");
    return;
  }
  r.shape = fix.Shape();
  const Handle(ShapeBuild_ReShape) context = fix.Context();
  // Names and colours follow what healing replaced.
  for (auto& [solid, name] : r.solid_names) {
    const TopoDS_Shape now = context->Value(solid);
    if (!now.IsNull()) solid = now;
  }
  for (auto& [face, style] : r.face_styles) {
    const TopoDS_Shape now = context->Value(face);
    if (!now.IsNull()) face = now;
  }
  const std::string entities = replaced(before, context);
  const std::string retoleranced = tolerance_changes(tolerances_before, context);
  const std::string fixed = fixes(messages);
  r.log.push_back("healing: " + entities + (retoleranced.empty() ? "" : "; " + retoleranced));
  if (!fixed.empty()) r.log.push_back("healing: fixes made: " + fixed);
  if (entities == "no entity replaced" && retoleranced.empty() && fixed.empty()) {
    r.log.push_back(
        "healing: ShapeFix_Shape reported work but changed no entity and no tolerance (in-place "
        "repairs only: parameter curves, orientations)");
  }
  r.log.push_back("healing: largest vertex/edge tolerance " + number(tolerance_before) + " -> " +
                  number(max_tolerance(r.shape)));
  const std::string counts_after = counts(r.shape);
  r.log.push_back(counts_after == counts_before
                      ? "healing: counts unchanged (" + counts_before + ")"
                      : "healing: before " + counts_before + "; after " + counts_after);
}

}  // namespace rdmesh::cad
