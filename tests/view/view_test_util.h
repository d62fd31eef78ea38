// Meshes and pixel counting for the picture tests.
#pragma once

#include <png.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "rdmesh/picture.h"
#include "rdmesh/view_mesh.h"

namespace rdmesh::view::testing {

/// The unit cube cut into n^3 cells of 6 tetrahedra each; tetrahedra of cells
/// whose centre lies within `ball` of the cube's centre are subdomain 2, the
/// others subdomain 1. Triangles: two per cell square on each side of the cube,
/// patch 1 + side (x=0, x=1, y=0, y=1, z=0, z=1 give patches 1..6).
inline ViewMesh cube_grid(int n, double ball) {
  ViewMesh m;
  auto index = [n](int i, int j, int k) { return i + (n + 1) * (j + (n + 1) * k); };
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i)
        m.points.push_back({double(i) / n, double(j) / n, double(k) / n});
  const int steps[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const double x = (i + 0.5) / n - 0.5, y = (j + 0.5) / n - 0.5, z = (k + 0.5) / n - 0.5;
        for (const auto& step : steps) {
          int c[3] = {i, j, k};
          std::array<int, 4> tet{index(i, j, k), 0, 0, 0};
          for (int s = 0; s < 3; ++s) {
            ++c[step[s]];
            tet[s + 1] = index(c[0], c[1], c[2]);
          }
          m.tets.push_back(tet);
          m.tet_labels.push_back(x * x + y * y + z * z < ball * ball ? 2 : 1);
        }
      }
  for (int side = 0; side < 6; ++side) {
    const int axis = side / 2, at = side % 2 == 0 ? 0 : n;
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b) {
        auto corner = [&](int da, int db) {
          int c[3];
          c[axis] = at;
          c[(axis + 1) % 3] = a + da;
          c[(axis + 2) % 3] = b + db;
          return index(c[0], c[1], c[2]);
        };
        m.triangles.push_back({corner(0, 0), corner(1, 0), corner(1, 1)});
        m.triangles.push_back({corner(0, 0), corner(1, 1), corner(0, 1)});
        m.triangle_labels.push_back(1 + side);
        m.triangle_labels.push_back(1 + side);
      }
  }
  return m;
}

/// Pixels [x0, x1) x [y0, y1).
struct Region {
  int x0, y0, x1, y1;
};

/// The views' regions of a picture: the left and right halves above the legend band.
inline Region left_view(const Image& image) {
  return {0, 0, image.width / 2, image.height * 3 / 4};
}
inline Region right_view(const Image& image) {
  return {image.width / 2, 0, image.width, image.height * 3 / 4};
}

/// True when `p` is `c` scaled by a shading factor in [0.3, 1] (within rounding).
inline bool shaded_from(Rgb p, Rgb c) {
  const double dot = double(p[0]) * c[0] + double(p[1]) * c[1] + double(p[2]) * c[2];
  const double cc = double(c[0]) * c[0] + double(c[1]) * c[1] + double(c[2]) * c[2];
  const double s = dot / cc;
  if (s < 0.3 || s > 1.02) return false;
  for (int k = 0; k < 3; ++k) {
    if (std::abs(p[k] - s * c[k]) > 4) return false;
  }
  return true;
}

/// Pixels of `region` that are shades of `colour`.
inline std::size_t count_shades(const Image& image, const Region& r, Rgb colour) {
  std::size_t n = 0;
  for (int y = r.y0; y < r.y1; ++y)
    for (int x = r.x0; x < r.x1; ++x) n += shaded_from(image.pixel(x, y), colour);
  return n;
}

/// Pixels of `region` exactly `colour`.
inline std::size_t count_exact(const Image& image, const Region& r, Rgb colour) {
  std::size_t n = 0;
  for (int y = r.y0; y < r.y1; ++y)
    for (int x = r.x0; x < r.x1; ++x) n += image.pixel(x, y) == colour;
  return n;
}

/// Pixels of `region` that are not the background.
inline std::size_t count_drawn(const Image& image, const Region& r) {
  const std::size_t all = static_cast<std::size_t>(r.x1 - r.x0) * (r.y1 - r.y0);
  return all - count_exact(image, r, kBackground);
}

/// Decodes a PNG file with libpng as 8-bit RGB; width 0 when it cannot.
inline Image read_png(const std::string& path) {
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  Image image;
  if (!png_image_begin_read_from_file(&png, path.c_str())) return image;
  png.format = PNG_FORMAT_RGB;
  image.rgb.resize(PNG_IMAGE_SIZE(png));
  if (!png_image_finish_read(&png, nullptr, image.rgb.data(), 0, nullptr)) {
    png_image_free(&png);
    return image;
  }
  image.width = static_cast<int>(png.width);
  image.height = static_cast<int>(png.height);
  return image;
}

}  // namespace rdmesh::view::testing
