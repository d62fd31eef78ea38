// The implicit-function oracle: a domain described by signed functions of x, y, z.
//
// Each function f_k is "negative inside": point p is inside f_k when f_k(p) < 0
// and outside f_k when f_k(p) >= 0 (the zero set belongs to the outside, so that
// every point has exactly one label). A subdomain is the set of points inside all
// its `inside` functions and outside all its `outside` functions; the first
// matching subdomain (in order) gives the label, no match gives kOutside (0), and
// every point outside the bounding box is kOutside.
//
// A patch is the part of the boundary between two different labels a < b that
// lies on the zero set of one function f_k: a capped cylinder (inside three
// functions) has three patches, side, top and bottom, separated by its rims.
// Patches are discovered by sampling a regular grid over the box
// (Options::sampling_resolution cells per axis) and numbered 1..m in the order
// of their key (a, b, k); a boundary thinner than a grid cell may be missed by
// patches() and initial_points(), never by locate()/intersect(), which then
// return an unlisted id above m (deterministic: m + 1 + key).
//
// Sharp features (ImplicitCurveSpec, given to the constructor): curves are split
// where they meet (a curve through another's endpoint, two curves crossing), so
// that curves only meet at their endpoints; corners are the endpoints of the open
// pieces, merged within 1e-7 of the box diagonal, ids in order of first
// appearance (pieces in declaration order, start before end). Each piece's
// patches are found by probing labels on small circles (radius 1e-5 of the box
// diagonal, 32 directions) around 8 of its points in the normal plane: each pair
// of adjacent different labels gives patch_between(a, b). A corner's patches are
// the union of its curves' patches. curve(id) returns the piece on its own
// parameter range [t_begin, t_end] (a sub-range of the declared range; for a
// closed curve split at its meeting points, one piece may wrap past the declared
// end, t_end > declared t_end meaning t - period); its end points are exactly its
// corners' points.
//
// Thread safety: every query is const and touches no shared mutable state; the
// functions themselves must be callable concurrently (the expression functions of
// rdmesh/expression.h are).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "rdmesh/feature_table.h"
#include "rdmesh/oracle.h"

namespace rdmesh {

namespace detail {
struct SamplingGrid;  // implicit_sampling.cpp
}  // namespace detail

/// Options of ImplicitOracle (a namespace-scope struct so that it can be a default argument).
struct ImplicitOracleOptions {
  /// Grid cells per box axis used to discover patches, their connected
  /// components and the initial points. Cost: (n+1)^3 evaluations of every function.
  int sampling_resolution = 48;
  /// Optional batch evaluation of function k (indexed as the constructor's
  /// `functions`): fills `out` with the values at `points`, the values the
  /// function gives point by point. The box sampling labels its grid through it,
  /// one call per function; an empty entry (or vector) evaluates point by point.
  /// The Python module passes numpy-vectorised callables this way.
  using BatchFunction =
      std::function<void(const std::vector<Point3>& points, std::vector<double>& out)>;
  std::vector<BatchFunction> batch;
};

/// A sharp-feature curve declared to ImplicitOracle: `curve` restricted to
/// [t_begin, t_end]. Closed when point(t_begin) and point(t_end) are within the
/// corner merge distance (1e-7 of the box diagonal).
struct ImplicitCurveSpec {
  std::string name;  ///< empty: "curve_<index from 1>"
  std::shared_ptr<const Curve> curve;
  double t_begin = 0, t_end = 1;
};

class ImplicitOracle final : public DomainOracle {
 public:
  /// A scalar function, negative inside. Must be deterministic and thread-safe.
  using Function = std::function<double(const Point3&)>;

  /// A subdomain: where all `inside` functions are < 0 and all `outside` ones >= 0.
  /// Indices refer to the `functions` vector.
  struct SubdomainSpec {
    std::string name;  ///< empty: "subdomain_<id>"
    std::vector<int> inside;
    std::vector<int> outside;
  };

  using Options = ImplicitOracleOptions;
  using CurveSpec = ImplicitCurveSpec;

  /// At most this many functions (the sign pattern is kept in one 64-bit word).
  static constexpr int kMaxFunctions = 63;

  /// Builds the oracle and samples the box (deterministic).
  /// Empty `subdomains`: exactly one function is required and its inside is subdomain 1,
  /// named after the function when `function_names` names it, else "subdomain_1".
  /// Throws InputError (message without a file name; callers add it) for: no
  /// function, too many functions, a null function, bad indices, a subdomain with
  /// neither inside nor outside functions, an empty or NaN box, a bad sampling
  /// resolution, and a subdomain that matches no sample point of the box.
  /// `curves` declares the sharp features (see the file comment); InputError
  /// "curve 'NAME': ..." for a null curve, a bad range, a curve leaving the box
  /// or not on the domain boundary (fewer than two labels around one of its points).
  ImplicitOracle(Box3 box, std::vector<Function> functions,
                 std::vector<SubdomainSpec> subdomains = {},
                 std::vector<std::string> function_names = {}, Options options = {},
                 std::vector<CurveSpec> curves = {});

