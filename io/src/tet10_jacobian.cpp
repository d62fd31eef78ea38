// Bounds of the Jacobian determinant of a 10-node tetrahedron.
//
// The map of a quadratic tetrahedron from the reference one is
// x(l) = sum_i l_i (2 l_i - 1) X_i + sum_{i<j} 4 l_i l_j X_ij in barycentric
// coordinates l; its Jacobian determinant is a cubic polynomial. Sampled at the
// 20 points of the cubic lattice (l = a / 3, |a| = 3) and converted to the
// cubic Bernstein basis, its coefficients bound it from below and above
// (Bernstein polynomials are non-negative and sum to one on the simplex), and
// their mean times the reference volume 1/6 is its integral (every cubic
// Bernstein polynomial has the same integral, 1/20 of the simplex's volume).
#include <algorithm>
#include <array>
#include <cmath>

#include "rdmesh/second_order.h"

namespace rdmesh {
namespace {

constexpr int kN = 20;
using Index = std::array<int, 4>;

/// The multi-indices of degree 3 in 4 variables, in a fixed order.
std::array<Index, kN> lattice() {
  std::array<Index, kN> a{};
  int k = 0;
  for (int i = 3; i >= 0; --i) {
    for (int j = 3 - i; j >= 0; --j) {
      for (int l = 3 - i - j; l >= 0; --l) a[k++] = {i, j, l, 3 - i - j - l};
    }
  }
  return a;
}

double bernstein(const Index& a, const std::array<double, 4>& l) {
  static constexpr double kFactorial[4] = {1, 1, 2, 6};
  double v = 6.0;
  for (int i = 0; i < 4; ++i) {
    v /= kFactorial[a[i]];
    for (int p = 0; p < a[i]; ++p) v *= l[i];
  }
  return v;
}

/// The inverse of M[p][a] = B_a(lattice point p): values at the lattice to
/// Bernstein coefficients. Gauss-Jordan with partial pivoting, once.
std::array<std::array<double, kN>, kN> values_to_bernstein() {
  const std::array<Index, kN> idx = lattice();
  std::array<std::array<double, 2 * kN>, kN> m{};
  for (int p = 0; p < kN; ++p) {
    const std::array<double, 4> l{idx[p][0] / 3.0, idx[p][1] / 3.0, idx[p][2] / 3.0,
                                  idx[p][3] / 3.0};
    for (int a = 0; a < kN; ++a) m[p][a] = bernstein(idx[a], l);
    m[p][kN + p] = 1;
  }
  for (int c = 0; c < kN; ++c) {
    int pivot = c;
    for (int r = c + 1; r < kN; ++r) {
      if (std::abs(m[r][c]) > std::abs(m[pivot][c])) pivot = r;
    }
    std::swap(m[c], m[pivot]);
    const double d = m[c][c];
    for (double& v : m[c]) v /= d;
    for (int r = 0; r < kN; ++r) {
      if (r == c || m[r][c] == 0) continue;
      const double f = m[r][c];
      for (int k = 0; k < 2 * kN; ++k) m[r][k] -= f * m[c][k];
    }
  }
  std::array<std::array<double, kN>, kN> inv{};
  for (int r = 0; r < kN; ++r) {
    for (int k = 0; k < kN; ++k) inv[r][k] = m[r][kN + k];
  }
  return inv;
}

/// Node index (Gmsh order) of the mid node of edge {i, j}, i != j.
constexpr int mid_node(int i, int j) {
  constexpr int table[4][4] = {{-1, 4, 6, 7}, {4, -1, 5, 9}, {6, 5, -1, 8}, {7, 9, 8, -1}};
  return table[i][j];
}

/// det J at barycentric point l; `x` holds the nodes relative to node 0.
double jacobian_at(const std::array<Point3, 10>& x, const std::array<double, 4>& l) {
  std::array<Point3, 4> d{};  // d x / d l_i, the l_i taken as independent
  for (int i = 0; i < 4; ++i) {
    Point3 v = (4 * l[i] - 1) * x[i];
    for (int j = 0; j < 4; ++j) {
      if (j != i) v = v + (4 * l[j]) * x[mid_node(i, j)];
    }
    d[i] = v;
  }
  return dot(d[1] - d[0], cross(d[2] - d[0], d[3] - d[0]));
}

}  // namespace

JacobianBounds tet10_jacobian(const std::array<Point3, 10>& nodes) {
  static const std::array<Index, kN> idx = lattice();
  static const std::array<std::array<double, kN>, kN> inv = values_to_bernstein();
  std::array<Point3, 10> x;
  for (int i = 0; i < 10; ++i) x[i] = nodes[i] - nodes[0];
  std::array<double, kN> values{};
  for (int p = 0; p < kN; ++p) {
    values[p] =
        jacobian_at(x, {idx[p][0] / 3.0, idx[p][1] / 3.0, idx[p][2] / 3.0, idx[p][3] / 3.0});
  }
  JacobianBounds b;
  double sum = 0;
  for (int a = 0; a < kN; ++a) {
    double c = 0;
    for (int p = 0; p < kN; ++p) c += inv[a][p] * values[p];
    b.lower = a == 0 ? c : std::min(b.lower, c);
    b.upper = a == 0 ? c : std::max(b.upper, c);
    sum += c;
  }
  b.volume = sum / (6.0 * kN);
  return b;
}

}  // namespace rdmesh
