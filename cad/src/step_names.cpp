#include "step_names.h"

#include <IFSelect_ReturnStatus.hxx>
#include <Quantity_Color.hxx>
#include <STEPCAFControl_Reader.hxx>
#include <STEPControl_Reader.hxx>
#include <StepData_StepModel.hxx>
#include <StepRepr_RepresentationItem.hxx>
#include <TCollection_AsciiString.hxx>
#include <TCollection_HAsciiString.hxx>
#include <TDF_Label.hxx>
#include <TDF_LabelSequence.hxx>
#include <TDataStd_Name.hxx>
#include <TDocStd_Document.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_ColorTool.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>
#include <XSControl_TransferReader.hxx>
#include <XSControl_WorkSession.hxx>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <map>

namespace rdmesh::cad {
namespace {

/// A name worth keeping: not empty, not "NONE", not an entity reference "#123", not
/// the product name OpenCASCADE's own writer gives every part.
bool informative(const std::string& name) {
  if (name.empty() || name == "NONE" || name == "none") return false;
  if (name.rfind("Open CASCADE STEP translator", 0) == 0) return false;
  if (name[0] == '#' && name.size() > 1 &&
      std::all_of(name.begin() + 1, name.end(), [](unsigned char c) { return std::isdigit(c); })) {
    return false;
  }
  return true;
}

std::string label_name(const TDF_Label& label) {
  Handle(TDataStd_Name) attribute;
  if (label.IsNull() || !label.FindAttribute(TDataStd_Name::GetID(), attribute)) return {};
  const TCollection_AsciiString text(attribute->Get(), '?');
  std::string name = text.ToCString();
  while (!name.empty() && std::isspace(static_cast<unsigned char>(name.back()))) name.pop_back();
  const auto first = name.find_first_not_of(" \t");
  name = first == std::string::npos ? std::string() : name.substr(first);
  return informative(name) ? name : std::string();
}

/// "#rrggbb" of the colour as the file gives it: OpenCASCADE keeps linear RGB, the
/// file's (and every viewer's) components are sRGB.
std::string hex_color(const Quantity_Color& c) {
  const auto byte = [](double v) {
    return static_cast<int>(std::lround(std::clamp(v, 0.0, 1.0) * 255));
  };
  double r = 0, g = 0, b = 0;
  c.Values(r, g, b, Quantity_TOC_sRGB);
  char text[8];
  std::snprintf(text, sizeof text, "#%02x%02x%02x", byte(r), byte(g), byte(b));
  return text;
}

/// The colour of a label or shape, surface colour first.
template <class Key>
std::string color_of(const Handle(XCAFDoc_ColorTool) & colors, const Key& key) {
  Quantity_Color c;
  if (colors->GetColor(key, XCAFDoc_ColorSurf, c) || colors->GetColor(key, XCAFDoc_ColorGen, c)) {
    return hex_color(c);
  }
  return {};
}

struct NamedSolid {
  TopoDS_Shape solid;    // placed
  std::string part;      // the product's name
  std::string instance;  // the assembly instance's name
};

struct Walk {
  Handle(XCAFDoc_ShapeTool) shapes;
  Handle(XCAFDoc_ColorTool) colors;
  std::vector<NamedSolid> solids;
  std::vector<std::pair<TopoDS_Shape, ShapeStyle>> faces;  // placed

  void part(const TDF_Label& label, const TopLoc_Location& place, const std::string& instance) {
    const TopoDS_Shape shape = XCAFDoc_ShapeTool::GetShape(label);
    if (shape.IsNull()) return;
    const std::string name = label_name(label);
    const std::string part_color = color_of(colors, label);
    TopTools_IndexedMapOfShape faces_of_part;
    TopExp::MapShapes(shape, TopAbs_FACE, faces_of_part);
    for (int i = 1; i <= faces_of_part.Extent(); ++i) {
      const TopoDS_Shape& face = faces_of_part(i);
      ShapeStyle style;
      TDF_Label sub;
      if (shapes->FindSubShape(label, face, sub)) style.name = label_name(sub);
      style.color = color_of(colors, face);
      if (style.color.empty()) style.color = part_color;
      if (!style.name.empty() || !style.color.empty()) faces.emplace_back(face.Moved(place), style);
    }
    for (TopExp_Explorer ex(shape, TopAbs_SOLID); ex.More(); ex.Next()) {
      solids.push_back({ex.Current().Moved(place), name, instance});
    }
  }

