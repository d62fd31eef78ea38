// Round trips of the three writers through independent readers: meshio
// (coordinates, connectivity with orientation, labels, names) and gmsh -check.
#include <gtest/gtest.h>

#include <cmath>
#include <locale>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "io/io_test_util.h"
#include "io/meshio_util.h"
#include "io/test_meshes.h"
#include "rdmesh/errors.h"
#include "rdmesh/mesh_writers.h"

namespace rdmesh {
namespace {

using testing::run_command;
using testing::TempDir;

/// The two-cube mesh with irregular coordinates (tests full precision).
TetMesh jittered_mesh() { return testing::jittered(testing::two_cube_mesh(0.1)); }

using WritersTest = testing::MeshioTest;
using testing::expect_same_points;
using testing::labelled;
using testing::read_cells;

TEST_F(WritersTest, MeditRoundTripThroughMeshio) {
  const TetMesh mesh = jittered_mesh();
  const nlohmann::json dump = write_and_read(mesh, "m.mesh");
  expect_same_points(mesh, dump);
  EXPECT_EQ(read_cells(dump, "tetra", "medit:ref"), labelled(mesh.tets, mesh.tet_subdomain));
  EXPECT_EQ(read_cells(dump, "triangle", "medit:ref"),
            labelled(mesh.triangles, mesh.triangle_patch));
}

TEST_F(WritersTest, VtuRoundTripThroughMeshio) {
  const TetMesh mesh = jittered_mesh();
  const nlohmann::json dump = write_and_read(mesh, "m.vtu");
  expect_same_points(mesh, dump);
  EXPECT_EQ(read_cells(dump, "tetra", "subdomain"), labelled(mesh.tets, mesh.tet_subdomain));
  EXPECT_EQ(read_cells(dump, "triangle", "patch"), labelled(mesh.triangles, mesh.triangle_patch));
  for (const auto& [cell, label] : read_cells(dump, "tetra", "patch")) EXPECT_EQ(label, 0);
  for (const auto& [cell, label] : read_cells(dump, "triangle", "subdomain")) EXPECT_EQ(label, 0);
  EXPECT_EQ(dump.at("cells")[0].at("cell_data").count("medit:ref"), 0u);
}

TEST_F(WritersTest, GmshRoundTripThroughMeshio) {
  const TetMesh mesh = jittered_mesh();
  const nlohmann::json dump = write_and_read(mesh, "m.msh");
  expect_same_points(mesh, dump);
  for (const char* key : {"gmsh:physical", "gmsh:geometrical"}) {
    EXPECT_EQ(read_cells(dump, "tetra", key), labelled(mesh.tets, mesh.tet_subdomain)) << key;
    EXPECT_EQ(read_cells(dump, "triangle", key), labelled(mesh.triangles, mesh.triangle_patch))
        << key;
  }
  // Physical names: meshio maps name -> [tag, dimension].
  const auto& names = dump.at("field_data");
  EXPECT_EQ(names.at("left"), nlohmann::json({1, 3}));
  EXPECT_EQ(names.at("right"), nlohmann::json({2, 3}));
  EXPECT_EQ(names.at("left skin"), nlohmann::json({1, 2}));
  EXPECT_EQ(names.at("right skin"), nlohmann::json({2, 2}));
  EXPECT_EQ(names.at("interface"), nlohmann::json({3, 2}));
}

TEST(GmshCheck, AcceptsOurMshAndMeditFiles) {
  if (!testing::gmsh_available()) RDMESH_MISSING_PREREQUISITE("gmsh");
  TempDir dir;
  const TetMesh mesh = jittered_mesh();
  write_mesh(mesh, dir.file("m.msh"));
  write_mesh(mesh, dir.file("m.mesh"));
  testing::expect_gmsh_accepts("-check " + dir.file("m.msh"));
  testing::expect_gmsh_accepts("-check " + dir.file("m.mesh"));
  // Gmsh re-exports the file with the same elements and physical names.
  testing::expect_gmsh_accepts(dir.file("m.msh") + " -0 -o " + dir.file("again.msh"));
  const std::string again = testing::read_text(dir.file("again.msh"));
  for (const char* name : {"\"left\"", "\"right\"", "\"left skin\"", "\"interface\""}) {
    EXPECT_NE(again.find(name), std::string::npos) << name;
  }
  const auto r = run_command("gmsh -check " + dir.file("m.msh"));
  EXPECT_NE(r.output.find("34 elements"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("12 nodes"), std::string::npos) << r.output;
}

TEST(Writers, OutputIsDeterministic) {
  const TetMesh mesh = jittered_mesh();
  for (auto write : {write_medit, write_gmsh41, write_vtu}) {
    std::ostringstream a, b;
    write(mesh, a);
    write(mesh, b);
    EXPECT_EQ(a.str(), b.str());
    EXPECT_FALSE(a.str().empty());
  }
}

/// Thousands grouped with commas, as some user locales do.
struct Grouping : std::numpunct<char> {
  char do_thousands_sep() const override { return ','; }
  std::string do_grouping() const override { return "\3"; }
};

TEST(Writers, NumbersDoNotFollowTheStreamsLocale) {
  // 300 copies of the two cubes side by side: thousands of vertices and tetrahedra.
  const TetMesh one = jittered_mesh();
  TetMesh mesh = one;
  for (int k = 1; k < 300; ++k) {
    const int shift = static_cast<int>(mesh.vertices.size());
    for (const Point3& p : one.vertices) mesh.vertices.push_back(p + Point3{3.0 * k, 0, 0});
    for (auto t : one.tets) {
      for (int& v : t) v += shift;
      mesh.tets.push_back(t);
    }
    mesh.tet_subdomain.insert(mesh.tet_subdomain.end(), one.tet_subdomain.begin(),
                              one.tet_subdomain.end());
    for (auto t : one.triangles) {
      for (int& v : t) v += shift;
      mesh.triangles.push_back(t);
    }
    mesh.triangle_patch.insert(mesh.triangle_patch.end(), one.triangle_patch.begin(),
                               one.triangle_patch.end());
  }
  ASSERT_GT(mesh.tets.size(), 1000u);
  for (auto write : {write_medit, write_gmsh41, write_gmsh41_binary, write_gmsh22, write_vtu,
                     write_vtu_binary}) {
    std::ostringstream plain, grouped;
    grouped.imbue(std::locale(std::locale::classic(), new Grouping));
    write(mesh, plain);
    write(mesh, grouped);
    const std::string a = grouped.str(), b = plain.str();
    const auto at = std::mismatch(a.begin(), a.end(), b.begin(), b.end()).first - a.begin();
    EXPECT_EQ(a, b) << "differs at byte " << at << ": " << a.substr(at > 40 ? at - 40 : 0, 80);
  }
}

TEST(Writers, MeditLayout) {
  std::ostringstream out;
  write_medit(testing::two_cube_mesh(0.5), out);
  const std::string s = out.str();
  EXPECT_EQ(s.rfind("MeshVersionFormatted 2\n", 0), 0u);
  EXPECT_NE(s.find("Dimension 3\n"), std::string::npos);
  EXPECT_NE(s.find("Vertices\n12\n0 0 0 0\n0.5 0 0 0\n1 0 0 0\n"), std::string::npos);
  EXPECT_NE(s.find("Tetrahedra\n12\n"), std::string::npos);
  EXPECT_NE(s.find("Triangles\n22\n"), std::string::npos);
  EXPECT_EQ(s.substr(s.size() - 4), "End\n");
}

TEST(Writers, EmptyMeshIsWritable) {
  for (auto write : {write_medit, write_gmsh41, write_vtu}) {
    std::ostringstream out;
    EXPECT_NO_THROW(write(TetMesh{}, out));
  }
}

TEST(Writers, InconsistentMeshIsRejected) {
  TetMesh mesh = testing::two_cube_mesh(0.1);
  mesh.triangles[0][1] = -1;
  for (auto write : {write_medit, write_gmsh41, write_vtu}) {
    std::ostringstream out;
    EXPECT_THROW(write(mesh, out), InternalError);
  }
  mesh = testing::two_cube_mesh(0.1);
  mesh.tet_subdomain[0] = kOutside;
  std::ostringstream out;
  EXPECT_THROW(write_gmsh41(mesh, out), InternalError);
}

TEST(Writers, FailingStreamThrowsOutputError) {
  std::ostringstream out;
  out.setstate(std::ios::badbit);
  EXPECT_THROW(write_vtu(testing::two_cube_mesh(0.1), out), OutputError);
}

}  // namespace
}  // namespace rdmesh
