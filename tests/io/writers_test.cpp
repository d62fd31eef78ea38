// Round trips of the three writers through independent readers: meshio
// (coordinates, connectivity with orientation, labels, names) and gmsh -check.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "io/io_test_util.h"
#include "io/test_meshes.h"
#include "rdmesh/errors.h"
#include "rdmesh/mesh_writers.h"

namespace rdmesh {
namespace {

using testing::run_command;
using testing::TempDir;

/// The two-cube mesh with every vertex moved by a small irregular amount, so
/// that coordinates are not short decimals (tests full precision).
TetMesh jittered_mesh() {
  TetMesh m = testing::two_cube_mesh(0.1);
  for (std::size_t i = 0; i < m.vertices.size(); ++i) {
    const double k = static_cast<double>(i) + 1;
    m.vertices[i] =
        m.vertices[i] + 1e-3 * Point3{std::sin(k), std::cos(2 * k), std::sin(3 * k) / 3};
  }
  m.vertices[0].x = -1.0 / 3.0;  // pulls one corner out further, keeps orientation
  return m;
}

/// Dumps what meshio reads from `mesh_file` as JSON: points, cell blocks with
/// their data, field_data.
constexpr const char* kMeshioDump = R"PY(
import json, sys, meshio
m = meshio.read(sys.argv[1])
out = {"points": m.points.tolist(), "cells": [], "field_data": {}}
for k, v in m.field_data.items():
    out["field_data"][k] = [int(x) for x in v]
for i, c in enumerate(m.cells):
    out["cells"].append({"type": c.type, "data": c.data.tolist(),
                         "cell_data": {k: [int(x) for x in m.cell_data[k][i]] for k in m.cell_data}})
with open(sys.argv[2], "w") as f:
    json.dump(out, f)
)PY";

class WritersTest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!testing::meshio_available()) GTEST_SKIP() << "python3-meshio is not installed";
    testing::write_text(dir_.file("dump.py"), kMeshioDump);
  }

  /// Writes `mesh` to `name` in the temp dir and returns what meshio reads.
  nlohmann::json write_and_read(const TetMesh& mesh, const std::string& name) {
    const std::string path = dir_.file(name), json_path = dir_.file(name + ".json");
    write_mesh(mesh, path);
    const auto r = run_command(std::string(testing::kPython) + " " + dir_.file("dump.py") + " " +
                               path + " " + json_path);
    EXPECT_EQ(r.exit_code, 0) << r.output;
    return nlohmann::json::parse(testing::read_text(json_path));
  }

  TempDir dir_;
};

/// Expected label of every element, keyed by its vertex tuple in written order.
template <std::size_t N, class LabelT>
std::map<std::vector<int>, int> labelled(const std::vector<std::array<int, N>>& elements,
                                         const std::vector<LabelT>& labels) {
  std::map<std::vector<int>, int> out;
  for (std::size_t e = 0; e < elements.size(); ++e) {
    out[std::vector<int>(elements[e].begin(), elements[e].end())] = labels[e].value;
  }
  return out;
}

/// Collects the cells of `type` with the labels of `key` from a meshio dump.
std::map<std::vector<int>, int> read_cells(const nlohmann::json& dump, const std::string& type,
                                           const std::string& key) {
  std::map<std::vector<int>, int> out;
  for (const auto& block : dump.at("cells")) {
    if (block.at("type") != type) continue;
    const auto& data = block.at("data");
    const auto& labels = block.at("cell_data").at(key);
    for (std::size_t i = 0; i < data.size(); ++i) {
      EXPECT_TRUE(out.emplace(data[i].get<std::vector<int>>(), labels[i].get<int>()).second)
          << "element written twice: " << data[i];
    }
  }
  return out;
}

void expect_same_points(const TetMesh& mesh, const nlohmann::json& dump) {
  const auto& points = dump.at("points");
  ASSERT_EQ(points.size(), mesh.vertices.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Point3 p{points[i][0].get<double>(), points[i][1].get<double>(),
                   points[i][2].get<double>()};
    EXPECT_EQ(p, mesh.vertices[i]) << "vertex " << i << " lost precision";
  }
}

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

/// Runs `gmsh ARGS` and expects success with no error in its log.
void expect_gmsh_accepts(const std::string& args) {
  const auto r = run_command("gmsh " + args);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output.find("Error"), std::string::npos) << r.output;
}

TEST(GmshCheck, AcceptsOurMshAndMeditFiles) {
  if (!testing::gmsh_available()) GTEST_SKIP() << "gmsh is not installed";
  TempDir dir;
  const TetMesh mesh = jittered_mesh();
  write_mesh(mesh, dir.file("m.msh"));
  write_mesh(mesh, dir.file("m.mesh"));
  expect_gmsh_accepts("-check " + dir.file("m.msh"));
  expect_gmsh_accepts("-check " + dir.file("m.mesh"));
  // Gmsh re-exports the file with the same elements and physical names.
  expect_gmsh_accepts(dir.file("m.msh") + " -0 -o " + dir.file("again.msh"));
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
