// The 3D part of the rasteriser: an RGB colour buffer with a depth buffer,
// filled with flat triangles (optionally with their sides drawn as lines),
// thick lines and dots. Pixel (x, y) has its centre at (x + 0.5, y + 0.5);
// a larger depth is nearer the viewer. Drawing is clipped to a rectangle so
// that the two views of the picture never spill into each other.
#pragma once

#include <cstdint>
#include <vector>

#include "rdmesh/picture.h"

namespace rdmesh::view::detail {

struct ScreenVertex {
  float x = 0, y = 0;  ///< pixels
  float depth = 0;     ///< larger is nearer
};

/// Pixels [x0, x1) x [y0, y1).
struct Rect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  int width() const { return x1 - x0; }
  int height() const { return y1 - y0; }
};

class Canvas {
 public:
  Canvas(int width, int height, Rgb background);

  int width() const { return width_; }
  int height() const { return height_; }
  void set_clip(const Rect& clip);

  /// Fills triangle abc (either orientation) where it is nearer than what is
  /// drawn (after adding `depth_bias` to its depth). With `edge_width` > 0,
  /// pixels closer than edge_width / 2 to one of its sides get `edge` (the
  /// width shrinks on triangles whose inradius is below about 3 edge widths).
  void fill_triangle(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c, Rgb fill,
                     Rgb edge = {}, float edge_width = 0, float depth_bias = 0);
  /// A line `width` pixels wide with square ends, depth-tested like a triangle.
  void draw_line(const ScreenVertex& a, const ScreenVertex& b, float width, Rgb colour,
                 float depth_bias);
  /// A disc of `radius` pixels at `centre`'s depth; with `hole` > 0 a ring, the
  /// pixels closer than `hole` to the centre left as they are.
  void draw_dot(const ScreenVertex& centre, float radius, Rgb colour, float depth_bias,
                float hole = 0);

  /// The picture reduced by `factor` in each direction (each output pixel the
  /// rounded mean of factor x factor pixels): the supersampling's antialiasing.
  Image downsample(int factor) const;

 private:
  void put(std::size_t index, Rgb colour) {
    rgb_[3 * index] = colour[0];
    rgb_[3 * index + 1] = colour[1];
    rgb_[3 * index + 2] = colour[2];
  }

  int width_, height_;
  Rect clip_;
  std::vector<std::uint8_t> rgb_;
  std::vector<float> depth_;
};

}  // namespace rdmesh::view::detail
