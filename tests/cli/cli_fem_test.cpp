// FEM options on the command line: --order 2 writes quadratic elements in
// every format, reports them, gives the same bytes twice; --partitions writes
// partitioned entities and reports the cut and balance; bad values are input
// errors.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "cli_runner.h"
#include "io/msh_partitions.h"
#include "shared_data.h"

namespace rdmesh::test {
namespace {

TEST(CliFem, OrderTwoWritesQuadraticElementsAndReportsThem) {
  ScratchDir dir;
  const std::string sample = "'" + source_path("samples/capped_cylinder.json") + "'";
  const CliRun run = run_cli(sample + " -o p2.msh --order 2 --report r.json", dir.path());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("second order: "), std::string::npos) << run.output;
  const nlohmann::json r = nlohmann::json::parse(read_file(dir.file("r.json")));
  const auto& s = r.at("second_order");
  EXPECT_GT(s.at("curve_nodes").get<int>(), 0);    // the rims
  EXPECT_GT(s.at("surface_nodes").get<int>(), 0);  // side and caps
  EXPECT_EQ(s.at("placement_failures").get<int>(), 0);
  EXPECT_GT(s.at("min_scaled_jacobian").get<double>(), 0.05);
  const std::string msh = read_file(dir.file("p2.msh"));
  // Element blocks "dim tag type count": 10-node tets, 6-node triangles, 3-node lines.
  EXPECT_NE(msh.find("\n3 1 11 " + std::to_string(r.at("tets").get<int>()) + "\n"),
            std::string::npos);
  EXPECT_NE(msh.find("\n2 1 9 "), std::string::npos);
  EXPECT_NE(msh.find("\n1 1 8 "), std::string::npos);

  for (const char* name : {"p2.vtu", "p2.mesh"}) {
    const CliRun again = run_cli(sample + " -q --order 2 -o " + name, dir.path());
    ASSERT_EQ(again.exit_code, 0) << again.output;
  }
  EXPECT_NE(read_file(dir.file("p2.vtu")).find("24 24 24"), std::string::npos);
  EXPECT_NE(read_file(dir.file("p2.mesh")).find("\nTetrahedraP2\n"), std::string::npos);
  const CliRun same = run_cli(sample + " -q --order 2 -o same.msh", dir.path());
  ASSERT_EQ(same.exit_code, 0) << same.output;
  EXPECT_EQ(read_file(dir.file("same.msh")), msh);
}

TEST(CliFem, FirstOrderReportsNoSecondOrder) {
  ScratchDir dir;
  const std::string sample = "'" + source_path("samples/sphere.json") + "'";
  const CliRun run = run_cli(sample + " -q --size 0.4 -o p1.msh --report r.json", dir.path());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_TRUE(nlohmann::json::parse(read_file(dir.file("r.json"))).at("second_order").is_null());
  const std::string msh = read_file(dir.file("p1.msh"));
  EXPECT_NE(msh.find("\n3 1 4 "), std::string::npos);
  EXPECT_EQ(msh.find("\n3 1 11 "), std::string::npos);
}

TEST(CliFem, BadOrderIsAnInputError) {
  ScratchDir dir;
  const std::string sample = "'" + source_path("samples/sphere.json") + "'";
  for (const char* bad : {"3", "0", "x"}) {
    const CliRun run = run_cli(sample + " --order " + bad + " -o out.msh", dir.path());
    EXPECT_EQ(run.exit_code, 2) << run.output;
    EXPECT_EQ(run.output.rfind("rdmesh: error: ", 0), 0u) << run.output;
    EXPECT_EQ(std::count(run.output.begin(), run.output.end(), '\n'), 1) << run.output;
    EXPECT_FALSE(std::filesystem::exists(dir.file("out.msh")));
  }
}

TEST(CliFem, PartitionsAreWrittenAndReported) {
  ScratchDir dir;
  const std::string sample = "'" + source_path("samples/nested_spheres.json") + "'";
  const CliRun run =
      run_cli(sample + " -o p.msh --partitions 3 --order 2 --report r.json", dir.path());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("partitions: 3 (METIS), edge cut "), std::string::npos) << run.output;
  const nlohmann::json r = nlohmann::json::parse(read_file(dir.file("r.json")));
  const auto& p = r.at("partitions");
  EXPECT_EQ(p.at("parts").get<int>(), 3);
  EXPECT_LE(p.at("imbalance").get<double>(), 1.03);
  EXPECT_GT(p.at("edge_cut").get<int>(), 0);
  EXPECT_LT(p.at("edge_cut").get<int>(), p.at("dual_edges").get<int>() / 5);
  std::size_t total = 0;
  for (const auto& n : p.at("tets_per_part")) total += n.get<std::size_t>();
  EXPECT_EQ(total, r.at("tets").get<std::size_t>());
  const std::string msh = read_file(dir.file("p.msh"));
  EXPECT_NE(msh.find("$PartitionedEntities\n3\n0\n"), std::string::npos);
  // The faces between partitions are 6-node triangles of partition-boundary surfaces.
  std::size_t boundary_faces = 0;
  for (const auto& [key, e] : testing::read_msh_partitions(msh).entities) {
    if (e.dim != 2 || e.partitions.size() < 2) continue;
    for (const auto& nodes : e.elements) {
      ++boundary_faces;
      EXPECT_EQ(std::set<int>(nodes.begin(), nodes.end()).size(), 6u);
    }
  }
  EXPECT_GT(boundary_faces, 0u);
  EXPECT_LE(boundary_faces, p.at("edge_cut").get<std::size_t>());
  EXPECT_FALSE(r.at("second_order").is_null());
  const CliRun vtu = run_cli(sample + " -q -o p.vtu --partitions 3", dir.path());
  ASSERT_EQ(vtu.exit_code, 0) << vtu.output;
  EXPECT_NE(read_file(dir.file("p.vtu")).find("Name=\"partition\""), std::string::npos);
}

