// Tests of muparser expressions: values against C++, errors, thread safety.
#include "rdmesh/expression.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <numbers>
#include <random>
#include <thread>

#include "rdmesh/domain_file.h"
#include "rdmesh/errors.h"

namespace rdmesh {
namespace {

TEST(Expression, ValuesMatchCpp) {
  struct Case {
    const char* text;
    double (*cpp)(double, double, double);
  };
  const Case cases[] = {
      {"x^2 + y^2 + z^2 - 1",
       [](double x, double y, double z) { return x * x + y * y + z * z - 1; }},
      {"-x^2", [](double x, double, double) { return -(x * x); }},
      {"2^3^2 + z", [](double, double, double z) { return 512 + z; }},
      {"sqrt(abs(x*y)) - cos(z)",
       [](double x, double y, double z) { return std::sqrt(std::abs(x * y)) - std::cos(z); }},
      {"sin(pi*x) + max(y, z, 0.25)",
       [](double x, double y, double z) {
         return std::sin(std::numbers::pi * x) + std::max({y, z, 0.25});
       }},
      {"min(x, y) * (sqrt(x^2 + y^2) - 1)^2",
       [](double x, double y, double) {
         const double q = std::sqrt(x * x + y * y) - 1;
         return std::min(x, y) * q * q;
       }},
      {"(z + 0.1)^2 - 1e-2", [](double, double, double z) { return (z + 0.1) * (z + 0.1) - 1e-2; }},
  };
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-2, 2);
  for (const Case& c : cases) {
    const Expression e(c.text);
    EXPECT_EQ(e.text(), c.text);
    const auto f = make_expression_function(c.text);
    for (int i = 0; i < 50; ++i) {
      const double x = u(rng), y = u(rng), z = u(rng);
      const double expected = c.cpp(x, y, z);
      EXPECT_NEAR(e(x, y, z), expected, 1e-12 * (1 + std::abs(expected))) << c.text;
      EXPECT_EQ(f({x, y, z}), e(x, y, z)) << c.text;
    }
  }
}

TEST(Expression, ErrorsNameTheProblem) {
  auto message = [](const std::string& text) {
    try {
      Expression e(text);
    } catch (const InputError& err) {
      return std::string(err.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("x + w").find("unknown variable 'w' in 'x + w'"), std::string::npos);
  EXPECT_NE(message("foo (x)").find("unknown function 'foo'"), std::string::npos);
  EXPECT_NE(message("x * (y").find("syntax error in 'x * (y'"), std::string::npos);
  EXPECT_NE(message("").find("empty expression"), std::string::npos);
  EXPECT_THROW(make_expression_function("x +"), InputError);
}

TEST(Expression, ConcurrentEvaluationIsExact) {
  const Expression e("sin(x) * cos(y) + z^3");
  auto point = [](int i, int t) { return Point3{0.001 * i, 0.5 * t, -0.0001 * i}; };
  std::vector<std::vector<double>> expected(4);
  for (int t = 0; t < 4; ++t) {
    for (int i = 0; i < 20000; ++i) {
      const Point3 p = point(i, t);
      expected[t].push_back(e(p));
      ASSERT_NEAR(expected[t].back(), std::sin(p.x) * std::cos(p.y) + std::pow(p.z, 3), 1e-14);
    }
  }
  std::vector<std::thread> threads;
  std::atomic<int> mismatches{0};
  for (int t = 0; t < 4; ++t) {
    threads.emplace_back([&, t] {
      // A copy shares the compiled state: it must be safe as well.
      const Expression copy = e;
      for (int i = 0; i < 20000; ++i) {
        if ((i % 2 ? copy : e)(point(i, t)) != expected[t][i]) ++mismatches;
      }
    });
  }
  for (std::thread& th : threads) th.join();
  EXPECT_EQ(mismatches.load(), 0);
}

TEST(Expression, OracleFromJsonIsThreadSafe) {
  LoadedDomain d = parse_domain_json(R"({"bbox": [-1.5, -1.5, -1.5, 1.5, 1.5, 1.5],
      "functions": {"outer": "x^2 + y^2 + z^2 - 1", "inner": "(x-0.1)^2 + y^2 + z^2 - 0.2"},
      "subdomains": [{"inside": ["outer"], "outside": ["inner"]}, {"inside": ["inner"]}]})",
                                     "threads.json");
  const DomainOracle& o = *d.oracle;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  std::vector<std::pair<Point3, Point3>> segments;
  for (int i = 0; i < 4000; ++i)
    segments.push_back({{u(rng), u(rng), u(rng)}, {u(rng), u(rng), u(rng)}});
  std::vector<std::optional<SurfaceHit>> expected;
  for (const auto& [a, b] : segments) expected.push_back(o.intersect(a, b));
  std::vector<std::vector<std::optional<SurfaceHit>>> got(
      4, std::vector<std::optional<SurfaceHit>>(segments.size()));
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t) {
    threads.emplace_back([&, t] {
      // Each thread walks the segments in a different order (multipliers coprime to 4000).
      const std::size_t multiplier[4] = {1, 3, 7, 9};
      for (std::size_t i = 0; i < segments.size(); ++i) {
        const std::size_t j = (i * multiplier[t] + 97 * t) % segments.size();
        got[t][j] = o.intersect(segments[j].first, segments[j].second);
      }
    });
  }
  for (std::thread& th : threads) th.join();
  int hits = 0;
  for (int t = 0; t < 4; ++t) {
    for (std::size_t i = 0; i < segments.size(); ++i) {
      ASSERT_EQ(got[t][i].has_value(), expected[i].has_value())
          << "thread " << t << " segment " << i;
      if (!expected[i]) continue;
      ++hits;
      EXPECT_EQ(got[t][i]->point, expected[i]->point);
      EXPECT_EQ(got[t][i]->patch, expected[i]->patch);
    }
  }
  EXPECT_GT(hits, 1000);
}

}  // namespace
}  // namespace rdmesh
