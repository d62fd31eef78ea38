// Tests of the triangle mesh readers and structural checks, on small meshes
// written by the tests themselves.
#include "rdmesh/triangle_mesh_io.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "oracles/error_of.h"
#include "rdmesh/errors.h"
#include "rdmesh/triangle_mesh_check.h"

namespace rdmesh {
namespace {

namespace fs = std::filesystem;

// A unit cube: 8 corners, 6 quads (outward).
const char* kCubeOff =
    "OFF\n# a comment\n8 6 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
    "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n";

std::string temp_file(const std::string& name, const std::string& content) {
  const fs::path p =
      fs::temp_directory_path() / ("rdmesh_tmio_" + std::to_string(::getpid()) + "_" + name);
  std::ofstream(p, std::ios::binary) << content;
  return p.string();
}

void expect_has(const std::string& text, const std::string& part) {
  EXPECT_NE(text.find(part), std::string::npos) << "'" << text << "' lacks '" << part << "'";
}

/// The cube's triangles as (x y z) corner triples, for writing other formats.
TriangleSoup cube() {
  std::istringstream in(kCubeOff);
  TriangleSoup s = parse_off(in, "cube.off");
  return s;
}

std::string ascii_stl(const TriangleSoup& s) {
  std::ostringstream o;
  o.precision(17);
  o << "solid cube\n";
  for (const auto& t : s.triangles) {
    o << " facet normal 0 0 0\n  outer loop\n";
    for (int v : t)
      o << "   vertex " << s.points[v].x << " " << s.points[v].y << " " << s.points[v].z << "\n";
    o << "  endloop\n endfacet\n";
  }
  o << "endsolid cube\n";
  return o.str();
}

std::string binary_stl(const TriangleSoup& s) {
  std::string b(80, 'x');
  b.replace(0, 5, "solid");  // a binary file may start with "solid": the size decides
  const std::uint32_t n = static_cast<std::uint32_t>(s.triangles.size());
  b.append(reinterpret_cast<const char*>(&n), 4);
  for (const auto& t : s.triangles) {
    float f[12] = {};
    for (int k = 0; k < 3; ++k) {
      f[3 + 3 * k] = static_cast<float>(s.points[t[k]].x);
      f[4 + 3 * k] = static_cast<float>(s.points[t[k]].y);
      f[5 + 3 * k] = static_cast<float>(s.points[t[k]].z);
    }
    b.append(reinterpret_cast<const char*>(f), 48);
    b.append(2, '\0');
  }
  return b;
}

void expect_cube(const TriangleSoup& s) {
  EXPECT_EQ(s.points.size(), 8u);
  EXPECT_EQ(s.triangles.size(), 12u);
  TriangleSoup copy = s;
  const TriangleMeshTopology topo = orient_triangle_mesh(copy, "x", true);
  EXPECT_EQ(topo.component_count, 1);
  EXPECT_NEAR(enclosed_volume(copy), 1.0, 1e-12);
}

TEST(TriangleMeshIo, Off) { expect_cube(read_triangle_mesh(temp_file("c.off", kCubeOff))); }

TEST(TriangleMeshIo, OffCountsOnHeaderLine) {
  std::string text = kCubeOff;
  text.replace(text.find("OFF\n# a comment\n"), 16, "OFF 8 6 0\n");
  text.erase(text.find("8 6 0\n0 0 0"), 6);
  expect_cube(read_triangle_mesh(temp_file("c2.off", text)));
}

TEST(TriangleMeshIo, AsciiStlMergesDuplicates) {
  const std::string path = temp_file("a.stl", ascii_stl(cube()));
  expect_cube(read_triangle_mesh(path));
}

TEST(TriangleMeshIo, BinaryStl) {
  expect_cube(read_triangle_mesh(temp_file("b.STL", binary_stl(cube()))));
}

TEST(TriangleMeshIo, TruncatedBinaryStl) {
  std::string b = binary_stl(cube());
  b.resize(b.size() - 7);
  const std::string path = temp_file("t.stl", b);
  const std::string e = error_of([&] { read_triangle_mesh(path); });
  expect_has(e, path + ": truncated binary STL");
}

TEST(TriangleMeshIo, Obj) {
  const std::string obj =
      "# cube\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\nvn 0 0 1\n"
      "f 1//1 4//1 3//1 2//1\nf 5/1/1 6/1/1 7/1/1 8/1/1\nf 1 2 6 5\nf 2 3 7 6\nf -6 -5 -1 -2\n"
      "f 4 1 5 8\ng x\nusemtl y\n";
  expect_cube(read_triangle_mesh(temp_file("c.obj", obj)));
}

TEST(TriangleMeshIo, AsciiPly) {
  const std::string ply =
      "ply\nformat ascii 1.0\ncomment hi\nelement vertex 8\nproperty float x\nproperty float y\n"
      "property float z\nproperty uchar red\nelement face 6\nproperty list uchar int "
      "vertex_indices\n"
      "element extra 1\nproperty list uchar float junk\nend_header\n"
      "0 0 0 1\n1 0 0 1\n1 1 0 1\n0 1 0 1\n0 0 1 1\n1 0 1 1\n1 1 1 1\n0 1 1 1\n"
      "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n2 0.5 0.25\n";
  expect_cube(read_triangle_mesh(temp_file("c.ply", ply)));
}

std::string binary_ply(bool big_endian) {
  const TriangleSoup s = cube();
  std::string b =
      std::string("ply\nformat ") + (big_endian ? "binary_big_endian" : "binary_little_endian") +
      " 1.0\nelement vertex 8\nproperty double x\nproperty double y\nproperty double z\n"
      "element face 12\nproperty list uchar uint vertex_indices\nend_header\n";
  auto put = [&](const void* p, int n) {
    std::string bytes(static_cast<const char*>(p), n);
    if (big_endian == (std::endian::native == std::endian::little))
      std::reverse(bytes.begin(), bytes.end());
    b += bytes;
  };
  for (const Point3& p : s.points) {
    put(&p.x, 8);
    put(&p.y, 8);
    put(&p.z, 8);
  }
  for (const auto& t : s.triangles) {
    b += '\3';
    for (int v : t) {
      const std::uint32_t u = v;
      put(&u, 4);
    }
  }
  return b;
}

TEST(TriangleMeshIo, BinaryPlyBothEndians) {
  expect_cube(read_triangle_mesh(temp_file("le.ply", binary_ply(false))));
  expect_cube(read_triangle_mesh(temp_file("be.ply", binary_ply(true))));
  std::string cut = binary_ply(false);
  cut.resize(cut.size() - 3);
  const std::string path = temp_file("cut.ply", cut);
  expect_has(error_of([&] { read_triangle_mesh(path); }), "truncated");
}

TEST(TriangleMeshIo, Errors) {
  auto err = [](const std::string& name, const std::string& text) {
    const std::string path = temp_file(name, text);
    const std::string e = error_of([&] { read_triangle_mesh(path); });
    EXPECT_EQ(e.rfind(path + ": ", 0), 0u) << e;
    return e;
  };
  expect_has(err("i.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n"), "out of range");
  expect_has(err("n.off", "OFF\n3 1 0\n0 0 nan\n1 0 0\n0 1 0\n3 0 1 2\n"), "non-finite");
  expect_has(err("d.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n2 0 0\n3 0 1 2\n"), "degenerate");
  expect_has(err("r.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n0 0 0\n0 1 0\n3 0 1 2\n"), "degenerate");
  expect_has(err("s.off", "OFF\n2 1 0\n0 0 0\n1 0 0\n3 0 1 2\n"), "line 5");
  expect_has(err("e.off", "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"), "ends after 1 of 2 faces");
  expect_has(err("o.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n"), "out of range");
  expect_has(
      err("x.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nend_header\n1\n2\n"),
      "ends early");
  expect_has(err("u.xyz", ""), "unknown");
  expect_has(error_of([] { read_triangle_mesh("/nonexistent/m.off"); }),
             "/nonexistent/m.off: no such file");
}

TriangleSoup soup_of(const std::string& off) {
  std::istringstream in(off);
  TriangleSoup s = parse_off(in, "m.off");
  merge_duplicate_vertices(s);
  return s;
}

TEST(TriangleMeshCheck, OpenSurfaceIsNotClosed) {
  TriangleSoup s = soup_of("OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n");
  const std::string e = error_of([&] { orient_triangle_mesh(s, "m.off", true); });
  expect_has(e, "m.off: not closed: 4 border edges");
  const TriangleMeshTopology t = orient_triangle_mesh(s, "m.off", false);
  EXPECT_FALSE(t.component_closed[0]);
}

TEST(TriangleMeshCheck, NonManifoldEdge) {
  TriangleSoup s =
      soup_of("OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n3 0 1 2\n3 1 0 3\n3 0 1 4\n");
  expect_has(error_of([&] { orient_triangle_mesh(s, "m.off", false); }), "non-manifold edge");
}

TEST(TriangleMeshCheck, TryOrientReportsFailureAndLeavesTheSoup) {
  // The five-vertex Moebius band: triangles (i, i+1, i+2) mod 5, manifold but
  // with no consistent orientation.
  TriangleSoup band = soup_of(
      "OFF\n5 5 0\n1 0 0\n0.3 0.95 0.1\n-0.8 0.6 -0.1\n-0.8 -0.6 0.1\n0.3 -0.95 -0.1\n"
      "3 0 1 2\n3 1 2 3\n3 2 3 4\n3 3 4 0\n3 4 0 1\n");
  const auto before = band.triangles;
  const OrientationResult r = try_orient_triangle_mesh(band, false);
  EXPECT_EQ(r.failure, OrientationFailure::non_orientable);
  EXPECT_FALSE(r.ok());
  expect_has(r.problem, "non-orientable surface");
  EXPECT_EQ(band.triangles, before);
  expect_has(error_of([&] { orient_triangle_mesh(band, "m.off", false); }),
             "m.off: non-orientable surface");

  TriangleSoup open = soup_of("OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n");
  EXPECT_EQ(try_orient_triangle_mesh(open, true).failure, OrientationFailure::not_closed);
  const OrientationResult fine = try_orient_triangle_mesh(open, false);
  EXPECT_TRUE(fine.ok());
  EXPECT_TRUE(fine.problem.empty());
  EXPECT_EQ(fine.topology.component_count, 1);

  TriangleSoup fan =
      soup_of("OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n3 0 1 2\n3 1 0 3\n3 0 1 4\n");
  EXPECT_EQ(try_orient_triangle_mesh(fan, false).failure, OrientationFailure::non_manifold_edge);
}

TEST(TriangleMeshCheck, OrientsInconsistentTrianglesOutward) {
  TriangleSoup s = cube();
  std::swap(s.triangles[3][1], s.triangles[3][2]);    // one flipped triangle
  for (auto& t : s.triangles) std::swap(t[1], t[2]);  // now all inward but one
  const TriangleMeshTopology topo = orient_triangle_mesh(s, "m.off", true);
  EXPECT_NEAR(enclosed_volume(s), 1.0, 1e-12);
  for (int t = 0; t < 12; ++t) {
    for (int k = 0; k < 3; ++k) EXPECT_GE(topo.neighbors[t][k], 0);
  }
}

TEST(TriangleMeshCheck, SelfIntersections) {
  TriangleSoup s = cube();
  EXPECT_NO_THROW(check_self_intersections(s, "m.off"));
  // A second cube poking into the first one.
  const TriangleSoup c = cube();
  for (const auto& t : c.triangles) {
    s.triangles.push_back({t[0] + 8, t[1] + 8, t[2] + 8});
  }
  for (const Point3& p : c.points) s.points.push_back(p + Point3{0.5, 0.5, 0.5});
  expect_has(error_of([&] { check_self_intersections(s, "m.off"); }), "m.off: self-intersecting");
  // Moved away, or nested strictly inside: fine.
  for (int i = 8; i < 16; ++i) s.points[i] = c.points[i - 8] + Point3{3, 0, 0};
  EXPECT_NO_THROW(check_self_intersections(s, "m.off"));
  for (int i = 8; i < 16; ++i) s.points[i] = Point3{0.25, 0.25, 0.25} + 0.5 * c.points[i - 8];
  EXPECT_NO_THROW(check_self_intersections(s, "m.off"));
  // A fold: a triangle folded back onto its neighbour along their shared edge.
  TriangleSoup f = soup_of("OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n0.2 0.2 0\n3 0 1 2\n3 1 0 3\n");
  expect_has(error_of([&] { check_self_intersections(f, "f.off"); }), "self-intersecting");
}

}  // namespace
}  // namespace rdmesh
