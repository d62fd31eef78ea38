#include "rdmesh/oracle.h"

#include <algorithm>
#include <string>

#include "rdmesh/errors.h"
#include "rdmesh/feature_table.h"

namespace rdmesh {

std::optional<SurfaceHit> DomainOracle::intersect(const Point3& a, const Point3& b) const {
  const SubdomainId la = locate(a).label;
  SubdomainId lb = locate(b).label;
  if (la == lb) return std::nullopt;
  // Invariant: locate(lo) == la != locate(hi) == lb. 200 halvings reach any
  // tolerance from any segment of finite doubles.
  Point3 lo = a, hi = b;
  const double tol = tolerance();
  for (int i = 0; i < 200 && distance(lo, hi) > tol; ++i) {
    const Point3 mid = 0.5 * (lo + hi);
    const SubdomainId l = locate(mid).label;
    if (l == la) {
      lo = mid;
    } else {
      hi = mid;
      lb = l;
    }
  }
  const SubdomainId s0 = std::min(la, lb), s1 = std::max(la, lb);
  for (const PatchInfo& p : patches()) {
    if (p.side_a == s0 && p.side_b == s1) return SurfaceHit{0.5 * (lo + hi), p.id};
  }
  throw OracleError("no patch between subdomains " + std::to_string(s0.value) + " and " +
                    std::to_string(s1.value) + ", which meet at " + std::to_string(hi.x) + " " +
                    std::to_string(hi.y) + " " + std::to_string(hi.z));
}

const Curve& DomainOracle::curve(CurveId id) const { throw_unknown_id("curve", id.value, 0); }

}  // namespace rdmesh