TEST(CliFem, ImpossiblePartitionsAreInputErrorsBeforeMeshing) {
  ScratchDir dir;
  const std::string sample = "'" + source_path("samples/sphere.json") + "'";
  for (const std::string args :
       {"--partitions 2 -o out.mesh", "--partitions 0 -o out.msh",
        "--partitions 2 --surface-only -o out.msh", "--partitions 100000 --size 0.5 -o out.msh",
        "--partitions 2 --format msh22 -o out.msh"}) {
    const CliRun run = run_cli(sample + " " + args, dir.path());
    EXPECT_EQ(run.exit_code, 2) << args << ": " << run.output;
    EXPECT_EQ(run.output.rfind("rdmesh: error: ", 0), 0u) << run.output;
    EXPECT_EQ(std::count(run.output.begin(), run.output.end(), '\n'), 1) << run.output;
    EXPECT_EQ(dir.entries(), 0u) << args;
  }
  // MSH 2.2 was written without its partitions, silently.
  const CliRun msh22 = run_cli(sample + " --partitions 2 --format msh22 -o out.msh", dir.path());
  EXPECT_NE(msh22.output.find("out.msh: rdmesh writes no partitions (--partitions) in MSH 2.2"),
            std::string::npos)
      << msh22.output;
}

TEST(CliFem, EntitySizesFromOptionsAndFileAreReported) {
  ScratchDir dir;
  const std::string sample = "'" + source_path("samples/capped_cylinder.json") + "'";
  const CliRun base = run_cli(sample + " -q -o base.msh --report base.json", dir.path());
  ASSERT_EQ(base.exit_code, 0) << base.output;
  dir.write("sizes.json", R"({"curve:1": 0.03, "grade": 1.3})");
  const CliRun run = run_cli(
      sample + " -o s.msh --report r.json --size-on face:2=0.04 --sizes sizes.json", dir.path());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("size on face:2: asked 0.04, edges mean "), std::string::npos)
      << run.output;
  const nlohmann::json r = nlohmann::json::parse(read_file(dir.file("r.json")));
  const auto& sizes = r.at("entity_sizes");
  ASSERT_EQ(sizes.size(), 2u);
  EXPECT_EQ(sizes[0].at("entity"), "face:2");
  EXPECT_EQ(sizes[1].at("entity"), "curve:1");
  EXPECT_EQ(sizes[1].at("requested").get<double>(), 0.03);
  EXPECT_LE(sizes[0].at("mean_edge").get<double>(), 2 * 0.04);
  EXPECT_LE(sizes[1].at("max_edge").get<double>(), 2 * 0.03);
  EXPECT_GT(r.at("tets").get<int>(),
            nlohmann::json::parse(read_file(dir.file("base.json"))).at("tets").get<int>());
  EXPECT_TRUE(nlohmann::json::parse(read_file(dir.file("base.json"))).at("entity_sizes").is_null());
}

TEST(CliFem, BadEntitySizesAreInputErrors) {
  ScratchDir dir;
  const std::string sample = "'" + source_path("samples/capped_cylinder.json") + "'";
  dir.write("bad.json", R"({"face:1": "small"})");
  dir.write("notjson.json", "{face");
  for (const std::string args :
       {"--size-on face:99=0.1", "--size-on face:1=-2", "--size-on wall:1=0.1",
        "--size-on face:1=0.1 --grade 1", "--sizes bad.json", "--sizes notjson.json",
        "--sizes missing.json"}) {
    const CliRun run = run_cli(sample + " " + args + " -o out.msh", dir.path());
    EXPECT_EQ(run.exit_code, 2) << args << ": " << run.output;
    EXPECT_EQ(run.output.rfind("rdmesh: error: ", 0), 0u) << run.output;
    EXPECT_EQ(std::count(run.output.begin(), run.output.end(), '\n'), 1) << run.output;
    EXPECT_FALSE(std::filesystem::exists(dir.file("out.msh"))) << args;
  }
}

