// A 5x7 bitmap font (with 2 rows of descenders) for the legend: printable
// ASCII, drawn at integer scales.
#pragma once

#include <string_view>

#include "rdmesh/picture.h"

namespace rdmesh::view::detail {

constexpr int kGlyphWidth = 5, kGlyphHeight = 9;  ///< rows stored; capitals are 7 high
constexpr int kCapHeight = 7;                     ///< height of capitals and digits
constexpr int kAdvance = 6;                       ///< glyph width plus one column of spacing
constexpr int kLineHeight = 11;                   ///< at scale 1

/// Width in pixels of `text` drawn at `scale`.
int text_width(std::string_view text, int scale);

/// Draws `text` with its top-left corner at (x, y), clipped to the image;
/// characters outside printable ASCII show as '?'.
void draw_text(Image& image, int x, int y, std::string_view text, Rgb colour, int scale);

}  // namespace rdmesh::view::detail
