// A picture of a mesh, drawn headless by rdmesh's own software rasteriser and
// written as PNG (libpng).
//
// Layout, as the paper's figures 3 and 4: on the left the boundary triangles,
// flat-shaded and coloured by patch, sharp curves as dark lines, corners as
// dots; on the right the same view cut by an axis-aligned plane, the
// tetrahedra behind it drawn with their edges and coloured by subdomain, the
// worst ones (smallest dihedral angle below PictureOptions::sliver_angle)
// in kHighlight; below, a legend (input name, counts, extreme dihedral
// angles, subdomain colours) and a histogram of dihedral angles in 5-degree
// bins. A mesh without tetrahedra shows its triangles in both views; one
// without triangles shows the boundary faces of its tetrahedra on the left.
//
// The same mesh and options give the same bytes: no clock, no threads, no
// randomness, no locale.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "rdmesh/view_mesh.h"

namespace rdmesh::view {

enum class ViewDirection {
  kIso,  ///< from +x, -y, +z: front, right side and top visible, z up
  kX,    ///< along -x (from +x), z up
  kY,    ///< along +y (from -y, the front), z up
  kZ,    ///< along -z (from above), y up
};

struct CutPlane {
  int axis = 0;       ///< 0 = x, 1 = y, 2 = z
  double offset = 0;  ///< the plane is {p : p[axis] = offset}
};

struct PictureOptions {
  int width = 1600, height = 900;  ///< pixels, kMinSize..kMaxSize each
  ViewDirection view = ViewDirection::kIso;
  /// Default: through the centre of the bounding box, normal to its longest
  /// axis among those the view does not see edge-on.
  std::optional<CutPlane> cut;
  std::string title;         ///< shown in the legend (the input's file name)
  double sliver_angle = 10;  ///< degrees: tetrahedra with a smaller dihedral angle are highlighted
};

constexpr int kMinSize = 320;
constexpr int kMaxSize = 8192;

using Rgb = std::array<std::uint8_t, 3>;

/// Colour of the label of rank `rank` (0 = smallest label of its kind, patches
/// on the left, subdomains on the right) before shading; never close to
/// kHighlight, the background or the line colour.
Rgb label_colour(std::size_t rank);
constexpr Rgb kHighlight{230, 0, 30};  ///< worst tetrahedra, unshaded
constexpr Rgb kBackground{255, 255, 255};
constexpr Rgb kInk{25, 25, 30};  ///< sharp curves, corners, text

/// An RGB image, rows top to bottom, 3 bytes per pixel.
struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;
  Rgb pixel(int x, int y) const {
    const std::size_t i = 3 * (static_cast<std::size_t>(y) * width + x);
    return {rgb[i], rgb[i + 1], rgb[i + 2]};
  }
};

/// Draws the picture. @throws InputError for options out of range (size,
/// a cut axis other than 0..2, a non-finite offset) or an empty mesh.
Image render_picture(const ViewMesh& mesh, const PictureOptions& options);

/// PNG bytes of `image` (8-bit RGB, no time stamp: deterministic).
std::vector<std::uint8_t> encode_png(const Image& image);

/// render_picture then encode_png, written atomically to `path` (a partial
/// file is never left). @throws InputError as render_picture; OutputError
/// ("path: problem") when the file cannot be written.
void render_png(const ViewMesh& mesh, const PictureOptions& options, const std::string& path);

/// Option parsers for command lines and bindings; each throws InputError
/// naming the option and the bad value.
ViewDirection parse_view_direction(const std::string& text);     ///< "iso", "x", "y", "z"
std::array<int, 2> parse_picture_size(const std::string& text);  ///< "1600x900"
CutPlane parse_cut(const std::string& text);                     ///< "x=0.2", "z=-1e-3"

}  // namespace rdmesh::view