  void visit(const TDF_Label& label, const TopLoc_Location& place, const std::string& instance) {
    if (!XCAFDoc_ShapeTool::IsAssembly(label)) {
      part(label, place, instance);
      return;
    }
    TDF_LabelSequence components;
    XCAFDoc_ShapeTool::GetComponents(label, components);
    for (int i = 1; i <= components.Length(); ++i) {
      TDF_Label referred;
      if (!XCAFDoc_ShapeTool::GetReferredShape(components.Value(i), referred)) continue;
      visit(referred, place * XCAFDoc_ShapeTool::GetLocation(components.Value(i)),
            label_name(components.Value(i)));
    }
  }
};

/// The same shape at the same place (the transforms compared, not their histories).
bool same_placed(const TopoDS_Shape& a, const TopoDS_Shape& b) {
  if (!a.IsPartner(b)) return false;
  const gp_Trsf ta = a.Location().Transformation(), tb = b.Location().Transformation();
  for (int r = 1; r <= 3; ++r) {
    for (int c = 1; c <= 4; ++c) {
      const double x = ta.Value(r, c), y = tb.Value(r, c);
      if (std::fabs(x - y) > 1e-9 * (1 + std::fabs(x))) return false;
    }
  }
  return true;
}

/// Names used by several solids get _1, _2, ... in file order.
void make_unique(std::vector<std::string>& names) {
  std::map<std::string, int> uses, seen;
  for (const std::string& n : names) ++uses[n];
  for (std::string& n : names) {
    if (!n.empty() && uses[n] > 1) n += "_" + std::to_string(++seen[n]);
  }
}

}  // namespace

ReadShape read_step_with_names(const std::string& path) {
  STEPCAFControl_Reader reader;
  reader.SetNameMode(true);
  reader.SetColorMode(true);
  reader.SetLayerMode(false);
  reader.SetPropsMode(false);
  reader.SetGDTMode(false);
  reader.SetMatMode(false);
  reader.SetViewMode(false);
  reader.SetSHUOMode(false);
  if (reader.ReadFile(path.c_str()) != IFSelect_RetDone) {
    throw InputError(path, "cannot parse the STEP file (corrupt or truncated?)");
  }
  check_step_numbers(reader.ChangeReader().StepModel(), path);
  Handle(TDocStd_Document) doc;
  XCAFApp_Application::GetApplication()->NewDocument("MDTV-XCAF", doc);
  if (!reader.Transfer(doc) || reader.ChangeReader().NbShapes() == 0) {
    throw InputError(path, "the STEP file holds no shape");
  }
  ReadShape r;
  r.shape = reader.ChangeReader().OneShape();
  r.log.push_back("STEP read, lengths in millimetres");

  Walk walk;
  walk.shapes = XCAFDoc_DocumentTool::ShapeTool(doc->Main());
  walk.colors = XCAFDoc_DocumentTool::ColorTool(doc->Main());
  TDF_LabelSequence roots;
  walk.shapes->GetFreeShapes(roots);
  for (int i = 1; i <= roots.Length(); ++i) walk.visit(roots.Value(i), TopLoc_Location(), {});

  // Per solid of the shape: its representation item's name, its part's, its instance's.
  std::vector<TopoDS_Shape> solids;
  std::vector<std::string> own, part, instance;
  std::vector<char> used(walk.solids.size(), 0);
  const Handle(XSControl_TransferReader) transfer = reader.ChangeReader().WS()->TransferReader();
  for (TopExp_Explorer ex(r.shape, TopAbs_SOLID); ex.More(); ex.Next()) {
    solids.push_back(ex.Current());
    own.emplace_back();
    part.emplace_back();
    instance.emplace_back();
    const Handle(StepRepr_RepresentationItem) item = Handle(StepRepr_RepresentationItem)::DownCast(
        transfer->EntityFromShapeResult(ex.Current(), 1));
    if (!item.IsNull() && !item->Name().IsNull() && informative(item->Name()->ToCString())) {
      own.back() = item->Name()->ToCString();
    }
    for (std::size_t k = 0; k < walk.solids.size(); ++k) {
      if (used[k] || !same_placed(walk.solids[k].solid, ex.Current())) continue;
      used[k] = 1;
      part.back() = walk.solids[k].part;
      instance.back() = walk.solids[k].instance;
      break;
    }
  }
  // The solid's own name unless several solids share it (every CATIA body is a
  // "PartBody"), else its part's (the product: "nut"), else its instance's.
  std::map<std::string, int> own_uses;
  for (const std::string& n : own) ++own_uses[n];
  std::vector<std::string> names(solids.size());
  for (std::size_t i = 0; i < solids.size(); ++i) {
    if (!own[i].empty() && own_uses[own[i]] == 1) {
      names[i] = own[i];
    } else if (!part[i].empty()) {
      names[i] = part[i];
    } else {
      names[i] = !instance[i].empty() ? instance[i] : own[i];
    }
  }
  make_unique(names);
  for (std::size_t i = 0; i < solids.size(); ++i) {
    if (!names[i].empty()) r.solid_names.emplace_back(solids[i], names[i]);
  }
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(r.shape, TopAbs_FACE, faces);
  for (int i = 1; i <= faces.Extent(); ++i) {
    for (const auto& [face, style] : walk.faces) {
      if (same_placed(face, faces(i))) {
        r.face_styles.emplace_back(faces(i), style);
        break;
      }
    }
  }
  XCAFApp_Application::GetApplication()->Close(doc);
  return r;
}

}  // namespace rdmesh::cad
