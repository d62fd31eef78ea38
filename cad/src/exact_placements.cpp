// Saving and restoring the placements of analytic geometry (exact_placements.h).
#include "exact_placements.h"

#include <BRep_CurveRepresentation.hxx>
#include <BRep_TEdge.hxx>
#include <BRep_TFace.hxx>
#include <Geom2d_Conic.hxx>
#include <Geom2d_Line.hxx>
#include <Geom2d_OffsetCurve.hxx>
#include <Geom2d_TrimmedCurve.hxx>
#include <Geom_Conic.hxx>
#include <Geom_ElementarySurface.hxx>
#include <Geom_Line.hxx>
#include <Geom_OffsetCurve.hxx>
#include <Geom_OffsetSurface.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <cstring>
#include <type_traits>
#include <vector>

namespace rdmesh::cad {
namespace {

// Where one placement lives: the geometry keeps it by value, so its bytes can
// be read and, in a geometry of the same kind, overwritten.
struct Placement {
  char tag;
  const void* bytes;
  std::size_t size;
};

template <typename Axis>
Placement placement(char tag, const Axis& axis) {
  // Plain doubles: the bytes are the value.
  static_assert(std::is_trivially_copyable_v<Axis>);
  return {tag, &axis, sizeof(Axis)};
}

class Walk {
 public:
  explicit Walk(const TopoDS_Shape& shape) {
    TopTools_IndexedMapOfShape faces, edges;
    TopExp::MapShapes(shape, TopAbs_FACE, faces);
    TopExp::MapShapes(shape, TopAbs_EDGE, edges);
    for (int i = 1; i <= faces.Extent(); ++i) {
      const auto face = Handle(BRep_TFace)::DownCast(faces(i).TShape());
      if (!face.IsNull()) surface(face->Surface());
    }
    for (int i = 1; i <= edges.Extent(); ++i) {
      const auto edge = Handle(BRep_TEdge)::DownCast(edges(i).TShape());
      if (edge.IsNull()) continue;
      for (const Handle(BRep_CurveRepresentation) & r : edge->Curves()) {
        if (r->IsCurve3D()) curve(r->Curve3D());
        if (r->IsCurveOnSurface()) {
          surface(r->Surface());
          curve2d(r->PCurve());
        }
        if (r->IsCurveOnClosedSurface()) curve2d(r->PCurve2());
      }
    }
  }
  const std::vector<Placement>& placements() const { return found_; }

 private:
  void surface(const Handle(Geom_Surface) & s) {
    if (s.IsNull()) return;
    if (const auto e = Handle(Geom_ElementarySurface)::DownCast(s); !e.IsNull()) {
      found_.push_back(placement('S', e->Position()));
    } else if (const auto t = Handle(Geom_RectangularTrimmedSurface)::DownCast(s); !t.IsNull()) {
      surface(t->BasisSurface());
    } else if (const auto o = Handle(Geom_OffsetSurface)::DownCast(s); !o.IsNull()) {
      surface(o->BasisSurface());
    }
  }
  void curve(const Handle(Geom_Curve) & c) {
    any_curve<Geom_Conic, Geom_Line, Geom_TrimmedCurve, Geom_OffsetCurve>(c, 'C', 'L');
  }
  void curve2d(const Handle(Geom2d_Curve) & c) {
    any_curve<Geom2d_Conic, Geom2d_Line, Geom2d_TrimmedCurve, Geom2d_OffsetCurve>(c, 'c', 'l');
  }
  // A 3D or 2D curve: the conic's or the line's placement, through trimming and offsets.
  template <typename Conic, typename Line, typename Trimmed, typename Offset, typename Curve>
  void any_curve(const opencascade::handle<Curve>& c, char conic_tag, char line_tag) {
    if (c.IsNull()) return;
    if (const auto k = opencascade::handle<Conic>::DownCast(c); !k.IsNull()) {
      found_.push_back(placement(conic_tag, k->Position()));
    } else if (const auto l = opencascade::handle<Line>::DownCast(c); !l.IsNull()) {
      found_.push_back(placement(line_tag, l->Position()));
    } else if (const auto t = opencascade::handle<Trimmed>::DownCast(c); !t.IsNull()) {
      any_curve<Conic, Line, Trimmed, Offset>(t->BasisCurve(), conic_tag, line_tag);
    } else if (const auto o = opencascade::handle<Offset>::DownCast(c); !o.IsNull()) {
      any_curve<Conic, Line, Trimmed, Offset>(o->BasisCurve(), conic_tag, line_tag);
    }
  }
  std::vector<Placement> found_;
};

}  // namespace

std::string save_placements(const TopoDS_Shape& shape) {
  std::string out;
  const Walk walk(shape);
  for (const Placement& p : walk.placements()) {
    out += p.tag;
    out.append(static_cast<const char*>(p.bytes), p.size);
  }
  return out;
}

bool restore_placements(const TopoDS_Shape& shape, const std::string& saved) {
  const Walk walk(shape);
  std::size_t pos = 0;
  for (const Placement& p : walk.placements()) {
    if (pos + 1 + p.size > saved.size() || saved[pos] != p.tag) return false;
    pos += 1 + p.size;
  }
  if (pos != saved.size()) return false;
  pos = 0;
  for (const Placement& p : walk.placements()) {
    // The geometry is ours (just read) and not const; Position() only hands
    // out a const reference to the member that the formats rebuilt inexactly.
    std::memcpy(const_cast<void*>(p.bytes), saved.data() + pos + 1, p.size);
    pos += 1 + p.size;
  }
  return true;
}

}  // namespace rdmesh::cad
