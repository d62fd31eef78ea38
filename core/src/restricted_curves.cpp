// D|L_j: the restricted Delaunay triangulations of the curves (RR-7912
// section 3): their samples, the arcs between them and the corners. The rules
// on the arcs (R1, R2) are the curve level's (level_curves.cpp).
#include "restricted_curves.h"

#include "rdmesh/errors.h"
#include "rdmesh/feature_name.h"

namespace rdmesh::detail {

RestrictedCurves::RestrictedCurves(const DomainOracle& oracle) {
  corners_ = oracle.corners();
  for (std::size_t i = 0; i < corners_.size(); ++i) {
    if (corners_[i].id.value != static_cast<int>(i) + 1) {
      throw OracleError("oracle corners must have ids 1..n in order");
    }
  }
  for (const CurveInfo& info : oracle.curves()) {
    if (info.id.value != static_cast<int>(curves_.size()) + 1) {
      throw OracleError("oracle curves must have ids 1..n in order");
    }
    CurveState state;
    state.info = info;
    state.curve = &oracle.curve(info.id);
    curves_.push_back(std::move(state));
  }
}

std::vector<std::vector<PatchId>> RestrictedCurves::corner_patches() const {
  std::vector<std::vector<PatchId>> out;
  for (const CornerInfo& c : corners_) out.push_back(c.patches);
  return out;
}

std::vector<std::vector<PatchId>> RestrictedCurves::curve_patches() const {
  std::vector<std::vector<PatchId>> out;
  for (const CurveState& c : curves_) out.push_back(c.info.patches);
  return out;
}

ChainEdges RestrictedCurves::chain_edges() const {
  ChainEdges chains;
  for (const CurveState& c : curves_) {
    for (auto a = c.samples.begin(); std::next(a) != c.samples.end(); ++a) {
      chains.add(a->second.vertex, std::next(a)->second.vertex);
    }
  }
  chains.finish();
  return chains;
}

std::optional<CurveState::Arc> RestrictedCurves::find_arc(const ArcRef& ref) {
  CurveState& c = curves_[ref.curve];
  const auto a = c.samples.find(ref.t);
  if (a == c.samples.end() || !c.has_next(a)) return std::nullopt;
  if (a->second.vertex != ref.a || std::next(a)->second.vertex != ref.b) return std::nullopt;
  return a;
}

void RestrictedCurves::arcs_of(Vertex_handle v, std::vector<std::pair<int, CurveState::Arc>>& out) {
  out.clear();
  const VertexInfo& info = v->info();
  auto add_around = [&](int curve, std::map<double, CurveSample>::iterator it) {
    CurveState& c = curves_[curve];
    if (it == c.samples.end()) return;
    if (c.has_next(it)) out.emplace_back(curve, it);
    if (it != c.samples.begin()) out.emplace_back(curve, std::prev(it));
  };
  if (info.dim() == FeatureDim::kCurve) {
    const int curve = info.feature.curve().value - 1;
    CurveState& c = curves_[curve];
    add_around(curve, c.samples.find(info.t));
    if (c.info.closed && info.t == c.info.t_begin) add_around(curve, c.samples.find(c.info.t_end));
  } else if (info.dim() == FeatureDim::kCorner) {
    const CornerId corner = info.feature.corner();
    for (const CurveId& id : corners_[corner.value - 1].curves) {
      CurveState& c = curves_[id.value - 1];
      if (c.info.start == corner) add_around(id.value - 1, c.samples.begin());
      if (c.info.end == corner) add_around(id.value - 1, std::prev(c.samples.end()));
    }
  }
}

std::string RestrictedCurves::describe(const VertexInfo& v) const {
  switch (v.dim()) {
    case FeatureDim::kCorner:
      return feature_name(v.feature.corner());
    case FeatureDim::kCurve:
      return feature_name(v.feature.curve(), curves_[v.feature.curve().value - 1].info.name);
    case FeatureDim::kPatch:
      return feature_name(v.feature.patch());
    case FeatureDim::kVolume:
      return "volume";
  }
  return "?";
}

}  // namespace rdmesh::detail
