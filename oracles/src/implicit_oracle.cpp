// ImplicitOracle: construction, locate, intersect (projection: implicit_projection.cpp).
// Sampling of the box (patch discovery, initial points) is in implicit_sampling.cpp.

#include "rdmesh/implicit_oracle.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <string>

#include "brent.h"
#include "rdmesh/errors.h"

namespace rdmesh {

namespace {

constexpr std::uint64_t kInBox = std::uint64_t{1} << 63;

}  // namespace

ImplicitOracle::ImplicitOracle(Box3 box, std::vector<Function> functions,
                               std::vector<SubdomainSpec> subdomains,
                               std::vector<std::string> function_names, Options options,
                               std::vector<CurveSpec> curves)
    : box_(box),
      functions_(std::move(functions)),
      function_names_(std::move(function_names)),
      options_(options) {
  const int n = static_cast<int>(functions_.size());
  if (n == 0) throw InputError("no function given");
  if (n > kMaxFunctions) {
    throw InputError("too many functions (" + std::to_string(n) + "), at most " +
                     std::to_string(kMaxFunctions));
  }
  const bool named = !function_names_.empty() && !function_names_[0].empty();
  function_names_.resize(n);
  for (int k = 0; k < n; ++k) {
    if (function_names_[k].empty()) function_names_[k] = "function_" + std::to_string(k);
    if (!functions_[k]) throw InputError("function '" + function_names_[k] + "' is empty");
  }
  if (!is_finite(box_.lo) || !is_finite(box_.hi) || !(box_.lo.x < box_.hi.x) ||
      !(box_.lo.y < box_.hi.y) || !(box_.lo.z < box_.hi.z)) {
    throw InputError("bounding box is empty or not finite (need lo < hi on every axis)");
  }
  if (options_.sampling_resolution < 2 || options_.sampling_resolution > 1024) {
    throw InputError("sampling resolution must be in [2, 1024], got " +
                     std::to_string(options_.sampling_resolution));
  }
  if (subdomains.empty()) {
    if (n != 1) {
      throw InputError("a list of subdomains is required when there are " + std::to_string(n) +
                       " functions");
    }
    subdomains.push_back({named ? function_names_[0] : std::string(), {0}, {}});
  }
  std::uint64_t used = 0;
  for (std::size_t i = 0; i < subdomains.size(); ++i) {
    const SubdomainSpec& spec = subdomains[i];
    const int id = static_cast<int>(i) + 1;
    const std::string name = spec.name.empty() ? "subdomain_" + std::to_string(id) : spec.name;
    if (spec.inside.empty() && spec.outside.empty()) {
      throw InputError("subdomain '" + name + "' has neither inside nor outside functions");
    }
    Rule rule;
    for (int pass = 0; pass < 2; ++pass) {
      for (int k : pass == 0 ? spec.inside : spec.outside) {
        if (k < 0 || k >= n) {
          throw InputError("subdomain '" + name + "' refers to function index " +
                           std::to_string(k) + ", valid indices are 0.." + std::to_string(n - 1));
        }
        (pass == 0 ? rule.inside : rule.outside) |= std::uint64_t{1} << k;
      }
    }
    used |= rule.inside | rule.outside;
    rules_.push_back(rule);
    subdomain_infos_.push_back({SubdomainId(id), name});
  }
  for (int k = 0; k < n; ++k) {
    if (used & (std::uint64_t{1} << k)) used_.push_back(k);
  }
  tolerance_ = 1e-10 * box_.diagonal();
  sample_box();
  build_features(std::move(curves));
}

std::uint64_t ImplicitOracle::state_at(const Point3& p, double* values) const {
  std::uint64_t state = box_.contains(p) ? kInBox : 0;
  for (int k : used_) {
    const double v = functions_[k](p);
    values[k] = v;
    if (v < 0) state |= std::uint64_t{1} << k;
  }
  return state;
}

int ImplicitOracle::label_of(std::uint64_t state) const {
  if (!(state & kInBox)) return 0;
  for (std::size_t i = 0; i < rules_.size(); ++i) {
    if ((rules_[i].inside & ~state) == 0 && (rules_[i].outside & state) == 0) {
      return static_cast<int>(i) + 1;
    }
  }
  return 0;
}

Located ImplicitOracle::locate(const Point3& p, const std::optional<LocateHint>&) const {
  if (!box_.contains(p)) return {kOutside, std::nullopt};
  std::array<double, 64> values;
  return {SubdomainId(label_of(state_at(p, values.data()))), std::nullopt};
}

PatchId ImplicitOracle::patch_between(SubdomainId sa, SubdomainId sb) const {
  const SubdomainId a = std::min(sa, sb), b = std::max(sa, sb);
  for (const PatchInfo& p : patches_) {
    if (p.side_a == a && p.side_b == b) return p.id;
  }
  throw OracleError("no patch between labels " + std::to_string(a.value) + " and " +
                    std::to_string(b.value));
}

int ImplicitOracle::patch_key(int a, int b, int k) const {
  if (a > b) std::swap(a, b);
  const int n = static_cast<int>(rules_.size());
  // Pairs (i, j), i < j <= n, ranked lexicographically: row i holds n - i pairs.
  const int rank = a * n - a * (a - 1) / 2 + (b - a - 1);
  return rank * (static_cast<int>(functions_.size()) + 1) + k;
}

PatchId ImplicitOracle::patch_of_key(int key) const {
  return PatchId(patch_of_key_.empty() ? key + 1 : patch_of_key_[key]);
}

std::optional<SurfaceHit> ImplicitOracle::intersect(const Point3& a, const Point3& b) const {
  std::array<double, 64> vs, vt, vm;
  std::uint64_t ss = state_at(a, vs.data());
  std::uint64_t st = state_at(b, vt.data());
  int ls = label_of(ss), lt = label_of(st);
  if (ls == lt) return std::nullopt;
  const Point3 dir = b - a;
  const double length = norm(dir);
  double ts = 0, tt = 1;
  const double xtol = length > 0 ? tolerance_ / length : 1.0;
  // Bisection on labels until a single function changes sign in [ts, tt].
  for (int iteration = 0; iteration < 200; ++iteration) {
    const std::uint64_t diff = ss ^ st;
    if (std::has_single_bit(diff) && !(diff & kInBox)) {
      const int k = std::countr_zero(diff);
      const Function& f = functions_[k];
      auto g = [&](double t) { return f(a + t * dir); };
      const detail::Transition tr = detail::brent_transition(g, ts, vs[k], tt, vt[k], xtol);
      const std::uint64_t bit = std::uint64_t{1} << k;
      const Point3 hit = a + tr.best * dir;
      // The other functions have equal signs at ts and tt but may change sign an
      // even number of times in between: take their signs at the hit itself.
      const std::uint64_t s_best =
          used_.size() == 1 ? (tr.g_best < 0 ? (ss | bit) : (ss & ~bit)) : state_at(hit, vm.data());
      const std::uint64_t s_other = tr.g_other < 0 ? (s_best | bit) : (s_best & ~bit);
      const int l_best = label_of(s_best);
      if (l_best != label_of(s_other)) {
        return SurfaceHit{hit, patch_of_key(patch_key(l_best, label_of(s_other), k))};
      }
      // This sign change of f_k is not a label change: keep the half that has one.
      if (l_best != ls) {
        tt = tr.best, st = s_best, lt = l_best;
        for (int j : used_) vt[j] = vm[j];
      } else {
        ts = tr.best, ss = s_best, ls = l_best;
        for (int j : used_) vs[j] = vm[j];
      }
      // ... and fall through to a bisection step, which guarantees progress.
    }
    if ((tt - ts) <= xtol) break;
    const double tm = 0.5 * (ts + tt);
    const std::uint64_t sm = state_at(a + tm * dir, vm.data());
    const int lm = label_of(sm);
    if (lm != ls) {
      tt = tm, st = sm, lt = lm;
      for (int k : used_) vt[k] = vm[k];
    } else {
      ts = tm, ss = sm, ls = lm;
      for (int k : used_) vs[k] = vm[k];
    }
  }
  // Several signs change within tolerance (e.g. at the box or a junction of
  // functions): the patch of the lowest function changing sign, else the box.
  const std::uint64_t changed = (ss ^ st) & ~kInBox;
  const int k = changed ? std::countr_zero(changed) : static_cast<int>(functions_.size());
  return SurfaceHit{a + (0.5 * (ts + tt)) * dir, patch_of_key(patch_key(ls, lt, k))};
}

Point3 ImplicitOracle::gradient(int k, const Point3& p) const {
  const double h = 1e-6 * box_.diagonal();
  const Function& f = functions_[k];
  return {(f({p.x + h, p.y, p.z}) - f({p.x - h, p.y, p.z})) / (2 * h),
          (f({p.x, p.y + h, p.z}) - f({p.x, p.y - h, p.z})) / (2 * h),
          (f({p.x, p.y, p.z + h}) - f({p.x, p.y, p.z - h})) / (2 * h)};
}

}  // namespace rdmesh
