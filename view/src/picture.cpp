// render_picture: the layout of the picture and its option parsers.
//
// Layout: the two views side by side above a band holding the legend (left)
// and the histogram (right). The views are drawn supersampled (2x2 below
// 4 megapixels) and averaged down, which smooths the edges; text is drawn
// afterwards at the final size so that it stays crisp.
#include "rdmesh/picture.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>

#include "camera.h"
#include "canvas.h"
#include "font.h"
#include "legend.h"
#include "rdmesh/atomic_file.h"
#include "rdmesh/errors.h"
#include "scene.h"
#include "tet_quality.h"

namespace rdmesh::view {
namespace {

using detail::Rect;

constexpr long long kMaxPixels = 32LL << 20;

/// The points that elements use (files may hold others, far away).
std::vector<Point3> used_points(const ViewMesh& mesh) {
  std::vector<char> used(mesh.points.size(), 0);
  for (const auto& t : mesh.tets)
    for (int v : t) used[v] = 1;
  for (const auto& t : mesh.triangles)
    for (int v : t) used[v] = 1;
  for (const auto& e : mesh.edges)
    for (int v : e) used[v] = 1;
  for (int v : mesh.corners) used[v] = 1;
  std::vector<Point3> points;
  for (std::size_t i = 0; i < used.size(); ++i) {
    if (used[i]) points.push_back(mesh.points[i]);
  }
  return points;
}

/// Through the centre of the points' box, normal to its longest axis among
/// those the view does not look along edge-on.
CutPlane default_cut(const std::vector<Point3>& points, ViewDirection view) {
  Point3 right, up, eye;
  detail::view_axes(view, right, up, eye);
  using detail::coordinate;
  double lo[3], hi[3];
  for (int a = 0; a < 3; ++a) {
    lo[a] = std::numeric_limits<double>::infinity();
    hi[a] = -lo[a];
  }
  for (const Point3& p : points) {
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], coordinate(p, a));
      hi[a] = std::max(hi[a], coordinate(p, a));
    }
  }
  CutPlane cut{-1, 0};
  for (int a = 0; a < 3; ++a) {
    if (std::abs(coordinate(eye, a)) < 1e-9) continue;
    if (cut.axis < 0 || hi[a] - lo[a] > hi[cut.axis] - lo[cut.axis]) cut.axis = a;
  }
  cut.offset = 0.5 * (lo[cut.axis] + hi[cut.axis]);
  return cut;
}

void check_options(const PictureOptions& o, const std::string& what) {
  if (o.width < kMinSize || o.height < kMinSize || o.width > kMaxSize || o.height > kMaxSize ||
      static_cast<long long>(o.width) * o.height > kMaxPixels) {
    throw InputError(what, "picture size " + std::to_string(o.width) + "x" +
                               std::to_string(o.height) + " is out of range (each side " +
                               std::to_string(kMinSize) + " to " + std::to_string(kMaxSize) +
                               ", at most 32 megapixels)");
  }
  if (o.cut && (o.cut->axis < 0 || o.cut->axis > 2 || !std::isfinite(o.cut->offset))) {
    throw InputError(what, "the cut plane needs an axis x, y or z and a finite offset");
  }
  if (!(o.sliver_angle >= 0 && o.sliver_angle <= 180)) {
    throw InputError(what, "the sliver angle must be between 0 and 180 degrees");
  }
}

}  // namespace

