// The picture: size, colours of patches and subdomains in the views, the cut,
// the highlighted slivers, options and determinism.
#include "rdmesh/picture.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "io/io_test_util.h"
#include "rdmesh/errors.h"
#include "view_test_util.h"

namespace rdmesh::view::testing {
namespace {

PictureOptions options(int width = 800, int height = 500) {
  PictureOptions o;
  o.width = width;
  o.height = height;
  o.title = "test";
  return o;
}

/// Appends tetrahedron `p` (new points) to `mesh`, in subdomain 1.
void add_tet(ViewMesh& mesh, const std::array<Point3, 4>& p) {
  const int base = static_cast<int>(mesh.points.size());
  mesh.points.insert(mesh.points.end(), p.begin(), p.end());
  mesh.tets.push_back({base, base + 1, base + 2, base + 3});
  mesh.tet_labels.push_back(1);
}

TEST(Picture, HasTheRequestedSize) {
  const ViewMesh mesh = cube_grid(4, 0.3);
  for (auto [w, h] : {std::pair{800, 500}, {1203, 611}, {320, 320}}) {
    const Image image = render_picture(mesh, options(w, h));
    EXPECT_EQ(image.width, w);
    EXPECT_EQ(image.height, h);
    EXPECT_EQ(image.rgb.size(), 3u * w * h);
  }
  rdmesh::testing::TempDir dir;
  const std::string path = dir.file("grid.png");
  render_png(mesh, options(1000, 420), path);
  const Image read = read_png(path);
  EXPECT_EQ(read.width, 1000);
  EXPECT_EQ(read.height, 420);
}

TEST(Picture, EachVisiblePatchHasItsColourInTheLeftView) {
  // The iso view looks at the cube from +x, -y, +z: it sees the sides x=1
  // (patch 2), y=0 (patch 3) and z=1 (patch 6), each a third of the drawing.
  const ViewMesh mesh = cube_grid(4, 0);
  const Image image = render_picture(mesh, options());
  const Region left = left_view(image);
  const double drawn = static_cast<double>(count_drawn(image, left));
  ASSERT_GT(drawn, 0.15 * (left.x1 - left.x0) * (left.y1 - left.y0))
      << "the cube fills little of the view";
  for (int rank : {1, 2, 5}) {
    const double share = count_shades(image, left, label_colour(rank)) / drawn;
    EXPECT_GT(share, 0.2) << "patch " << rank + 1;
    EXPECT_LT(share, 0.45) << "patch " << rank + 1;
  }
  for (int rank : {0, 3, 4}) {  // hidden sides
    EXPECT_LT(count_shades(image, left, label_colour(rank)) / drawn, 0.01) << "patch " << rank + 1;
  }
}

TEST(Picture, CutThroughTwoSubdomainsShowsBothColours) {
  const ViewMesh mesh = cube_grid(8, 0.3);  // a ball of subdomain 2 inside subdomain 1
  const Image image = render_picture(mesh, options());
  const Region right = right_view(image);
  const double drawn = static_cast<double>(count_drawn(image, right));
  const double outer = count_shades(image, right, label_colour(0)) / drawn;
  const double inner = count_shades(image, right, label_colour(1)) / drawn;
  EXPECT_GT(outer, 0.4);
  EXPECT_GT(inner, 0.03);
  EXPECT_LT(inner, 0.3);
}

TEST(Picture, ACutMissingTheBallShowsOneSubdomain) {
  const ViewMesh mesh = cube_grid(8, 0.3);
  PictureOptions o = options();
  o.cut = CutPlane{0, 0.1};  // keeps x <= 0.1 (the viewer is on the +x side): no ball there
  const Image image = render_picture(mesh, o);
  EXPECT_GT(count_shades(image, right_view(image), label_colour(0)), 1000u);
  EXPECT_EQ(count_shades(image, right_view(image), label_colour(1)), 0u);
}

TEST(Picture, APlantedSliverIsHighlighted) {
  ViewMesh mesh = cube_grid(6, 0);
  const Image clean = render_picture(mesh, options());
  EXPECT_EQ(count_exact(clean, right_view(clean), kHighlight), 0u);
  // A flat tetrahedron across the default cut plane x = 0.5, facing the viewer
  // (who is on the +x side): a square normal to x with two opposite corners
  // moved 0.015 towards the viewer; its centroid is behind the plane, so it is kept.
  add_tet(mesh, {{{0.505, 0.3, 0.3}, {0.49, 0.7, 0.3}, {0.505, 0.7, 0.7}, {0.49, 0.3, 0.7}}});
  const Image image = render_picture(mesh, options());
  EXPECT_GT(count_exact(image, right_view(image), kHighlight), 500u);
  EXPECT_EQ(count_exact(image, left_view(image), kHighlight), 0u);
}

TEST(Picture, PointsNoElementUsesDoNotMoveThePicture) {
  ViewMesh mesh = cube_grid(3, 0.3);
  const Image image = render_picture(mesh, options());
  mesh.points.push_back({100, -50, 7});
  const Image with_far_point = render_picture(mesh, options());
  const std::size_t views =
      3 * static_cast<std::size_t>(image.width) * left_view(image).y1;  // not the legend
  EXPECT_TRUE(std::equal(image.rgb.begin(), image.rgb.begin() + views, with_far_point.rgb.begin()));
}

TEST(Picture, AHiddenSliverIsMarkedByARing) {
  ViewMesh mesh = cube_grid(6, 0);
  const std::size_t base = mesh.points.size();
  // Deep inside the kept half x <= 0.5, behind the cut faces.
  add_tet(mesh, {{{0.2, 0.4, 0.4}, {0.2, 0.6, 0.4}, {0.2, 0.6, 0.6}, {0.201, 0.4, 0.6}}});
  const Image image = render_picture(mesh, options());
  EXPECT_GT(count_exact(image, right_view(image), kHighlight), 20u);
  // A sliver in the half the cut takes away is not drawn.
  for (std::size_t i = base; i < mesh.points.size(); ++i) mesh.points[i].x += 0.6;
  const Image cut_away = render_picture(mesh, options());
  EXPECT_EQ(count_exact(cut_away, right_view(cut_away), kHighlight), 0u);
}

TEST(Picture, SameMeshSameBytes) {
  const ViewMesh mesh = cube_grid(5, 0.3);
  const std::vector<std::uint8_t> a = encode_png(render_picture(mesh, options()));
  const std::vector<std::uint8_t> b = encode_png(render_picture(mesh, options()));
  EXPECT_EQ(a, b);
  rdmesh::testing::TempDir dir;
  render_png(mesh, options(), dir.file("a.png"));
  const std::string file = rdmesh::testing::read_text(dir.file("a.png"));
  EXPECT_EQ(std::vector<std::uint8_t>(file.begin(), file.end()), a);
}

TEST(Picture, ViewDirectionsGiveDifferentPictures) {
  const ViewMesh mesh = cube_grid(4, 0.3);
  std::vector<std::vector<std::uint8_t>> pictures;
  for (ViewDirection v :
       {ViewDirection::kIso, ViewDirection::kX, ViewDirection::kY, ViewDirection::kZ}) {
    PictureOptions o = options();
    o.view = v;
    pictures.push_back(render_picture(mesh, o).rgb);
  }
  for (std::size_t i = 0; i < pictures.size(); ++i)
    for (std::size_t j = i + 1; j < pictures.size(); ++j)
      EXPECT_NE(pictures[i], pictures[j]) << i << " " << j;
  // Looking along z, the left view shows the top side (patch 6) alone.
  PictureOptions top = options();
  top.view = ViewDirection::kZ;
  const Image image = render_picture(mesh, top);
  EXPECT_GT(count_shades(image, left_view(image), label_colour(5)),
            0.9 * count_drawn(image, left_view(image)));
}

TEST(Picture, SurfaceOnlyMeshShowsItsPatchesInBothViews) {
  ViewMesh mesh = cube_grid(4, 0);
  mesh.tets.clear();
  mesh.tet_labels.clear();
  const Image image = render_picture(mesh, options());
  EXPECT_GT(count_shades(image, left_view(image), label_colour(1)), 1000u);
  // Behind the cut x = 0.5 lie the sides y = 0 (patch 3) and z = 1 (6), not x = 1 (2).
  EXPECT_GT(count_shades(image, right_view(image), label_colour(2)), 1000u);
  EXPECT_EQ(count_shades(image, right_view(image), label_colour(1)), 0u);
}

TEST(Picture, TetrahedraWithoutTrianglesShowTheirBoundaryBySubdomain) {
  ViewMesh mesh = cube_grid(4, 0);
  mesh.triangles.clear();
  mesh.triangle_labels.clear();
  for (int& label : mesh.tet_labels) label = 7;
  const Image image = render_picture(mesh, options());
  const Region left = left_view(image);
  EXPECT_GT(count_shades(image, left, label_colour(0)), 0.9 * count_drawn(image, left));
}

TEST(Picture, RejectsBadOptionsAndEmptyMeshes) {
  const ViewMesh mesh = cube_grid(2, 0);
  PictureOptions o = options(100, 500);
  EXPECT_THROW(render_picture(mesh, o), InputError);
  o = options(9000, 500);
  EXPECT_THROW(render_picture(mesh, o), InputError);
  o = options();
  o.cut = CutPlane{3, 0};
  EXPECT_THROW(render_picture(mesh, o), InputError);
  o.cut = CutPlane{0, std::nan("")};
  EXPECT_THROW(render_picture(mesh, o), InputError);
  EXPECT_THROW(render_picture(ViewMesh{}, options()), InputError);
  ViewMesh broken = mesh;
  broken.tets.push_back({0, 1, 2, 1000});
  broken.tet_labels.push_back(1);
  EXPECT_THROW(render_picture(broken, options()), InputError);
}

TEST(Picture, UnwritablePathIsAnOutputErrorAndLeavesNothing) {
  rdmesh::testing::TempDir dir;
  EXPECT_THROW(render_png(cube_grid(2, 0), options(), dir.file("missing/p.png")), OutputError);
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

TEST(PictureOptions, ParsersAcceptGoodValuesAndNameBadOnes) {
  EXPECT_EQ(parse_view_direction("iso"), ViewDirection::kIso);
  EXPECT_EQ(parse_view_direction("z"), ViewDirection::kZ);
  EXPECT_EQ(parse_picture_size("1600x900"), (std::array<int, 2>{1600, 900}));
  const CutPlane cut = parse_cut("y=-0.25");
  EXPECT_EQ(cut.axis, 1);
  EXPECT_EQ(cut.offset, -0.25);
  EXPECT_EQ(parse_cut("z=1e-3").offset, 1e-3);
  EXPECT_EQ(parse_cut("x=+0.5").offset, 0.5);
  for (const char* bad : {"", "iso ", "w", "X"})
    EXPECT_THROW(parse_view_direction(bad), InputError) << bad;
  for (const char* bad :
       {"", "1600", "1600x", "x900", "1600x900x2", "-5x900", "100x100", "9000x900", "1e3x900"}) {
    EXPECT_THROW(parse_picture_size(bad), InputError) << bad;
  }
  for (const char* bad :
       {"", "x", "x=", "w=1", "x=1=2", "x=nan", "x=inf", "x 1", "x=0.2mm", "x=+-1", "x=+"}) {
    EXPECT_THROW(parse_cut(bad), InputError) << bad;
  }
  try {
    parse_picture_size("big");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--picture-size"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace rdmesh::view::testing
