// Reading our output files back through meshio (python3), shared by the writer tests.
#pragma once

#include <gtest/gtest.h>

#include <array>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "io/io_test_util.h"
#include "rdmesh/mesh_writers.h"
#include "rdmesh/tet_mesh.h"

namespace rdmesh::testing {

/// Dumps what meshio reads from `mesh_file` as JSON: points, point_data, cell
/// blocks with their data, field_data.
inline constexpr const char* kMeshioDump = R"PY(
import json, sys, meshio
m = meshio.read(sys.argv[1])
out = {"points": m.points.tolist(), "cells": [], "field_data": {}, "point_data": {}}
for k, v in m.field_data.items():
    out["field_data"][k] = [int(x) for x in v]
for k, v in m.point_data.items():
    out["point_data"][k] = v.tolist()
for i, c in enumerate(m.cells):
    out["cells"].append({"type": c.type, "data": c.data.tolist(),
                         "cell_data": {k: [int(x) for x in m.cell_data[k][i]] for k in m.cell_data}})
with open(sys.argv[2], "w") as f:
    json.dump(out, f)
)PY";

/// Fixture base: skips without meshio; writes meshes to a temp dir and reads them back.
class MeshioTest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!meshio_available()) RDMESH_MISSING_PREREQUISITE("python3-meshio");
    write_text(dir_.file("dump.py"), kMeshioDump);
  }

  /// Writes `mesh` to `name` in the temp dir and returns what meshio reads.
  nlohmann::json write_and_read(const TetMesh& mesh, const std::string& name) {
    const std::string path = dir_.file(name), json_path = dir_.file(name + ".json");
    write_mesh(mesh, path);
    const auto r = run_command(std::string(kPython) + " " + dir_.file("dump.py") + " " + path +
                               " " + json_path);
    EXPECT_EQ(r.exit_code, 0) << r.output;
    return nlohmann::json::parse(read_text(json_path));
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
inline std::map<std::vector<int>, int> read_cells(const nlohmann::json& dump,
                                                  const std::string& type, const std::string& key) {
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

/// Number of cells of `type` in a meshio dump.
inline std::size_t count_cells(const nlohmann::json& dump, const std::string& type) {
  std::size_t n = 0;
  for (const auto& block : dump.at("cells")) {
    if (block.at("type") == type) n += block.at("data").size();
  }
  return n;
}

inline void expect_same_points(const TetMesh& mesh, const nlohmann::json& dump) {
  const auto& points = dump.at("points");
  ASSERT_EQ(points.size(), mesh.vertices.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Point3 p{points[i][0].get<double>(), points[i][1].get<double>(),
                   points[i][2].get<double>()};
    EXPECT_EQ(p, mesh.vertices[i]) << "vertex " << i << " lost precision";
  }
}

/// Runs `gmsh ARGS` and expects success with no error in its log; returns the log.
inline std::string expect_gmsh_accepts(const std::string& args) {
  const auto r = run_command("gmsh " + args);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output.find("Error"), std::string::npos) << r.output;
  return r.output;
}

}  // namespace rdmesh::testing
