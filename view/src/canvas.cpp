#include "canvas.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace rdmesh::view::detail {
namespace {

/// False for vertices far outside any canvas, or not finite (from degenerate
/// input): their bounding boxes could not be converted to pixel indices.
bool usable(const ScreenVertex& v) {
  return std::abs(v.x) < 1e7f && std::abs(v.y) < 1e7f && std::abs(v.depth) < 1e30f;
}

}  // namespace

Canvas::Canvas(int width, int height, Rgb background)
    : width_(width),
      height_(height),
      clip_{0, 0, width, height},
      rgb_(3 * static_cast<std::size_t>(width) * height),
      depth_(static_cast<std::size_t>(width) * height, -std::numeric_limits<float>::infinity()) {
  for (std::size_t i = 0; i < depth_.size(); ++i) put(i, background);
}

void Canvas::set_clip(const Rect& clip) {
  clip_ = {std::max(0, clip.x0), std::max(0, clip.y0), std::min(width_, clip.x1),
           std::min(height_, clip.y1)};
}

void Canvas::fill_triangle(const ScreenVertex& a, const ScreenVertex& b_in,
                           const ScreenVertex& c_in, Rgb fill, Rgb edge, float edge_width,
                           float depth_bias) {
  if (!usable(a) || !usable(b_in) || !usable(c_in)) return;
  ScreenVertex b = b_in, c = c_in;
  float area = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
  if (!(std::abs(area) > 1e-9f)) return;  // seen edge-on (or NaN)
  if (area < 0) {
    std::swap(b, c);
    area = -area;
  }
  const int x0 = std::max(clip_.x0, static_cast<int>(std::floor(std::min({a.x, b.x, c.x}))));
  const int x1 = std::min(clip_.x1 - 1, static_cast<int>(std::ceil(std::max({a.x, b.x, c.x}))));
  const int y0 = std::max(clip_.y0, static_cast<int>(std::floor(std::min({a.y, b.y, c.y}))));
  const int y1 = std::min(clip_.y1 - 1, static_cast<int>(std::ceil(std::max({a.y, b.y, c.y}))));
  if (x0 > x1 || y0 > y1) return;

  // Edge functions: w0 vanishes on side bc, w1 on ca, w2 on ab; inside all are >= 0
  // and they sum to `area`. w_k / |side k| is the distance to side k in pixels.
  const float dx0 = -(c.y - b.y), dy0 = c.x - b.x;
  const float dx1 = -(a.y - c.y), dy1 = a.x - c.x;
  const float dx2 = -(b.y - a.y), dy2 = b.x - a.x;
  const bool edges = edge_width > 0;
  const float len0 = std::hypot(dx0, dy0), len1 = std::hypot(dx1, dy1), len2 = std::hypot(dx2, dy2);
  // Sides at most 0.3 of the inradius wide: tiny triangles keep their colour.
  const float half = std::min(0.5f * edge_width, 0.3f * area / (len0 + len1 + len2));
  const float inv0 = 1.0f / len0, inv1 = 1.0f / len1, inv2 = 1.0f / len2;
  const float inv_area = 1.0f / area;
  for (int y = y0; y <= y1; ++y) {
    const float py = static_cast<float>(y) + 0.5f, px = static_cast<float>(x0) + 0.5f;
    float w0 = dy0 * (py - b.y) + dx0 * (px - b.x);
    float w1 = dy1 * (py - c.y) + dx1 * (px - c.x);
    float w2 = dy2 * (py - a.y) + dx2 * (px - a.x);
    std::size_t index = static_cast<std::size_t>(y) * width_ + x0;
    for (int x = x0; x <= x1; ++x, ++index, w0 += dx0, w1 += dx1, w2 += dx2) {
      if (w0 < 0 || w1 < 0 || w2 < 0) continue;
      const float depth = (w0 * a.depth + w1 * b.depth + w2 * c.depth) * inv_area;
      if (!(depth + depth_bias > depth_[index])) continue;
      depth_[index] = depth;
      const bool on_edge = edges && (w0 * inv0 < half || w1 * inv1 < half || w2 * inv2 < half);
      put(index, on_edge ? edge : fill);
    }
  }
}

void Canvas::draw_line(const ScreenVertex& a, const ScreenVertex& b, float width, Rgb colour,
                       float depth_bias) {
  const float dx = b.x - a.x, dy = b.y - a.y;
  const float length = std::hypot(dx, dy);
  const float h = 0.5f * width;
  if (!(length > 1e-6f)) {
    draw_dot(a, h, colour, depth_bias);
    return;
  }
  const float ux = dx / length * h, uy = dy / length * h;  // along, half width long
  const ScreenVertex a0{a.x - ux - uy, a.y - uy + ux, a.depth},
      a1{a.x - ux + uy, a.y - uy - ux, a.depth};
  const ScreenVertex b0{b.x + ux - uy, b.y + uy + ux, b.depth},
      b1{b.x + ux + uy, b.y + uy - ux, b.depth};
  fill_triangle(a0, a1, b1, colour, {}, 0, depth_bias);
  fill_triangle(a0, b1, b0, colour, {}, 0, depth_bias);
}

void Canvas::draw_dot(const ScreenVertex& centre, float radius, Rgb colour, float depth_bias,
                      float hole) {
  if (!usable(centre)) return;
  const int x0 = std::max(clip_.x0, static_cast<int>(std::floor(centre.x - radius)));
  const int x1 = std::min(clip_.x1 - 1, static_cast<int>(std::ceil(centre.x + radius)));
  const int y0 = std::max(clip_.y0, static_cast<int>(std::floor(centre.y - radius)));
  const int y1 = std::min(clip_.y1 - 1, static_cast<int>(std::ceil(centre.y + radius)));
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      const float ex = static_cast<float>(x) + 0.5f - centre.x,
                  ey = static_cast<float>(y) + 0.5f - centre.y;
      const float r2 = ex * ex + ey * ey;
      if (r2 > radius * radius || r2 < hole * hole) continue;
      const std::size_t index = static_cast<std::size_t>(y) * width_ + x;
      if (!(centre.depth + depth_bias > depth_[index])) continue;
      depth_[index] = centre.depth;
      put(index, colour);
    }
  }
}

Image Canvas::downsample(int factor) const {
  Image out;
  out.width = width_ / factor;
  out.height = height_ / factor;
  out.rgb.resize(3 * static_cast<std::size_t>(out.width) * out.height);
  const unsigned count = static_cast<unsigned>(factor * factor);
  for (int y = 0; y < out.height; ++y) {
    for (int x = 0; x < out.width; ++x) {
      unsigned sum[3] = {0, 0, 0};
      for (int sy = 0; sy < factor; ++sy) {
        const std::size_t row = static_cast<std::size_t>(y * factor + sy) * width_ + x * factor;
        for (int sx = 0; sx < factor; ++sx) {
          for (int k = 0; k < 3; ++k) sum[k] += rgb_[3 * (row + sx) + k];
        }
      }
      const std::size_t o = 3 * (static_cast<std::size_t>(y) * out.width + x);
      for (int k = 0; k < 3; ++k)
        out.rgb[o + k] = static_cast<std::uint8_t>((sum[k] + count / 2) / count);
    }
  }
  return out;
}

}  // namespace rdmesh::view::detail
