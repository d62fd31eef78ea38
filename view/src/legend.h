// The 2D parts of the picture, drawn on the final image after the 3D views:
// the views' captions, the legend and the dihedral-angle histogram.
#pragma once

#include <string>

#include "canvas.h"
#include "rdmesh/picture.h"
#include "rdmesh/view_mesh.h"
#include "scene.h"
#include "tet_quality.h"

namespace rdmesh::view::detail {

struct LegendContext {
  const ViewMesh& mesh;
  const PictureOptions& options;
  const Surface& surface;
  const TetQuality& quality;
  CutPlane cut;
  int text_scale;  ///< integer scale of the 5x7 font
};

/// Light separators between the views and above the legend band, and a caption
/// in the top-left corner of each view.
void draw_frames(Image& image, const Rect& left, const Rect& right, const Rect& band,
                 const LegendContext& context);

/// Legend lines (input name, counts, angles, colour keys) in `area`.
void draw_legend(Image& image, const Rect& area, const LegendContext& context);

/// Histogram of the dihedral angles in 5-degree bins in `area`; bins below the
/// sliver angle in kHighlight.
void draw_histogram(Image& image, const Rect& area, const LegendContext& context);

/// "12.3" (fixed, `decimals` digits) whatever the C locale is.
std::string format_number(double value, int decimals);

}  // namespace rdmesh::view::detail