TEST(CliFem, DomainFileSizesWithCurvature) {
  ScratchDir dir;
  // Torus R = 1, r = 0.3: largest principal curvature 1 / 0.3 everywhere.
  dir.write("torus.json", R"({
    "bbox": [-1.5, -1.5, -0.5, 1.5, 1.5, 0.5],
    "functions": {"torus": "(sqrt(x^2 + y^2) - 1)^2 + z^2 - 0.09"},
    "size": 0.3,
    "sizes": {"patch:1": 0.25, "curvature": 12, "grade": 1.3}
  })");
  const CliRun run = run_cli("torus.json -o t.msh --report r.json", dir.path());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const nlohmann::json r = nlohmann::json::parse(read_file(dir.file("r.json")));
  const auto& c = r.at("curvature_sizes");
  EXPECT_EQ(c.at("per_turn").get<double>(), 12);
  EXPECT_NEAR(c.at("min_radius").get<double>(), 0.3, 0.015);
  EXPECT_EQ(c.at("clamped_to_min_size").get<int>(), 0);
  EXPECT_EQ(c.at("unknown").get<int>(), 0);
  EXPECT_GT(c.at("facets").get<int>(), 100);
  EXPECT_LE(c.at("facet_max_ratio").get<double>(), 1.05);  // no curves: no protecting balls
  EXPECT_EQ(r.at("entity_sizes").at(0).at("entity"), "patch:1");
  // The minor circle (radius 0.3) has at least 12 edges per turn: the
  // boundary has about 2 pi R / (2 pi r / 12) x 12 triangles or more.
  EXPECT_GT(r.at("triangles").get<int>(), 2 * 12 * 12 * 1 / 0.3);
  // The command line overrides the file's curvature.
  const CliRun six = run_cli("torus.json -o t6.msh --report r6.json --curvature 6", dir.path());
  ASSERT_EQ(six.exit_code, 0) << six.output;
  const nlohmann::json r6 = nlohmann::json::parse(read_file(dir.file("r6.json")));
  EXPECT_EQ(r6.at("curvature_sizes").at("per_turn").get<double>(), 6);
  EXPECT_LT(r6.at("triangles").get<int>(), r.at("triangles").get<int>());
}

TEST(CliFem, TriangleMeshCurvature) {
  const std::string mesh = test::shared_data("mesh/cgal_pinion.off");
  if (mesh.empty()) RDMESH_MISSING_SHARED_DATA("mesh/cgal_pinion.off");
  ScratchDir dir;
  const CliRun base = run_cli("'" + mesh + "' -q -o a.msh --report a.json", dir.path());
  ASSERT_EQ(base.exit_code, 0) << base.output;
  const CliRun run =
      run_cli("'" + mesh + "' -q -o b.msh --report b.json --curvature 3", dir.path());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const nlohmann::json a = nlohmann::json::parse(read_file(dir.file("a.json")));
  const nlohmann::json b = nlohmann::json::parse(read_file(dir.file("b.json")));
  const auto& c = b.at("curvature_sizes");
  EXPECT_GT(c.at("samples").get<int>(), 0);
  EXPECT_EQ(c.at("unknown").get<int>(), 0);
  EXPECT_GT(c.at("min_radius").get<double>(), 0);
  EXPECT_GT(b.at("triangles").get<int>(), a.at("triangles").get<int>());
  EXPECT_LT(c.at("facet_mean_ratio").get<double>(), 1.0);
}

TEST(CliFem, BadCurvatureIsAnInputError) {
  ScratchDir dir;
  const std::string sample = "'" + source_path("samples/capped_cylinder.json") + "'";
  dir.write("zero.json", R"({"curvature": 0})");
  dir.write("d.json", R"({"bbox": [-1, -1, -1, 1, 1, 1], "functions": {"s": "x^2+y^2+z^2-0.25"},
                          "sizes": {"bogus": 1}})");
  dir.write("d9.json", R"({"bbox": [-1, -1, -1, 1, 1, 1], "functions": {"s": "x^2+y^2+z^2-0.25"},
                           "sizes": {"patch:9": 0.1}})");
  dir.write("face9.json", R"({"face:9": 0.1})");
  for (const std::string& args :
       {sample + " --curvature 0", sample + " --curvature x", sample + " --sizes zero.json",
        std::string("d.json"), std::string("d9.json"), sample + " --sizes face9.json"}) {
    const CliRun run = run_cli(args + " -o out.msh", dir.path());
    EXPECT_EQ(run.exit_code, 2) << args << ": " << run.output;
    EXPECT_EQ(run.output.rfind("rdmesh: error: ", 0), 0u) << run.output;
    EXPECT_FALSE(std::filesystem::exists(dir.file("out.msh"))) << args;
    if (args == "d9.json") {
      EXPECT_NE(run.output.find("'sizes': patch:9"), std::string::npos) << run.output;
    }
    if (args.find("face9.json") != std::string::npos) {
      EXPECT_NE(run.output.find("face9.json: face:9"), std::string::npos) << run.output;
    }
  }
}

}  // namespace
}  // namespace rdmesh::test
