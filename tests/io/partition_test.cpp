// Partitions: METIS on the dual graph of a meshed ball and of two nested
// subdomains, every element in exactly one partition, balance within 3%, the
// edge cut recounted, the lower-dimensional elements on a tetrahedron of
// their partition; Gmsh reads the partitioned .msh, meshio the .vtu's
// partition array.
#include "rdmesh/partition.h"

#include <gtest/gtest.h>

#include <map>
#include <set>

#include "core/capped_cylinder_oracle.h"
#include "core/test_domains.h"
#include "io/meshio_util.h"
#include "io/msh_partitions.h"
#include "rdmesh/errors.h"
#include "rdmesh/mesher.h"
#include "rdmesh/second_order.h"

namespace rdmesh {
namespace {

TetMesh nested_mesh() {
  const ImplicitOracle oracle = test::nested_spheres();
  return generate_mesh(oracle, test::uniform_criteria(0.12)).mesh;
}

std::array<int, 3> sorted_face(std::array<int, 3> f) {
  std::sort(f.begin(), f.end());
  return f;
}

TEST(Partition, EveryTetInOnePartitionBalancedCutCounted) {
  TetMesh mesh = nested_mesh();
  ASSERT_GT(mesh.tets.size(), 3000u);
  for (int parts : {1, 2, 4, 7}) {
    TetMesh m = mesh;
    const PartitionStats s = partition_mesh(m, parts);
    ASSERT_EQ(m.tet_partition.size(), m.tets.size());
    std::vector<std::size_t> count(parts, 0);
    for (int p : m.tet_partition) {
      ASSERT_GE(p, 1);
      ASSERT_LE(p, parts);
      ++count[p - 1];
    }
    EXPECT_EQ(count, s.tets_per_part);
    for (std::size_t c : count) EXPECT_GT(c, 0u) << parts;
    const double average = static_cast<double>(m.tets.size()) / parts;
    const double largest = static_cast<double>(*std::max_element(count.begin(), count.end()));
    EXPECT_DOUBLE_EQ(s.imbalance, largest / average);
    EXPECT_LE(s.imbalance, 1.03) << parts << " parts";
    // The dual graph's edges and the cut, recounted from the faces.
    std::map<std::array<int, 3>, std::vector<int>> faces;
    for (std::size_t t = 0; t < m.tets.size(); ++t) {
      const auto& v = m.tets[t];
      for (int skip = 0; skip < 4; ++skip) {
        std::array<int, 3> f{};
        for (int i = 0, k = 0; i < 4; ++i) {
          if (i != skip) f[k++] = v[i];
        }
        faces[sorted_face(f)].push_back(static_cast<int>(t));
      }
    }
    std::size_t shared = 0, cut = 0;
    for (const auto& [f, tets] : faces) {
      ASSERT_LE(tets.size(), 2u);
      if (tets.size() == 2) {
        ++shared;
        cut += m.tet_partition[tets[0]] != m.tet_partition[tets[1]];
      }
    }
    EXPECT_EQ(s.dual_edges, shared);
    EXPECT_EQ(s.edge_cut, cut);
    if (parts == 1) {
      EXPECT_EQ(cut, 0u);
    } else {
      EXPECT_GT(cut, 0u);
    }
    // Each triangle is a face of a tetrahedron of its partition, the smallest one.
    ASSERT_EQ(m.triangle_partition.size(), m.triangles.size());
    for (std::size_t f = 0; f < m.triangles.size(); ++f) {
      int smallest = parts + 1;
      for (int t : faces.at(sorted_face(m.triangles[f])))
        smallest = std::min(smallest, m.tet_partition[t]);
      EXPECT_EQ(m.triangle_partition[f], smallest);
    }
  }
}

TEST(Partition, DeterministicAndRefusesImpossibleRequests) {
  const TetMesh mesh = nested_mesh();
  TetMesh a = mesh, b = mesh;
  partition_mesh(a, 5);
  partition_mesh(b, 5);
  EXPECT_EQ(a.tet_partition, b.tet_partition);
  EXPECT_EQ(a.triangle_partition, b.triangle_partition);
  TetMesh c = mesh;
  EXPECT_THROW(partition_mesh(c, 0), InputError);
  EXPECT_THROW(partition_mesh(c, static_cast<int>(mesh.tets.size()) + 1), InputError);
  TetMesh surface = mesh;
  surface.tets.clear();
  surface.tet_subdomain.clear();
  EXPECT_THROW(partition_mesh(surface, 2), InputError);
}

TEST(Partition, FeatureEdgesGoToTheSmallestPartitionAroundThem) {
  const test::CappedCylinderOracle oracle(0.5, 0.6);
  TetMesh m = generate_mesh(oracle, test::uniform_criteria(0.15)).mesh;
  ASSERT_FALSE(m.edges.empty());
  partition_mesh(m, 3);
  ASSERT_EQ(m.edge_partition.size(), m.edges.size());
  for (std::size_t e = 0; e < m.edges.size(); ++e) {
    int smallest = 4;
    for (std::size_t t = 0; t < m.tets.size(); ++t) {
      const auto& v = m.tets[t];
      if (std::count(v.begin(), v.end(), m.edges[e][0]) &&
          std::count(v.begin(), v.end(), m.edges[e][1])) {
        smallest = std::min(smallest, m.tet_partition[t]);
      }
    }
    EXPECT_EQ(m.edge_partition[e], smallest) << "edge " << e;
  }
}

// Where features come closer than the minimum size, a feature edge may be no
// tetrahedron's edge (the shared gmsh_part.step does so): it goes to the
// smallest partition around its vertices instead of failing as our bug.
TEST(Partition, AFeatureEdgeOnNoTetrahedronGoesToThePartitionsAroundItsVertices) {
  const test::CappedCylinderOracle oracle(0.5, 0.6);
  TetMesh m = generate_mesh(oracle, test::uniform_criteria(0.15)).mesh;
  ASSERT_FALSE(m.edges.empty());
  // Two vertices sharing no tetrahedron, joined as an edge of the first curve.
  const int a = m.tets.front()[0];
  int b = -1;
  for (std::size_t v = 0; v < m.vertices.size() && b < 0; ++v) {
    bool shared = false;
    for (const auto& t : m.tets) {
      shared |= std::count(t.begin(), t.end(), a) && std::count(t.begin(), t.end(), int(v));
    }
    if (!shared) b = static_cast<int>(v);
  }
  ASSERT_GE(b, 0);
  m.edges.push_back({a, b});
  m.edge_curve.push_back(m.edge_curve.front());
  partition_mesh(m, 3);
  int smallest = 4;
  for (std::size_t t = 0; t < m.tets.size(); ++t) {
    const auto& v = m.tets[t];
    if (std::count(v.begin(), v.end(), a) || std::count(v.begin(), v.end(), b)) {
      smallest = std::min(smallest, m.tet_partition[t]);
    }
  }
  EXPECT_EQ(m.edge_partition.back(), smallest);
}

class PartitionFiles : public testing::MeshioTest {};

TEST_F(PartitionFiles, VtuCarriesThePartitionAndGmshReadsTheMsh) {
  TetMesh mesh = nested_mesh();
  partition_mesh(mesh, 4);
  const nlohmann::json j = write_and_read(mesh, "p.vtu");
  std::vector<int> read;
  for (const auto& block : j["cells"]) {
    if (block["type"] != "tetra") continue;
    for (const auto& v : block["cell_data"]["partition"]) read.push_back(v.get<int>());
  }
  EXPECT_EQ(read, mesh.tet_partition);
  if (!testing::gmsh_available()) RDMESH_MISSING_PREREQUISITE("gmsh");
  write_mesh(mesh, dir_.file("p.msh"));
  const std::string log = testing::expect_gmsh_accepts("-check " + dir_.file("p.msh"));
  EXPECT_NE(log.find(std::to_string(mesh.vertices.size()) + " nodes"), std::string::npos) << log;
  EXPECT_NE(log.find("Info    : 4 partitions"), std::string::npos) << log;
  // The faces between partitions are written, once, on partition-boundary
  // surfaces (with their curves and points), the faces of both subdomains and of their interface.
  const auto entities =
      testing::expect_partition_boundaries(mesh, testing::read_text(dir_.file("p.msh")));
  EXPECT_GT(entities[2], 0u);
  EXPECT_GT(entities[1], 0u);
  // Gmsh saves it again with its partitions.
  testing::expect_gmsh_accepts(dir_.file("p.msh") + " -0 -o " + dir_.file("again.msh"));
  const std::string again = testing::read_text(dir_.file("again.msh"));
  EXPECT_NE(again.find("$PartitionedEntities\n4\n"), std::string::npos);
}

// Second order: the partition-boundary triangles and lines are 6- and 3-node
// elements whose mid nodes are the tetrahedra's mid-edge nodes.
TEST_F(PartitionFiles, SecondOrderBoundariesUseTheTetrahedraMidNodes) {
  const ImplicitOracle oracle = test::nested_spheres();
  TetMesh mesh = generate_mesh(oracle, test::uniform_criteria(0.12)).mesh;
  make_second_order(mesh, oracle);
  partition_mesh(mesh, 4);
  write_mesh(mesh, dir_.file("p2.msh"));
  const std::string text = testing::read_text(dir_.file("p2.msh"));
  const auto entities = testing::expect_partition_boundaries(mesh, text);
  EXPECT_GT(entities[2], 0u);
  std::map<std::pair<int, int>, int> mid;
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    for (std::size_t k = 0; k < kTetEdges.size(); ++k) {
      const int a = mesh.tets[t][kTetEdges[k][0]], b = mesh.tets[t][kTetEdges[k][1]];
      mid[std::minmax(a, b)] = mesh.tet_mid_nodes[t][k];
    }
  }
  std::size_t checked = 0;
  for (const auto& [key, e] : testing::read_msh_partitions(text).entities) {
    if (e.partitions.size() < 2 || e.dim == 0) continue;
    for (const auto& nodes : e.elements) {
      const std::size_t n = e.dim == 2 ? 3 : 2;
      ASSERT_EQ(nodes.size(), e.dim == 2 ? 6u : 3u);
      for (std::size_t i = 0; i < (n == 3 ? 3 : 1); ++i) {
        EXPECT_EQ(nodes[n + i], mid.at(std::minmax(nodes[i], nodes[(i + 1) % n])));
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 0u);
}

}  // namespace
}  // namespace rdmesh
