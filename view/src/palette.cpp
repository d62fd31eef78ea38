#include "palette.h"

#include <cmath>

namespace rdmesh::view {
namespace {

// Twelve colours that stay apart from one another once shaded, and from the
// highlight red, the white background and the dark ink.
constexpr Rgb kPalette[] = {{78, 121, 167},  {242, 142, 43},  {89, 161, 79},   {237, 201, 72},
                            {176, 122, 161}, {118, 183, 178}, {255, 157, 167}, {156, 117, 95},
                            {186, 176, 172}, {134, 188, 234}, {170, 200, 90},  {200, 150, 220}};

/// HSV (h in degrees) to RGB.
Rgb from_hsv(double h, double s, double v) {
  const double c = v * s, hp = std::fmod(h, 360.0) / 60.0;
  const double x = c * (1 - std::abs(std::fmod(hp, 2.0) - 1));
  double r = 0, g = 0, b = 0;
  if (hp < 1) {
    r = c, g = x;
  } else if (hp < 2) {
    r = x, g = c;
  } else if (hp < 3) {
    g = c, b = x;
  } else if (hp < 4) {
    g = x, b = c;
  } else if (hp < 5) {
    r = x, b = c;
  } else {
    r = c, b = x;
  }
  const double m = v - c;
  auto byte = [](double u) { return static_cast<std::uint8_t>(std::lround(255 * u)); };
  return {byte(r + m), byte(g + m), byte(b + m)};
}

}  // namespace

Rgb label_colour(std::size_t rank) {
  constexpr std::size_t n = sizeof kPalette / sizeof kPalette[0];
  if (rank < n) return kPalette[rank];
  // Beyond the palette: hues 30..330 degrees (no red) by the golden angle,
  // saturation and value varying so that neighbours in rank differ.
  const std::size_t k = rank - n;
  const double hue = 30 + std::fmod(137.50776 * static_cast<double>(k), 300.0);
  return from_hsv(hue, 0.35 + 0.1 * static_cast<double>(k % 3),
                  0.78 + 0.07 * static_cast<double>(k % 2));
}

namespace detail {

Rgb shade(Rgb colour, double intensity) {
  Rgb out;
  for (int k = 0; k < 3; ++k) {
    out[k] = static_cast<std::uint8_t>(std::clamp(std::lround(colour[k] * intensity), 0L, 255L));
  }
  return out;
}

LabelRanks::LabelRanks(std::vector<int> labels) : sorted_(std::move(labels)) {
  std::sort(sorted_.begin(), sorted_.end());
  sorted_.erase(std::unique(sorted_.begin(), sorted_.end()), sorted_.end());
}

}  // namespace detail
}  // namespace rdmesh::view
