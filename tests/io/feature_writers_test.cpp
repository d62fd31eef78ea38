// The 1D and 0D levels in the writers: feature edges (curve ids) and corner
// vertices (corner ids) read back through meshio and gmsh; meshes without
// features keep their historical output byte for byte.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "io/io_test_util.h"
#include "io/meshio_util.h"
#include "io/reference_writers.h"
#include "io/test_meshes.h"
#include "rdmesh/errors.h"
#include "rdmesh/mesh_writers.h"

namespace rdmesh {
namespace {

using testing::count_cells;
using testing::expect_same_points;
using testing::labelled;
using testing::read_cells;
using testing::TempDir;

using FeatureWritersTest = testing::MeshioTest;

TetMesh featured_mesh() { return testing::jittered(testing::featured_two_cube_mesh(0.1)); }

/// Corner id of every corner vertex, keyed by the one-vertex cell.
std::map<std::vector<int>, int> corner_cells(const TetMesh& m) {
  std::map<std::vector<int>, int> out;
  for (std::size_t c = 0; c < m.corner_vertices.size(); ++c) {
    out[{m.corner_vertices[c]}] = m.corner_ids[c].value;
  }
  return out;
}

/// Expects `label` to be 0 on every cell of `type`.
void expect_zero(const nlohmann::json& dump, const std::string& type, const std::string& label) {
  for (const auto& [cell, value] : read_cells(dump, type, label)) {
    EXPECT_EQ(value, 0) << type << ' ' << label;
  }
}

TEST_F(FeatureWritersTest, MeditEdgesAndCornersReadBack) {
  const TetMesh mesh = featured_mesh();
  const nlohmann::json dump = write_and_read(mesh, "f.mesh");
  expect_same_points(mesh, dump);
  EXPECT_EQ(read_cells(dump, "tetra", "medit:ref"), labelled(mesh.tets, mesh.tet_subdomain));
  EXPECT_EQ(read_cells(dump, "triangle", "medit:ref"),
            labelled(mesh.triangles, mesh.triangle_patch));
  EXPECT_EQ(read_cells(dump, "line", "medit:ref"), labelled(mesh.edges, mesh.edge_curve));
  EXPECT_EQ(count_cells(dump, "line"), 20u);
  // meshio skips the Corners keyword; the corner ids travel as vertex references.
  std::vector<int> expected_refs(mesh.vertices.size(), 0);
  for (std::size_t c = 0; c < mesh.corner_vertices.size(); ++c) {
    expected_refs[mesh.corner_vertices[c]] = mesh.corner_ids[c].value;
  }
  EXPECT_EQ(dump.at("point_data").at("medit:ref").get<std::vector<int>>(), expected_refs);
}

TEST(FeatureWriters, MeditCornersSection) {
  const TetMesh mesh = testing::featured_two_cube_mesh(0.5);
  std::ostringstream out;
  write_medit(mesh, out);
  const std::string s = out.str();
  // Corner vertices (i, j, k) -> 1-based index 1 + 2i + 3j + 6k, in corner id order.
  EXPECT_NE(s.find("\nCorners\n8\n1\n3\n4\n6\n7\n9\n10\n12\n\nEnd\n"), std::string::npos) << s;
  EXPECT_NE(s.find("\nEdges\n20\n1 2 1\n2 3 1\n"), std::string::npos) << s;
  EXPECT_NE(s.find("Vertices\n12\n0 0 0 1\n0.5 0 0 0\n1 0 0 2\n"), std::string::npos) << s;
}

TEST_F(FeatureWritersTest, VtuLineAndVertexCellsReadBack) {
  const TetMesh mesh = featured_mesh();
  const nlohmann::json dump = write_and_read(mesh, "f.vtu");
  expect_same_points(mesh, dump);
  EXPECT_EQ(read_cells(dump, "tetra", "subdomain"), labelled(mesh.tets, mesh.tet_subdomain));
  EXPECT_EQ(read_cells(dump, "triangle", "patch"), labelled(mesh.triangles, mesh.triangle_patch));
  EXPECT_EQ(read_cells(dump, "line", "curve"), labelled(mesh.edges, mesh.edge_curve));
  EXPECT_EQ(read_cells(dump, "vertex", "corner"), corner_cells(mesh));
  for (const char* type : {"tetra", "triangle", "vertex"}) expect_zero(dump, type, "curve");
  for (const char* type : {"tetra", "triangle", "line"}) expect_zero(dump, type, "corner");
  for (const char* type : {"triangle", "line", "vertex"}) expect_zero(dump, type, "subdomain");
  for (const char* type : {"tetra", "line", "vertex"}) expect_zero(dump, type, "patch");
  EXPECT_EQ(count_cells(dump, "tetra"), 12u);
  EXPECT_EQ(count_cells(dump, "triangle"), 22u);
  EXPECT_EQ(count_cells(dump, "line"), 20u);
  EXPECT_EQ(count_cells(dump, "vertex"), 8u);
}

TEST_F(FeatureWritersTest, GmshCurvesAndPointsReadBack) {
  const TetMesh mesh = featured_mesh();
  const nlohmann::json dump = write_and_read(mesh, "f.msh");
  expect_same_points(mesh, dump);
  for (const char* key : {"gmsh:physical", "gmsh:geometrical"}) {
    EXPECT_EQ(read_cells(dump, "tetra", key), labelled(mesh.tets, mesh.tet_subdomain)) << key;
    EXPECT_EQ(read_cells(dump, "triangle", key), labelled(mesh.triangles, mesh.triangle_patch))
        << key;
    EXPECT_EQ(read_cells(dump, "line", key), labelled(mesh.edges, mesh.edge_curve)) << key;
    EXPECT_EQ(read_cells(dump, "vertex", key), corner_cells(mesh)) << key;
  }
  const auto& names = dump.at("field_data");
  EXPECT_EQ(names.at("left"), nlohmann::json({1, 3}));
  EXPECT_EQ(names.at("interface"), nlohmann::json({3, 2}));
  EXPECT_EQ(names.at("x00"), nlohmann::json({1, 1}));
  EXPECT_EQ(names.at("z11"), nlohmann::json({12, 1}));
  EXPECT_EQ(names.at("rim"), nlohmann::json({13, 1}));
  EXPECT_EQ(names.at("corner_1"), nlohmann::json({1, 0}));
  EXPECT_EQ(names.at("corner_8"), nlohmann::json({8, 0}));
  EXPECT_EQ(names.size(), 5u + 13u + 8u);
}

/// The lines of the $Entities section after its header.
std::vector<std::string> entity_lines(const std::string& msh) {
  const auto begin = msh.find("$Entities\n"), end = msh.find("$EndEntities\n");
  std::istringstream in(msh.substr(begin, end - begin));
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return {lines.begin() + 2, lines.end()};
}

TEST(FeatureWriters, GmshEntityTopology) {
  std::ostringstream out;
  write_gmsh41(testing::featured_two_cube_mesh(0.5), out);
  const std::string msh = out.str();
  EXPECT_NE(msh.find("$Entities\n8 13 3 2\n"), std::string::npos);
  const std::vector<std::string> lines = entity_lines(msh);
  ASSERT_EQ(lines.size(), 8u + 13u + 3u + 2u);
  EXPECT_EQ(lines[0], "1 0 0 0 1 1");  // corner 1 at the origin
  EXPECT_EQ(lines[7], "8 1 0.5 0.5 1 8");
  // Open curves end at their corners (start +, end -); the closed rim has no boundary.
  EXPECT_EQ(lines[8], "1 0 0 0 1 0 0 1 1 2 1 -2");
  EXPECT_EQ(lines[8 + 11], "12 1 0.5 0 1 0.5 0.5 1 12 2 4 -8");
  EXPECT_EQ(lines[8 + 12], "13 0.5 0 0 0.5 0.5 0.5 1 13 0");
  // Surfaces: the curves listing them; the interface is bounded by the rim only.
  EXPECT_EQ(lines[21], "1 0 0 0 0.5 0.5 0.5 1 1 9 1 2 3 4 5 7 9 11 13");
  EXPECT_EQ(lines[23], "3 0.5 0 0 0.5 0.5 0.5 1 3 1 13");
  EXPECT_EQ(lines[24], "1 0 0 0 0.5 0.5 0.5 1 1 2 1 3");
  // Elements: tets and triangles keep tags 1..34, then 20 lines and 8 points.
  EXPECT_NE(msh.find("$Elements\n26 62 1 62\n"), std::string::npos);
  EXPECT_NE(msh.find("\n1 13 1 4\n"), std::string::npos);  // the rim block
  EXPECT_NE(msh.find("\n0 8 15 1\n62 12\n$EndElements\n"), std::string::npos);
}

TEST(FeatureWriters, GmshCheckAcceptsAndCountsEveryDimension) {
  if (!testing::gmsh_available()) RDMESH_MISSING_PREREQUISITE("gmsh");
  TempDir dir;
  const TetMesh mesh = featured_mesh();
  write_mesh(mesh, dir.file("f.msh"));
  write_mesh(mesh, dir.file("f.mesh"));
  const std::string log = testing::expect_gmsh_accepts("-check " + dir.file("f.msh"));
  EXPECT_NE(log.find("26 entities"), std::string::npos) << log;
  EXPECT_NE(log.find("12 nodes"), std::string::npos) << log;
  EXPECT_NE(log.find("62 elements"), std::string::npos) << log;  // 12 + 22 + 20 + 8
  // Medit through gmsh: it reads the Edges (12 + 22 + 20) and ignores Corners.
  const std::string medit_log = testing::expect_gmsh_accepts("-check " + dir.file("f.mesh"));
  EXPECT_NE(medit_log.find("54 elements"), std::string::npos) << medit_log;
  // Re-export by gmsh: element counts per dimension and the physical names survive.
  testing::expect_gmsh_accepts(dir.file("f.msh") + " -0 -format msh41 -o " + dir.file("g.msh"));
  const std::string again = testing::read_text(dir.file("g.msh"));
  for (const char* name : {"\"x00\"", "\"rim\"", "\"corner_8\"", "\"interface\""}) {
    EXPECT_NE(again.find(name), std::string::npos) << name;
  }
  std::size_t per_type[16] = {};
  const auto begin = again.find("$Elements\n");
  std::istringstream in(again.substr(begin + 10));
  std::size_t blocks = 0, total = 0, lo = 0, hi = 0;
  in >> blocks >> total >> lo >> hi;
  for (std::size_t b = 0; b < blocks; ++b) {
    int dim = 0, tag = 0, type = 0;
    std::size_t count = 0;
    in >> dim >> tag >> type >> count;
    ASSERT_TRUE(in && type > 0 && type < 16);
    per_type[type] += count;
    std::string line;
    std::getline(in, line);
    for (std::size_t e = 0; e < count; ++e) std::getline(in, line);
  }
  EXPECT_EQ(total, 62u);
  EXPECT_EQ(per_type[4], 12u);  // tetrahedra
  EXPECT_EQ(per_type[2], 22u);  // triangles
  EXPECT_EQ(per_type[1], 20u);  // lines
  EXPECT_EQ(per_type[15], 8u);  // points
}

TEST(FeatureWriters, FeaturelessOutputIsUnchanged) {
  // The two-cube mesh, and four translated copies of it (longer arrays, so that
  // every line-wrapping rule is exercised).
  TetMesh big;
  const TetMesh one = testing::jittered(testing::two_cube_mesh(0.1));
  big.subdomains = one.subdomains;
  big.patches = one.patches;
  for (int copy = 0; copy < 4; ++copy) {
    const int base = static_cast<int>(big.vertices.size());
    for (const Point3& p : one.vertices) big.vertices.push_back(p + Point3{0, 0.5 * copy, 0});
    for (auto t : one.tets)
      big.tets.push_back({t[0] + base, t[1] + base, t[2] + base, t[3] + base});
    for (auto f : one.triangles) big.triangles.push_back({f[0] + base, f[1] + base, f[2] + base});
    big.tet_subdomain.insert(big.tet_subdomain.end(), one.tet_subdomain.begin(),
                             one.tet_subdomain.end());
    big.triangle_patch.insert(big.triangle_patch.end(), one.triangle_patch.begin(),
                              one.triangle_patch.end());
  }
  for (const TetMesh& mesh : {one, big}) {
    std::ostringstream medit, gmsh, vtu;
    write_medit(mesh, medit);
    write_gmsh41(mesh, gmsh);
    write_vtu(mesh, vtu);
    EXPECT_EQ(medit.str(), testing::reference_medit(mesh));
    EXPECT_EQ(gmsh.str(), testing::reference_gmsh41(mesh));
    EXPECT_EQ(vtu.str(), testing::reference_vtu(mesh));
  }
}

TEST(FeatureWriters, OutputIsDeterministic) {
  const TetMesh mesh = featured_mesh();
  for (auto write : {write_medit, write_gmsh41, write_vtu}) {
    std::ostringstream a, b;
    write(mesh, a);
    write(mesh, b);
    EXPECT_EQ(a.str(), b.str());
  }
}

/// Expects every writer to reject `mesh` with InternalError.
void expect_rejected(const TetMesh& mesh, const char* what) {
  for (auto write : {write_medit, write_gmsh41, write_vtu}) {
    std::ostringstream out;
    EXPECT_THROW(write(mesh, out), InternalError) << what;
  }
}

TEST(FeatureWriters, InconsistentFeaturesAreRejected) {
  const TetMesh good = testing::featured_two_cube_mesh(0.1);
  TetMesh m = good;
  m.edges[3][1] = 12;
  expect_rejected(m, "edge vertex out of range");
  m = good;
  m.edges[0] = {4, 4};
  expect_rejected(m, "degenerate edge");
  m = good;
  m.edge_curve.pop_back();
  expect_rejected(m, "edge_curve too short");
  m = good;
  m.edge_curve[2] = CurveId(0);
  expect_rejected(m, "curve id 0");
  m = good;
  m.corner_vertices[1] = -1;
  expect_rejected(m, "corner vertex out of range");
  m = good;
  m.corner_ids.push_back(CornerId(9));
  expect_rejected(m, "corner_ids too long");
  m = good;
  m.corner_ids[0] = CornerId(-2);
  expect_rejected(m, "negative corner id");
  m = good;
  m.corner_vertices[1] = m.corner_vertices[0];
  expect_rejected(m, "vertex listed twice as a corner");
  m = good;
  m.corner_ids[1] = m.corner_ids[0];
  expect_rejected(m, "corner at two vertices");
}

}  // namespace
}  // namespace rdmesh
