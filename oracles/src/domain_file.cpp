// Parsing of the implicit domain file (.json). Schema: rdmesh/domain_file.h.
#include "rdmesh/domain_file.h"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "domain_file_limits.h"
#include "rdmesh/errors.h"
#include "rdmesh/expression.h"
#include "rdmesh/implicit_oracle.h"
#include "rdmesh/input_file.h"
#include "rdmesh/parametric_curve.h"
#include "rdmesh/polyline_curve.h"
#include "size_spec_json.h"

namespace rdmesh {

namespace {

using Json = nlohmann::ordered_json;

constexpr const char* kTopKeys[] = {
    "description", "bbox",      "functions",      "subdomains",  "curves",      "size", "edge_size",
    "facet_size",  "cell_size", "facet_distance", "facet_angle", "radius_edge", "sizes"};
constexpr const char* kSubdomainKeys[] = {"name", "inside", "outside"};
constexpr const char* kCurveKeys[] = {"name", "x", "y", "z", "t", "points"};
constexpr const char* kExternalCurveKeys[] = {"name", "external"};

std::string one_line(std::string s) {
  for (char& c : s) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  return s;
}

std::string number_text(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

/// Reads one document; throws with the context of every problem.
class Parser {
 public:
  Parser(std::string origin, const ExternalDefinitions* external)
      : origin_(std::move(origin)), external_(external) {}

  LoadedDomain parse(const std::string& text) {
    checked([&] { detail::check_json_depth(text); }, "");
    const Json doc = parse_json(text);
    if (!doc.is_object()) fail("the top level must be a JSON object");
    check_keys(doc, std::begin(kTopKeys), std::end(kTopKeys), "at the top level");
    if (doc.contains("description") && !doc["description"].is_string()) {
      fail("'description' must be a string");
    }
    const Box3 box = parse_bbox(doc);
    diagonal_ = box.diagonal();
    parse_functions(doc);
    std::vector<ImplicitOracle::SubdomainSpec> subdomains = parse_subdomains(doc);
    std::vector<ImplicitOracle::CurveSpec> curves = parse_curves(doc);
    LoadedDomain result;
    result.hints = parse_hints(doc, box.center());
    try {
      ImplicitOracle::Options options;
      options.batch = batch_;
      result.oracle = std::make_unique<ImplicitOracle>(box, functions_, std::move(subdomains),
                                                       names_, options, std::move(curves));
    } catch (const InputError& e) {
      fail(e.what());
    }
    checked([&] { detail::check_domain_inside_box(*result.oracle); }, "");
    return result;
  }

 private:
  [[noreturn]] void fail(const std::string& problem) const {
    throw InputError(origin_, one_line(problem));
  }

  /// Runs `check`; its InputError becomes fail(where + problem).
  template <class Check>
  void checked(Check&& check, const std::string& where) const {
    try {
      check();
    } catch (const InputError& e) {
      fail(where + e.what());
    }
  }

  Json parse_json(const std::string& text) const {
    try {
      return Json::parse(text, nullptr, /*allow_exceptions=*/true, /*ignore_comments=*/true);
    } catch (const Json::exception& e) {
      std::string message = e.what();  // "[json.exception.parse_error.101] parse error at ..."
      const std::size_t bracket = message.find("] ");
      if (message.rfind("[json.exception", 0) == 0 && bracket != std::string::npos) {
        message = message.substr(bracket + 2);
      }
      fail("malformed JSON: " + message);
    }
  }

  template <class It>
  void check_keys(const Json& object, It begin, It end, const std::string& where) const {
    for (const auto& item : object.items()) {
      if (std::find(begin, end, item.key()) != end) continue;
      std::string expected;
      for (It k = begin; k != end; ++k) expected += std::string(expected.empty() ? "" : ", ") + *k;
      fail("unknown key '" + item.key() + "' " + where + " (expected: " + expected + ")");
    }
  }

  Box3 parse_bbox(const Json& doc) const {
    if (!doc.contains("bbox")) fail("missing 'bbox' [xmin, ymin, zmin, xmax, ymax, zmax]");
    const Json& b = doc["bbox"];
    if (!b.is_array() || b.size() != 6) {
      fail("'bbox' must be an array of 6 numbers [xmin, ymin, zmin, xmax, ymax, zmax]");
    }
    double v[6];
    for (int i = 0; i < 6; ++i) {
      if (!b[i].is_number()) fail("'bbox' entry " + std::to_string(i) + " is not a number");
      v[i] = b[i].get<double>();
      if (!std::isfinite(v[i])) fail("'bbox' entry " + std::to_string(i) + " is not finite");
    }
    const char* axis = "xyz";
    for (int i = 0; i < 3; ++i) {
      if (!(v[i] < v[i + 3])) {
        fail(std::string("'bbox' is empty along ") + axis[i] + ": " + axis[i] + "min " +
             number_text(v[i]) + " >= " + axis[i] + "max " + number_text(v[i + 3]));
      }
    }
    const Box3 box{{v[0], v[1], v[2]}, {v[3], v[4], v[5]}};
    checked([&] { detail::check_box_size(box); }, "");
    return box;
  }

  void parse_functions(const Json& doc) {
    if (!doc.contains("functions")) fail("missing 'functions' {\"name\": \"expression\", ...}");
    const Json& fs = doc["functions"];
    if (!fs.is_object() || fs.empty()) {
      fail("'functions' must be a non-empty object {\"name\": \"expression\", ...}");
    }
    for (const auto& item : fs.items()) {
      const std::string name = item.key();
      if (external_ && item.value().is_object()) {
        const ExternalFunction& f = external_function(item.value(), name);
        functions_.push_back(f.point);
        batch_.resize(functions_.size());
        batch_.back() = f.batch;
        names_.push_back(name);
        continue;
      }
      if (!item.value().is_string()) fail("function '" + name + "' must be an expression string");
      checked([&] { detail::check_expression_length(item.value().get<std::string>(), "it"); },
              "function '" + name + "': ");
      try {
        functions_.push_back(Expression(item.value().get<std::string>()));
      } catch (const InputError& e) {
        fail("function '" + name + "': " + e.what());
      }
      names_.push_back(name);
    }
  }

  /// {"external": "KEY"}: the caller's function KEY.
  const ExternalFunction& external_function(const Json& v, const std::string& name) const {
    if (v.size() != 1 || !v.contains("external") || !v["external"].is_string()) {
      fail("function '" + name + "' must be an expression string or {\"external\": KEY}");
    }
    const auto it = external_->functions.find(v["external"].get<std::string>());
    if (it == external_->functions.end() || !it->second.point) {
      fail("function '" + name + "': no external function '" + v["external"].get<std::string>() +
           "'");
    }
    return it->second;
  }

  int function_index(const std::string& name, const std::string& subdomain,
                     const char* list) const {
    for (std::size_t k = 0; k < names_.size(); ++k) {
      if (names_[k] == name) return static_cast<int>(k);
    }
    std::string known;
    for (const std::string& n : names_) known += (known.empty() ? "" : ", ") + n;
    fail("subdomain '" + subdomain + "': unknown function '" + name + "' in '" + list +
         "' (functions: " + known + ")");
  }

  std::vector<int> function_list(const Json& s, const char* list, const std::string& sub) const {
    std::vector<int> out;
    if (!s.contains(list)) return out;
    const Json& v = s[list];
    if (v.is_string()) return {function_index(v.get<std::string>(), sub, list)};
    if (!v.is_array()) fail("subdomain '" + sub + "': '" + list + "' must be a list of names");
    for (const Json& name : v) {
      if (!name.is_string()) {
        fail("subdomain '" + sub + "': '" + list + "' must be a list of function names");
      }
      out.push_back(function_index(name.get<std::string>(), sub, list));
    }
    return out;
  }

  std::vector<ImplicitOracle::SubdomainSpec> parse_subdomains(const Json& doc) const {
    std::vector<ImplicitOracle::SubdomainSpec> out;
    if (!doc.contains("subdomains")) {
      if (names_.size() != 1) {
        fail("'subdomains' is required when there are several functions (" +
             std::to_string(names_.size()) + " given)");
      }
      return out;
    }
    const Json& subs = doc["subdomains"];
    if (!subs.is_array() || subs.empty()) fail("'subdomains' must be a non-empty list");
    if (subs.size() > detail::kMaxSubdomains) {
      fail("too many subdomains (" + std::to_string(subs.size()) + "), at most " +
           std::to_string(detail::kMaxSubdomains));
    }
    for (std::size_t i = 0; i < subs.size(); ++i) {
      const Json& s = subs[i];
      std::string label = "subdomain_" + std::to_string(i + 1);
      if (!s.is_object()) fail("subdomain " + std::to_string(i + 1) + " must be an object");
      if (s.contains("name")) {
        if (!s["name"].is_string() || s["name"].get<std::string>().empty()) {
          fail("subdomain " + std::to_string(i + 1) + ": 'name' must be a non-empty string");
        }
        label = s["name"].get<std::string>();
      }
      check_keys(s, std::begin(kSubdomainKeys), std::end(kSubdomainKeys),
                 "in subdomain '" + label + "'");
      out.push_back({label, function_list(s, "inside", label), function_list(s, "outside", label)});
    }
    return out;
  }

  std::vector<ImplicitOracle::CurveSpec> parse_curves(const Json& doc) const {
    std::vector<ImplicitOracle::CurveSpec> out;
    if (!doc.contains("curves")) return out;
    const Json& list = doc["curves"];
    if (!list.is_array()) fail("'curves' must be a list of curves");
    if (list.size() > detail::kMaxCurves) {
      fail("too many curves (" + std::to_string(list.size()) + "), at most " +
           std::to_string(detail::kMaxCurves));
    }
    for (std::size_t i = 0; i < list.size(); ++i) {
      const Json& c = list[i];
      if (!c.is_object()) fail("curve " + std::to_string(i + 1) + " must be an object");
      std::string name = "curve_" + std::to_string(i + 1);
      if (c.contains("name")) {
        if (!c["name"].is_string() || c["name"].get<std::string>().empty()) {
          fail("curve " + std::to_string(i + 1) + ": 'name' must be a non-empty string");
        }
        name = c["name"].get<std::string>();
      }
      for (const auto& other : out) {
        if (other.name == name) fail("two curves are named '" + name + "'");
      }
      if (external_ && c.contains("external")) {
        check_keys(c, std::begin(kExternalCurveKeys), std::end(kExternalCurveKeys),
                   "in curve '" + name + "'");
        out.push_back(external_curve(c["external"], name));
        continue;
      }
      check_keys(c, std::begin(kCurveKeys), std::end(kCurveKeys), "in curve '" + name + "'");
      out.push_back(parse_curve(c, name));
    }
    std::vector<std::pair<std::string, const Curve*>> named;
    std::vector<std::pair<double, double>> ranges;
    for (const auto& spec : out) {
      checked(
          [&] { detail::check_no_self_overlap(*spec.curve, spec.t_begin, spec.t_end, diagonal_); },
          "curve '" + spec.name + "': ");
      named.emplace_back(spec.name, spec.curve.get());
      ranges.emplace_back(spec.t_begin, spec.t_end);
    }
    checked([&] { detail::check_distinct_curves(named, ranges, diagonal_); }, "");
    return out;
  }

  /// "external": "KEY": the caller's curve KEY, its length checked as a parametric one's.
  ImplicitOracle::CurveSpec external_curve(const Json& key, const std::string& name) const {
    const std::string where = "curve '" + name + "': ";
    if (!key.is_string()) fail(where + "'external' must be a string");
    const auto it = external_->curves.find(key.get<std::string>());
    if (it == external_->curves.end() || !it->second.curve) {
      fail(where + "no external curve '" + key.get<std::string>() + "'");
    }
    ImplicitOracle::CurveSpec spec = it->second;
    spec.name = name;
    const Curve& curve = *spec.curve;
    checked(
        [&] {
          detail::check_curve_length([&curve](double t) { return curve.point(t); }, spec.t_begin,
                                     spec.t_end, diagonal_);
        },
        where);
    return spec;
  }

  ImplicitOracle::CurveSpec parse_curve(const Json& c, const std::string& name) const {
    const std::string where = "curve '" + name + "': ";
    const bool parametric =
        c.contains("x") || c.contains("y") || c.contains("z") || c.contains("t");
    if (parametric == c.contains("points")) {
      fail(where +
           "give either \"x\", \"y\", \"z\" (expressions of t) and \"t\": [t0, t1], "
           "or \"points\": [[x, y, z], ...]");
    }
    {
      if (!parametric) {
        const Json& pts = c["points"];
        if (!pts.is_array() || pts.size() < 2) {
          fail(where + "'points' must be a list of at least two [x, y, z] points");
        }
        if (pts.size() > detail::kMaxPolylinePoints) {
          fail(where + "too many points (" + std::to_string(pts.size()) + "), at most " +
               std::to_string(detail::kMaxPolylinePoints));
        }
        std::vector<Point3> points;
        for (std::size_t k = 0; k < pts.size(); ++k) {
          const Json& p = pts[k];
          if (!p.is_array() || p.size() != 3 || !p[0].is_number() || !p[1].is_number() ||
              !p[2].is_number()) {
            fail(where + "point " + std::to_string(k) + " must be [x, y, z] (three numbers)");
          }
          points.push_back({p[0].get<double>(), p[1].get<double>(), p[2].get<double>()});
        }
        std::shared_ptr<PolylineCurve> curve;
        try {
          curve = std::make_shared<PolylineCurve>(std::move(points));
        } catch (const InputError& e) {
          fail(where + e.what());
        }
        return {name, curve, curve->t_begin(), curve->t_end()};
      }
      std::string xyz[3];
      for (int k = 0; k < 3; ++k) {
        const char* key = k == 0 ? "x" : k == 1 ? "y" : "z";
        if (!c.contains(key)) fail(where + "missing '" + key + "' (an expression of t)");
        if (!c[key].is_string()) fail(where + "'" + key + "' must be an expression string of t");
        xyz[k] = c[key].get<std::string>();
        checked([&] { detail::check_expression_length(xyz[k], std::string("'") + key + "'"); },
                where);
      }
      if (!c.contains("t")) fail(where + "missing 't': [t0, t1], the parameter range");
      const Json& t = c["t"];
      if (!t.is_array() || t.size() != 2 || !t[0].is_number() || !t[1].is_number() ||
          !std::isfinite(t[0].get<double>()) || !std::isfinite(t[1].get<double>()) ||
          !(t[0].get<double>() < t[1].get<double>())) {
        fail(where + "'t' must be [t0, t1] with finite numbers t0 < t1, got " + one_line(t.dump()));
      }
      const double t0 = t[0].get<double>(), t1 = t[1].get<double>();
      check_parametric_length(xyz, t0, t1, where);
      try {
        return {name, std::make_shared<ParametricCurve>(xyz[0], xyz[1], xyz[2], t0, t1), t0, t1};
      } catch (const InputError& e) {
        fail(where + e.what());
      }
    }
  }

  /// A curve with a million turns is refused before its sample table is built
  /// (syntax errors are left to ParametricCurve, which names the coordinate).
  void check_parametric_length(const std::string (&xyz)[3], double t0, double t1,
                               const std::string& where) const {
    std::optional<Expression> e[3];
    try {
      for (int k = 0; k < 3; ++k) e[k].emplace(xyz[k], std::vector<std::string>{"t"});
    } catch (const InputError&) {
      return;
    }
    const auto gamma = [&e](double t) { return Point3{e[0]->at(t), e[1]->at(t), e[2]->at(t)}; };
    checked([&] { detail::check_curve_length(gamma, t0, t1, diagonal_); }, where);
  }

  std::optional<double> positive_number(const Json& doc, const char* key, double max) const {
    if (!doc.contains(key)) return std::nullopt;
    const Json& v = doc[key];
    if (!v.is_number()) fail(std::string("'") + key + "' must be a number");
    const double d = v.get<double>();
    if (!std::isfinite(d) || !(d > 0) || !(d < max)) {
      fail(std::string("'") + key + "' must be a positive finite number" +
           (std::isinf(max) ? "" : " below " + number_text(max)) + ", got " + number_text(d));
    }
    return d;
  }

  std::optional<ScalarField> size_field(const Json& doc, const char* key, Point3 center) const {
    if (!doc.contains(key)) return std::nullopt;
    const Json& v = doc[key];
    if (v.is_number()) return ScalarField::uniform(*positive_number(doc, key, INFINITY));
    if (!v.is_string()) fail(std::string("'") + key + "' must be a number or an expression");
    std::optional<Expression> e;
    checked([&] { detail::check_expression_length(v.get<std::string>(), "the expression"); },
            std::string("'") + key + "': ");
    try {
      e.emplace(v.get<std::string>());
    } catch (const InputError& err) {
      fail(std::string("'") + key + "': " + err.what());
    }
    const double at_center = (*e)(center);
    if (!std::isfinite(at_center) || !(at_center > 0)) {
      fail(std::string("'") + key + "' expression '" + e->text() + "' evaluates to " +
           number_text(at_center) + " at the box center (" + number_text(center.x) + ", " +
           number_text(center.y) + ", " + number_text(center.z) + "); it must be positive");
    }
    return ScalarField{0.0, *e, /*thread_safe=*/true};  // one muparser object per thread
  }

  CriteriaHints parse_hints(const Json& doc, Point3 center) const {
    CriteriaHints h;
    h.size = size_field(doc, "size", center);
    h.edge_size = size_field(doc, "edge_size", center);
    h.facet_size = size_field(doc, "facet_size", center);
    h.cell_size = size_field(doc, "cell_size", center);
    h.facet_distance = positive_number(doc, "facet_distance", INFINITY);
    h.facet_angle = positive_number(doc, "facet_angle", 60.0);
    h.radius_edge = positive_number(doc, "radius_edge", INFINITY);
    if (doc.contains("sizes")) {
      checked([&] { h.sizes = detail::size_spec_from_json(doc["sizes"]); }, "'sizes': ");
    }
    return h;
  }

  std::string origin_;
  const ExternalDefinitions* external_;  ///< null: a domain file
  double diagonal_ = 0;                  ///< of the bbox
  std::vector<ImplicitOracle::Function> functions_;
  std::vector<std::string> names_;
  std::vector<ImplicitOracleOptions::BatchFunction> batch_;  ///< external functions' batches
};

}  // namespace

LoadedDomain parse_domain_json(const std::string& text, const std::string& origin,
                               const ExternalDefinitions& external) {
  return Parser(origin, &external).parse(text);
}

LoadedDomain parse_domain_json(const std::string& text, const std::string& origin) {
  return Parser(origin, nullptr).parse(text);
}

LoadedDomain load_domain_file(const std::string& path) {
  check_input_file(path);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, std::string("cannot open file: ") + std::strerror(errno));
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError(path, "cannot read file");
  return parse_domain_json(text.str(), path);
}

}  // namespace rdmesh