  Box3 bounding_box() const override { return box_; }
  /// The functions' signs at p against the subdomains' rules: as cheap as
  /// any walk, so the hint is ignored.
  Located locate(const Point3& p,
                 const std::optional<LocateHint>& hint = std::nullopt) const override;
  /// Label change bracketed by bisection on the sign pattern until a single
  /// function changes sign, then Brent's method on that function; the hit is
  /// within tolerance() (measured along the segment) of a label change. No heap
  /// allocation; about 10 evaluations for a single smooth function.
  std::optional<SurfaceHit> intersect(const Point3& a, const Point3& b) const override;
  std::vector<SubdomainInfo> subdomains() const override { return subdomain_infos_; }
  std::vector<PatchInfo> patches() const override { return patches_; }
  /// Empty for a patch id that sampling did not find.
  std::vector<Point3> initial_points(PatchId patch) const override {
    return features_.initial_points(patch);
  }
  /// Newton projection onto the zero set of each function that can bound the
  /// patch and onto each crease where two of them vanish (finite-difference
  /// gradients), then a foot-point iteration; each result is verified (the
  /// labels around it are the patch's sides).
  /// Returns the closest verified candidate, nullopt if none converges.
  std::optional<Point3> project(const Point3& p, PatchId patch) const override;
  /// Of the zero set of the function that carries the patch, at the point
  /// that up to 4 Newton steps along the gradient reach from p: the principal
  /// curvatures are the eigenvalues of its Hessian restricted to the tangent
  /// plane, over |grad f|. Gradient and Hessian by central differences of
  /// step 1e-4 x the box diagonal (19 evaluations, 7 per Newton step; the error grows as
  /// (step / radius)^2, 1% at a radius of 10 steps, and sizes below the
  /// default minimum size, 1e-4 of the diagonal, are clamped anyway).
  /// 0 on a boundary no function carries (the box's faces); nullopt for an
  /// unknown patch, where the gradient vanishes or the function is not finite.
  std::optional<double> curvature(const Point3& p, PatchId patch) const override;
  /// 1e-10 times the box diagonal.
  double tolerance() const override { return tolerance_; }
  /// Corners: endpoints of the open curve pieces (empty without curves).
  std::vector<CornerInfo> corners() const override { return features_.corners(); }
  /// Curve pieces after splitting at meeting points, in declaration order.
  std::vector<CurveInfo> curves() const override { return features_.curves(); }
  const Curve& curve(CurveId id) const override { return features_.curve(id); }

  /// The listed patch of smallest id between labels a != b (in any order);
  /// throws OracleError when no listed patch separates them.
  PatchId patch_between(SubdomainId a, SubdomainId b) const;

 private:
  struct Rule {
    std::uint64_t inside = 0;   // bit k: function k must be negative
    std::uint64_t outside = 0;  // bit k: function k must be non-negative
  };
  // Bit k of a state: f_k(p) < 0; bit kInBoxBit: p lies in the box.
  static constexpr int kInBoxBit = 63;

  std::uint64_t state_at(const Point3& p, double* values) const;
  int label_of(std::uint64_t state) const;
  std::optional<Point3> project_on_function(const Point3& p, int k, int a, int b) const;
  std::optional<Point3> project_on_crease(const Point3& p, int k, int l, int a, int b) const;
  Point3 gradient(int k, const Point3& p) const;
  // Sampling (implicit_sampling.cpp).
  void sample_box();
  /// The state of every grid node (in node order) through the batch
  /// functions; empty when no used function has one.
  std::vector<std::uint64_t> grid_states(const detail::SamplingGrid& grid) const;
  /// The label of every grid node; InputError for a subdomain no node lies in.
  std::vector<int> label_grid(const detail::SamplingGrid& grid) const;
  /// Numbers the patch keys found, in key order, as listed patches 1..n (the
  /// others after them); returns n.
  int number_patches(const std::vector<int>& keys_found);
  /// Fills patches_ with the listed patches' names and sides.
  void name_patches(int listed);
  void build_features(std::vector<CurveSpec> specs);  // implicit_features.cpp
  std::vector<PatchId> patches_around(const Curve& curve, double t_begin, double t_end,
                                      const std::string& name) const;

  Box3 box_;
  std::vector<Function> functions_;
  std::vector<std::string> function_names_;
  std::vector<Rule> rules_;
  std::vector<int> used_;  // indices of the functions some rule refers to
  std::vector<SubdomainInfo> subdomain_infos_;
  /// Key of a patch: (label pair rank) * (F + 1) + k, with k the function whose
  /// zero set carries it, k == F for boundaries that no single function carries
  /// (the box, or junctions within tolerance).
  int patch_key(int a, int b, int k) const;
  /// The id of a key: from the table once sampling has built it, key + 1 before.
  PatchId patch_of_key(int key) const;
  std::vector<int> patch_of_key_;  // key -> patch id
  std::vector<int> key_of_patch_;  // patch id -> key (listed patches)
  std::vector<PatchInfo> patches_;
  Options options_;
  double tolerance_ = 0;
  FeatureTable<> features_;  // curve pieces, their corners, initial points
};

}  // namespace rdmesh