Image render_picture(const ViewMesh& mesh, const PictureOptions& options) {
  const std::string what = options.title.empty() ? "picture" : options.title;
  check_options(options, what);
  check_view_mesh(mesh, what);
  if (mesh.tets.empty() && mesh.triangles.empty()) {
    throw InputError(what, "the mesh has neither tetrahedra nor triangles to draw");
  }
  const int W = options.width, H = options.height;
  const int k = std::max(1, std::min(W / 800, H / 450));  // text scale
  const int ss = static_cast<long long>(W) * H <= 4LL << 20 ? 2 : 1;
  const int band_height = 6 * detail::kLineHeight * k + 12 * k;  // five legend lines and margins
  const int views_height = H - band_height;
  const Rect left{0, 0, W / 2, views_height}, right{W / 2, 0, W, views_height};
  const Rect band{0, views_height, W, H};

  const detail::Surface surface = detail::boundary_surface(mesh);
  const detail::TetQuality quality = detail::measure_tets(mesh, options.sliver_angle);
  const std::vector<Point3> drawn = used_points(mesh);
  const CutPlane cut = options.cut ? *options.cut : default_cut(drawn, options.view);

  detail::Canvas canvas(W * ss, views_height * ss, kBackground);
  auto scaled = [ss](const Rect& r) { return Rect{r.x0 * ss, r.y0 * ss, r.x1 * ss, r.y1 * ss}; };
  const detail::Camera camera = detail::frame_points(drawn, options.view, scaled(left), 0.07);
  const detail::Strokes strokes{1.0f * ss, (1.0f + k) * ss, (2.0f + k) * ss};
  canvas.set_clip(scaled(left));
  detail::draw_surface_view(canvas, camera, mesh, surface, strokes);
  canvas.set_clip(scaled(right));
  detail::draw_cut_view(canvas, camera.moved_to(scaled(right)), mesh, surface, cut, quality,
                        options.sliver_angle, strokes);

  Image views = canvas.downsample(ss);
  Image image;
  image.width = W;
  image.height = H;
  image.rgb.assign(3 * static_cast<std::size_t>(W) * H, kBackground[0]);
  std::copy(views.rgb.begin(), views.rgb.end(), image.rgb.begin());

  const detail::LegendContext context{mesh, options, surface, quality, cut, k};
  detail::draw_frames(image, left, right, band, context);
  const int pad = 6 * k;
  const int histogram_width = std::min(W * 2 / 5, 36 * 8 * k);
  detail::draw_legend(image, {pad, band.y0 + pad, W - histogram_width - 3 * pad, H - pad}, context);
  if (!mesh.tets.empty()) {
    detail::draw_histogram(image, {W - histogram_width - pad, band.y0 + pad, W - pad, H - pad},
                           context);
  }
  return image;
}

void render_png(const ViewMesh& mesh, const PictureOptions& options, const std::string& path) {
  const std::vector<std::uint8_t> png = encode_png(render_picture(mesh, options));
  write_file_atomically(path, [&](std::ostream& out) {
    out.write(reinterpret_cast<const char*>(png.data()), static_cast<std::streamsize>(png.size()));
    if (!out) throw OutputError(path + ": write failed");
  });
}

ViewDirection parse_view_direction(const std::string& text) {
  if (text == "iso") return ViewDirection::kIso;
  if (text == "x") return ViewDirection::kX;
  if (text == "y") return ViewDirection::kY;
  if (text == "z") return ViewDirection::kZ;
  throw InputError("--view", "'" + text + "' is not a view direction (iso, x, y or z)");
}

std::array<int, 2> parse_picture_size(const std::string& text) {
  const std::size_t x = text.find('x');
  int w = 0, h = 0;
  bool ok = x != std::string::npos;
  if (ok) {
    const auto [end_w, ec_w] = std::from_chars(text.data(), text.data() + x, w);
    const auto [end_h, ec_h] = std::from_chars(text.data() + x + 1, text.data() + text.size(), h);
    ok = ec_w == std::errc() && end_w == text.data() + x && ec_h == std::errc() &&
         end_h == text.data() + text.size() && x > 0;
  }
  if (!ok || w < kMinSize || h < kMinSize || w > kMaxSize || h > kMaxSize ||
      static_cast<long long>(w) * h > kMaxPixels) {
    throw InputError("--picture-size", "'" + text + "' is not WIDTHxHEIGHT with each side " +
                                           std::to_string(kMinSize) + " to " +
                                           std::to_string(kMaxSize) +
                                           " pixels (at most 32 megapixels)");
  }
  return {w, h};
}

CutPlane parse_cut(const std::string& text) {
  CutPlane cut;
  const bool axis_ok = text.size() > 2 && text[1] == '=' && text[0] >= 'x' && text[0] <= 'z';
  double offset = 0;
  bool ok = axis_ok;
  if (ok) {
    const std::size_t start = text[2] == '+' ? 3 : 2;  // from_chars takes no '+'
    const auto [end, ec] = std::from_chars(text.data() + start, text.data() + text.size(), offset);
    ok = ec == std::errc() && end == text.data() + text.size() && std::isfinite(offset) &&
         !(start == 3 && text.size() > 3 && text[3] == '-');
  }
  if (!ok) throw InputError("--cut", "'" + text + "' is not AXIS=VALUE (x=0.2, y=-1, z=1e-3)");
  cut.axis = text[0] - 'x';
  cut.offset = offset;
  return cut;
}

}  // namespace rdmesh::view
