// Binary .msh 4.1, compressed binary .vtu and MSH 2.2: read back by meshio and
// Gmsh with the same points, elements, labels and names as the ASCII files;
// the .vtu names as field data; when write_mesh chooses binary.
#include <gtest/gtest.h>

#include <sstream>

#include "io/meshio_util.h"
#include "io/msh_partitions.h"
#include "io/test_meshes.h"
#include "rdmesh/errors.h"
#include "rdmesh/mesh_writers.h"
#include "rdmesh/partition.h"
#include "rdmesh/view_mesh.h"

namespace rdmesh::testing {
namespace {

TetMesh featured_mesh() { return jittered(featured_two_cube_mesh(0.1)); }

class BinaryWriters : public MeshioTest {
 protected:
  /// Writes `mesh` to `name` with `options` and returns what meshio reads.
  nlohmann::json write_and_read_as(const TetMesh& mesh, const std::string& name,
                                   const WriteOptions& options) {
    const std::string path = dir_.file(name), json_path = dir_.file(name + ".json");
    write_mesh(mesh, path, options);
    const auto r = run_command(std::string(kPython) + " " + dir_.file("dump.py") + " " + path +
                               " " + json_path);
    EXPECT_EQ(r.exit_code, 0) << r.output;
    return nlohmann::json::parse(read_text(json_path));
  }
};

WriteOptions binary() { return {Encoding::binary, false}; }
WriteOptions ascii() { return {Encoding::ascii, false}; }

TEST_F(BinaryWriters, BinaryMshReadsBackAsTheAsciiOne) {
  const TetMesh mesh = featured_mesh();
  const nlohmann::json text = write_and_read_as(mesh, "a.msh", ascii());
  const nlohmann::json bin = write_and_read_as(mesh, "b.msh", binary());
  EXPECT_EQ(read_text(dir_.file("b.msh")).substr(0, 21), "$MeshFormat\n4.1 1 8\n\x01");
  EXPECT_EQ(text, bin);
  expect_same_points(mesh, bin);
  EXPECT_EQ(read_cells(bin, "tetra", "gmsh:physical"), labelled(mesh.tets, mesh.tet_subdomain));
  EXPECT_EQ(read_cells(bin, "triangle", "gmsh:physical"),
            labelled(mesh.triangles, mesh.triangle_patch));
  EXPECT_EQ(read_cells(bin, "line", "gmsh:physical"), labelled(mesh.edges, mesh.edge_curve));
  EXPECT_EQ(bin.at("field_data").at("rim"), (nlohmann::json{13, 1}));
}

TEST_F(BinaryWriters, Msh22CarriesTheSameElementsLabelsAndNames) {
  const TetMesh mesh = featured_mesh();
  const nlohmann::json v41 = write_and_read_as(mesh, "a.msh", ascii());
  const nlohmann::json v22 = write_and_read_as(mesh, "c.msh", {Encoding::automatic, true});
  EXPECT_EQ(read_text(dir_.file("c.msh")).substr(0, 20), "$MeshFormat\n2.2 0 8\n");
  expect_same_points(mesh, v22);
  for (const char* type : {"tetra", "triangle", "line", "vertex"}) {
    for (const char* key : {"gmsh:physical", "gmsh:geometrical"}) {
      EXPECT_EQ(read_cells(v22, type, key), read_cells(v41, type, key)) << type << " " << key;
    }
  }
  EXPECT_EQ(v22.at("field_data"), v41.at("field_data"));
}

TEST_F(BinaryWriters, CompressedVtuReadsBackAsTheAsciiOneWithNames) {
  const TetMesh mesh = featured_mesh();
  const nlohmann::json text = write_and_read_as(mesh, "a.vtu", ascii());
  const nlohmann::json bin = write_and_read_as(mesh, "b.vtu", binary());
  const std::string file = read_text(dir_.file("b.vtu"));
  EXPECT_NE(file.find("compressor=\"vtkZLibDataCompressor\""), std::string::npos);
  EXPECT_EQ(file.find("format=\"ascii\">\n"), std::string::npos) << "an array left in text";
  EXPECT_LT(file.size(), read_text(dir_.file("a.vtu")).size());
  EXPECT_EQ(text, bin);
  expect_same_points(mesh, bin);
  EXPECT_EQ(read_cells(bin, "tetra", "subdomain"), labelled(mesh.tets, mesh.tet_subdomain));
  EXPECT_EQ(read_cells(bin, "line", "curve"), labelled(mesh.edges, mesh.edge_curve));
  // The names as field data: name -> [id, dimension].
  const nlohmann::json& names = bin.at("field_data");
  EXPECT_EQ(names.at("rim"), (nlohmann::json{13, 1}));
  EXPECT_EQ(names.at("x00"), (nlohmann::json{1, 1}));
  for (const SubdomainInfo& s : mesh.subdomains) {
    EXPECT_EQ(names.at(s.name), (nlohmann::json{s.id.value, 3})) << s.name;
  }
  for (const PatchInfo& p : mesh.patches) {
    EXPECT_EQ(names.at(p.name), (nlohmann::json{p.id.value, 2})) << p.name;
  }
  // rdmesh view reads it too.
  const view::ViewMesh seen = view::read_view_mesh(dir_.file("b.vtu"));
  EXPECT_EQ(seen.tets.size(), mesh.tets.size());
  EXPECT_EQ(seen.triangles.size(), mesh.triangles.size());
}

TEST(BinaryWritersGmsh, GmshReadsBinaryAndMsh22LikeTheAsciiFile) {
  if (!gmsh_available()) RDMESH_MISSING_PREREQUISITE("gmsh");
  TempDir dir;
  const TetMesh mesh = featured_mesh();
  write_mesh(mesh, dir.file("a.msh"), ascii());
  write_mesh(mesh, dir.file("b.msh"), binary());
  write_mesh(mesh, dir.file("c.msh"), {Encoding::ascii, true});
  const std::string a = expect_gmsh_accepts("-check " + dir.file("a.msh"));
  EXPECT_NE(a.find("62 elements"), std::string::npos) << a;
  for (const char* other : {"b.msh", "c.msh"}) {
    const std::string log = expect_gmsh_accepts("-check " + dir.file(other));
    EXPECT_NE(log.find("62 elements"), std::string::npos) << other << "\n" << log;
    EXPECT_NE(log.find("12 nodes"), std::string::npos) << other << "\n" << log;
  }
  // Gmsh's re-export of the binary file keeps the physical names.
  expect_gmsh_accepts(dir.file("b.msh") + " -0 -format msh41 -o " + dir.file("again.msh"));
  const std::string again = read_text(dir.file("again.msh"));
  for (const char* name : {"\"x00\"", "\"rim\"", "\"corner_8\"", "\"interface\""}) {
    EXPECT_NE(again.find(name), std::string::npos) << name;
  }
}

TEST_F(BinaryWriters, PartitionedMeshesTooInMeshioAndGmsh) {
  TetMesh mesh = featured_mesh();
  partition_mesh(mesh, 2);
  const nlohmann::json text = write_and_read_as(mesh, "p.vtu", ascii());
  const nlohmann::json bin = write_and_read_as(mesh, "q.vtu", binary());
  EXPECT_EQ(text, bin);
  EXPECT_EQ(read_cells(bin, "tetra", "partition").size(), mesh.tets.size());
  if (!gmsh_available()) RDMESH_MISSING_PREREQUISITE("gmsh");
  write_mesh(mesh, dir_.file("p.msh"), ascii());
  write_mesh(mesh, dir_.file("q.msh"), binary());
  // 62 model elements and the partition boundaries' elements (here points
  // where the pieces of a curve in two partitions meet).
  const std::string text_msh = read_text(dir_.file("p.msh"));
  const auto boundaries = expect_partition_boundaries(mesh, text_msh);
  EXPECT_GT(boundaries[0] + boundaries[1] + boundaries[2], 0u);
  std::size_t elements = 0;
  for (const auto& [key, e] : read_msh_partitions(text_msh).entities) elements += e.elements.size();
  EXPECT_GT(elements, 62u);
  std::string saved[2];
  for (const char* name : {"p.msh", "q.msh"}) {
    const std::string log = expect_gmsh_accepts("-check " + dir_.file(name));
    EXPECT_NE(log.find("2 partitions"), std::string::npos) << name << "\n" << log;
    EXPECT_NE(log.find(" " + std::to_string(elements) + " elements"), std::string::npos)
        << name << "\n"
        << log;
    EXPECT_NE(log.find("12 nodes"), std::string::npos) << name << "\n" << log;
    // Gmsh saves the binary file as it saves the ASCII one.
    expect_gmsh_accepts(dir_.file(name) + " -0 -format msh41 -o " + dir_.file("again.msh"));
    saved[name[0] == 'q'] = read_text(dir_.file("again.msh"));
  }
  EXPECT_EQ(saved[0], saved[1]);
}

TEST(BinaryWritersChoice, BinaryAboveTheDocumentedSizeOrWhenAsked) {
  const TetMesh small = featured_mesh();
  EXPECT_FALSE(writes_binary(small, MeshFormat::Gmsh41, {}));
  EXPECT_FALSE(writes_binary(small, MeshFormat::Vtu, {}));
  EXPECT_TRUE(writes_binary(small, MeshFormat::Gmsh41, binary()));
  EXPECT_TRUE(writes_binary(small, MeshFormat::Vtu, binary()));
  TetMesh big;
  big.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  big.tets.assign(kBinaryAboveElements + 1, {0, 1, 2, 3});
  big.tet_subdomain.assign(big.tets.size(), SubdomainId(1));
  EXPECT_TRUE(writes_binary(big, MeshFormat::Gmsh41, {}));
  EXPECT_TRUE(writes_binary(big, MeshFormat::Vtu, {}));
  EXPECT_FALSE(writes_binary(big, MeshFormat::Vtu, ascii()));
  EXPECT_FALSE(writes_binary(big, MeshFormat::Medit, {}));
  EXPECT_FALSE(writes_binary(big, MeshFormat::Gmsh41, {Encoding::automatic, true}));
  EXPECT_THROW(writes_binary(small, MeshFormat::Medit, binary()), InputError);
  EXPECT_THROW(writes_binary(small, MeshFormat::Gmsh41, {Encoding::binary, true}), InputError);
  EXPECT_THROW(writes_binary(small, MeshFormat::Vtu, {Encoding::automatic, true}), InputError);
}

TEST(BinaryWritersChoice, BinaryFilesAreDeterministic) {
  const TetMesh mesh = featured_mesh();
  for (auto write : {write_gmsh41_binary, write_vtu_binary, write_gmsh22}) {
    std::ostringstream a, b;
    write(mesh, a);
    write(mesh, b);
    EXPECT_EQ(a.str(), b.str());
    EXPECT_GT(a.str().size(), 500u);
  }
}

}  // namespace
}  // namespace rdmesh::testing
