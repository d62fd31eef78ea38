#include "legend.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string_view>

#include "font.h"
#include "palette.h"

namespace rdmesh::view::detail {
namespace {

constexpr Rgb kFrame{205, 205, 210};
constexpr Rgb kMuted{105, 105, 115};
constexpr Rgb kBar{96, 125, 160};

void fill_rect(Image& image, const Rect& r, Rgb colour) {
  for (int y = std::max(0, r.y0); y < std::min(image.height, r.y1); ++y) {
    for (int x = std::max(0, r.x0); x < std::min(image.width, r.x1); ++x) {
      const std::size_t i = 3 * (static_cast<std::size_t>(y) * image.width + x);
      image.rgb[i] = colour[0];
      image.rgb[i + 1] = colour[1];
      image.rgb[i + 2] = colour[2];
    }
  }
}

std::string count(std::size_t n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

const char* axis_name(int axis) { return axis == 0 ? "x" : axis == 1 ? "y" : "z"; }

const char* view_name(ViewDirection v) {
  switch (v) {
    case ViewDirection::kX:
      return "x";
    case ViewDirection::kY:
      return "y";
    case ViewDirection::kZ:
      return "z";
    case ViewDirection::kIso:
      break;
  }
  return "iso";
}

/// Writes text lines and colour keys left to right, clipped at the area's right end.
class LineWriter {
 public:
  LineWriter(Image& image, const Rect& area, int scale) : image_(image), area_(area), k_(scale) {
    x_ = area.x0;
    y_ = area.y0;
  }
  int line_height() const { return kLineHeight * k_; }
  void new_line() {
    x_ = area_.x0;
    y_ += line_height();
  }
  bool fits(int width) const {
    return x_ + width <= area_.x1 && y_ + kGlyphHeight * k_ <= area_.y1;
  }
  /// Writes `text` if it fits (else an ellipsis if that fits); returns whether all of it did.
  bool text(const std::string& text, Rgb colour = kInk) {
    const int w = text_width(text, k_) + kAdvance * k_;
    if (!fits(w)) {
      if (fits(text_width("...", k_))) draw_text(image_, x_, y_, "...", kMuted, k_);
      x_ = area_.x1;
      return false;
    }
    draw_text(image_, x_, y_, text, colour, k_);
    x_ += w;
    return true;
  }
  /// A colour square followed by its text.
  bool key(Rgb colour, const std::string& text) {
    const int side = kCapHeight * k_;
    if (!fits(side + 3 * k_ + text_width(text, k_))) {
      this->text("...");
      return false;
    }
    fill_rect(image_, {x_, y_, x_ + side, y_ + side}, colour);
    x_ += side + 3 * k_;
    return this->text(text);
  }

 private:
  Image& image_;
  Rect area_;
  int k_;
  int x_, y_;
};

std::string cut_text(const CutPlane& cut) {
  return std::string("cut ") + axis_name(cut.axis) + " = " + format_number(cut.offset, 4);
}

}  // namespace

std::string format_number(double value, int decimals) {
  char buffer[64];
  const auto [end, ec] =
      std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed, decimals);
  if (ec != std::errc()) return "?";
  std::string s(buffer, end);
  if (decimals > 1 && s.find('.') != std::string::npos) {  // 0.2000 -> 0.2
    s.erase(s.find_last_not_of('0') + 1);
    if (s.back() == '.') s.pop_back();
  }
  return s == "-0" ? "0" : s;
}

void draw_frames(Image& image, const Rect& left, const Rect& right, const Rect& band,
                 const LegendContext& c) {
  const int k = c.text_scale;
  fill_rect(image, {right.x0, left.y0 + 4 * k, right.x0 + 1, left.y1 - 4 * k}, kFrame);
  fill_rect(image, {band.x0 + 4 * k, band.y0, band.x1 - 4 * k, band.y0 + 1}, kFrame);
  const std::string left_caption =
      std::string("view ") + view_name(c.options.view) +
      (c.surface.from_tets ? ": boundary of the tetrahedra, by subdomain" : ": boundary, by patch");
  const std::string right_caption =
      cut_text(c.cut) + (c.mesh.tets.empty() ? ": triangles behind it, by patch"
                                             : ": tetrahedra behind it, by subdomain");
  LineWriter(image, {left.x0 + 6 * k, left.y0 + 6 * k, left.x1 - 4 * k, left.y1}, k)
      .text(left_caption, kMuted);
  LineWriter(image, {right.x0 + 6 * k, right.y0 + 6 * k, right.x1 - 4 * k, right.y1}, k)
      .text(right_caption, kMuted);
}

void draw_legend(Image& image, const Rect& area, const LegendContext& c) {
  const ViewMesh& m = c.mesh;
  LineWriter out(image, area, c.text_scale);
  out.text(c.options.title.empty() ? std::string("mesh") : c.options.title);
  out.new_line();
  out.text(count(m.points.size(), "point", "points") + ", " +
           count(m.tets.size(), "tetrahedron", "tetrahedra") + ", " +
           count(m.triangles.size(), "triangle", "triangles") + ", " +
           count(m.edges.size(), "feature edge", "feature edges") + ", " +
           count(m.corners.size(), "corner", "corners"));
  if (m.skipped_elements > 0)
    out.text(std::string("(") + count(m.skipped_elements, "other element", "other elements") +
                 " not drawn)",
             kMuted);
  out.new_line();
  if (!m.tets.empty()) {
    out.text("dihedral angles: min " + format_number(c.quality.min, 1) + ", max " +
             format_number(c.quality.max, 1) + " deg;");
    out.key(kHighlight, count(c.quality.below, "tetrahedron", "tetrahedra") + " below " +
                            format_number(c.options.sliver_angle, 1) + " deg");
  } else {
    out.text("no tetrahedra", kMuted);
  }
  out.new_line();
  const LabelRanks subdomains(m.tet_labels);
  if (!subdomains.labels().empty()) {
    out.text(count(subdomains.labels().size(), "subdomain:", "subdomains:"));
    for (std::size_t r = 0; r < subdomains.labels().size(); ++r) {
      const int label = subdomains.labels()[r];
      auto name = m.subdomain_names.find(label);
      const std::string text =
          std::to_string(label) + (name != m.subdomain_names.end() ? " " + name->second : "");
      if (!out.key(label_colour(r), text)) break;
    }
    out.new_line();
  }
  if (!c.surface.from_tets) {
    const LabelRanks patches(*c.surface.labels);
    out.text(count(patches.labels().size(), "patch:", "patches:"));
    for (std::size_t r = 0; r < patches.labels().size(); ++r) {
      if (!out.key(label_colour(r), std::to_string(patches.labels()[r]))) break;
    }
  }
}

void draw_histogram(Image& image, const Rect& area, const LegendContext& c) {
  const int k = c.text_scale;
  draw_text(image, area.x0, area.y0, "dihedral angles, 5-degree bins", kMuted, k);
  const int label_h = kLineHeight * k;
  const Rect plot{area.x0, area.y0 + label_h, area.x1, area.y1 - label_h};
  const int bar = std::max(1, plot.width() / kHistogramBins);
  const std::size_t top = *std::max_element(c.quality.histogram.begin(), c.quality.histogram.end());
  fill_rect(image, {plot.x0, plot.y1, plot.x0 + bar * kHistogramBins, plot.y1 + 1}, kMuted);
  for (int b = 0; b < kHistogramBins; ++b) {
    const std::size_t n = c.quality.histogram[b];
    if (n == 0) continue;
    const int h =
        std::max(k, static_cast<int>(std::lround(static_cast<double>(n) / top * plot.height())));
    const bool low = 5.0 * b < c.options.sliver_angle;
    fill_rect(
        image,
        {plot.x0 + b * bar, plot.y1 - h, plot.x0 + (b + 1) * bar - (bar > 3 ? 1 : 0), plot.y1},
        low ? kHighlight : kBar);
  }
  for (int degrees : {0, 90, 180}) {
    const std::string text = std::to_string(degrees);
    const int x = plot.x0 + degrees / 5 * bar -
                  (degrees == 0     ? 0
                   : degrees == 180 ? text_width(text, k)
                                    : text_width(text, k) / 2);
    draw_text(image, x, plot.y1 + 3 * k, text, kMuted, k);
  }
}

}  // namespace rdmesh::view::detail
