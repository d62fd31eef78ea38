// Partitions of shared STEP parts (several solids, interfaces): every
// tetrahedron in one partition, balance within 3%, a cut far below the
// dual graph's size, the partition-boundary surfaces, curves and points
// written (io/msh_partitions.h), and Gmsh reads the partitioned .msh.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "io/msh_partitions.h"
#include "rdmesh/cad_oracle.h"
#include "rdmesh/mesh_writers.h"
#include "rdmesh/mesher.h"
#include "rdmesh/partition.h"
#include "shared_data.h"

namespace rdmesh {
namespace {

class PartitionCad : public ::testing::TestWithParam<const char*> {};

TEST_P(PartitionCad, BalancedSmallCutGmshReadsIt) {
  const std::string path = test::shared_data(std::string("step/") + GetParam());
  if (path.empty()) RDMESH_MISSING_SHARED_DATA(std::string("step/") + GetParam());
  const auto oracle = load_cad_file(path);
  TetMesh mesh = generate_mesh(*oracle, default_criteria(oracle->bounding_box())).mesh;
  for (int parts : {2, 8}) {
    TetMesh m = mesh;
    const PartitionStats s = partition_mesh(m, parts);
    std::size_t total = 0;
    for (std::size_t n : s.tets_per_part) {
      EXPECT_GT(n, 0u);
      total += n;
    }
    EXPECT_EQ(total, m.tets.size());
    EXPECT_LE(s.imbalance, 1.03) << parts;
    EXPECT_LT(s.edge_cut * 10, s.dual_edges) << parts;
    std::printf("%s: %zu tets, %d parts: edge cut %zu of %zu, imbalance %.3f, %.3f s\n", GetParam(),
                m.tets.size(), parts, s.edge_cut, s.dual_edges, s.imbalance, s.seconds);
    if (parts != 8) continue;
    if (std::system("gmsh --version > /dev/null 2>&1") != 0) RDMESH_MISSING_PREREQUISITE("gmsh");
    // One file per part and process: ctest runs the cases in parallel.
    const std::string file = ::testing::TempDir() + "rdmesh_partition_" +
                             std::to_string(::getpid()) + "_" + std::string(GetParam()) + ".msh";
    write_mesh(m, file);
    std::ifstream written(file);
    std::stringstream text;
    text << written.rdbuf();
    const auto entities = testing::expect_partition_boundaries(m, text.str());
    EXPECT_GT(entities[2], 0u);
    EXPECT_GT(entities[1], 0u);
    EXPECT_GT(entities[0], 0u);
    std::printf("%s: partition boundaries: %zu surfaces, %zu curves, %zu points\n", GetParam(),
                entities[2], entities[1], entities[0]);
    const std::string log_file = file + ".log";
    const int code = std::system(("gmsh -check " + file + " > " + log_file + " 2>&1").c_str());
    std::ifstream in(log_file);
    std::stringstream log;
    log << in.rdbuf();
    EXPECT_EQ(code, 0) << log.str();
    EXPECT_NE(log.str().find("Info    : 8 partitions"), std::string::npos) << log.str();
    EXPECT_EQ(log.str().find("Error"), std::string::npos) << log.str();
    std::remove(file.c_str());
    std::remove(log_file.c_str());
  }
}

// Two solids sharing a face (an interface between subdomains), a housing
// with fillets and holes, and a part whose curves come closer than the
// minimum size (feature edges that are no tetrahedron's edge).
INSTANTIATE_TEST_SUITE_P(Parts, PartitionCad,
                         ::testing::Values("cadquery_red_cube_blue_cylinder.step",
                                           "occtsample_MBBGehauseRohteil.step", "gmsh_part.step"),
                         [](const auto& info) { return test::file_test_name(info.param); });

}  // namespace
}  // namespace rdmesh
