// Mesh readers: our writers' files read back exactly, other tools' files
// (Gmsh, meshio) read, malformed files rejected with InputError and never a
// crash or a huge allocation.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "io/io_test_util.h"
#include "io/test_meshes.h"
#include "rdmesh/errors.h"
#include "rdmesh/mesh_writers.h"
#include "rdmesh/view_conversion.h"
#include "rdmesh/view_mesh.h"
#include "shared_data.h"

namespace rdmesh::view::testing {
namespace {

using rdmesh::testing::TempDir;

using Parser = std::function<ViewMesh(const std::string&, const std::string&)>;

struct Format {
  const char* extension;
  void (*write)(const TetMesh&, std::ostream&);
  Parser parse;
};

const Format kFormats[] = {{".mesh", write_medit, parse_medit},
                           {".msh", write_gmsh41, parse_gmsh},
                           {".vtu", write_vtu, parse_vtu}};

std::string written(const TetMesh& mesh, const Format& f) {
  std::ostringstream out;
  f.write(mesh, out);
  return out.str();
}

/// Elements with their labels, sorted: files may group elements by label.
template <std::size_t N>
std::vector<std::pair<std::array<int, N>, int>> labelled(
    const std::vector<std::array<int, N>>& elements, const std::vector<int>& labels) {
  std::vector<std::pair<std::array<int, N>, int>> out;
  for (std::size_t i = 0; i < elements.size(); ++i) out.emplace_back(elements[i], labels.at(i));
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<int> sorted(std::vector<int> v) {
  std::sort(v.begin(), v.end());
  return v;
}

void expect_same_mesh(const ViewMesh& got, const ViewMesh& want, const std::string& what) {
  EXPECT_EQ(got.points, want.points) << what;
  EXPECT_EQ(labelled(got.tets, got.tet_labels), labelled(want.tets, want.tet_labels)) << what;
  EXPECT_EQ(labelled(got.triangles, got.triangle_labels),
            labelled(want.triangles, want.triangle_labels))
      << what;
  EXPECT_EQ(labelled(got.edges, got.edge_labels), labelled(want.edges, want.edge_labels)) << what;
  EXPECT_EQ(sorted(got.corners), sorted(want.corners)) << what;
  EXPECT_EQ(got.skipped_elements, 0u) << what;
}

TEST(Readers, ReadBackWhatOurWritersWrite) {
  const TetMesh mesh = rdmesh::testing::jittered(rdmesh::testing::featured_two_cube_mesh());
  const ViewMesh want = to_view_mesh(mesh);
  ASSERT_FALSE(want.edges.empty());
  ASSERT_FALSE(want.corners.empty());
  TempDir dir;
  for (const Format& f : kFormats) {
    const std::string path = dir.file(std::string("mesh") + f.extension);
    write_mesh(mesh, path);
    const ViewMesh got = read_view_mesh(path);
    expect_same_mesh(got, want, f.extension);
    if (std::string(f.extension) == ".msh") {
      EXPECT_EQ(got.subdomain_names, want.subdomain_names);
    }
  }
}

TEST(Readers, ReadGmshOwnMeshesInBothVersions) {
  if (!rdmesh::testing::gmsh_available()) RDMESH_MISSING_PREREQUISITE("gmsh");
  TempDir dir;
  rdmesh::testing::write_text(
      dir.file("two.geo"),
      "SetFactory(\"OpenCASCADE\");\n"
      "Box(1) = {0,0,0, 1,1,1};\nSphere(2) = {0.5,0.5,0.5, 0.3};\n"
      "BooleanFragments{ Volume{1}; Delete; }{ Volume{2}; Delete; }\n"
      "Physical Volume(\"box\", 11) = {3};\nPhysical Volume(\"ball\", 12) = {2};\n"
      "Physical Surface(21) = {1:7};\nMesh.MeshSizeMax = 0.35;\n");
  for (const char* version : {"msh41", "msh22"}) {
    const std::string out = dir.file(std::string(version) + ".msh");
    const auto run = rdmesh::testing::run_command("gmsh -3 -format " + std::string(version) + " '" +
                                                  dir.file("two.geo") + "' -o '" + out + "'");
    ASSERT_EQ(run.exit_code, 0) << run.output;
  }
  const ViewMesh v41 = read_view_mesh(dir.file("msh41.msh"));
  const ViewMesh v22 = read_view_mesh(dir.file("msh22.msh"));
  EXPECT_GT(v41.tets.size(), 100u);
  EXPECT_GT(v41.triangles.size(), 50u);
  EXPECT_EQ(sorted(std::vector<int>(v41.tet_labels)).front(), 11);
  EXPECT_EQ(sorted(std::vector<int>(v41.tet_labels)).back(), 12);
  EXPECT_EQ(v41.subdomain_names.at(11), "box");
  EXPECT_EQ(v41.subdomain_names.at(12), "ball");
  // Both versions describe the same mesh with the same node numbering.
  expect_same_mesh(v22, v41, "msh22 vs msh41");
}

TEST(Readers, ReadMeshioVtuInItsEncodings) {
  if (!rdmesh::testing::meshio_available()) RDMESH_MISSING_PREREQUISITE("meshio");
  const TetMesh mesh = rdmesh::testing::jittered(rdmesh::testing::featured_two_cube_mesh());
  TempDir dir;
  write_mesh(mesh, dir.file("ours.vtu"));
  const std::string script =
      "import meshio, sys\n"
      "m = meshio.read(sys.argv[1])\n"
      "meshio.write(sys.argv[2], m, binary=True)\n"                    // base64 + zlib
      "meshio.write(sys.argv[3], m, binary=True, compression=None)\n"  // base64
      "meshio.write(sys.argv[4], m, binary=False)\n";
  rdmesh::testing::write_text(dir.file("convert.py"), script);
  const auto run = rdmesh::testing::run_command(
      std::string(rdmesh::testing::kPython) + " '" + dir.file("convert.py") + "' '" +
      dir.file("ours.vtu") + "' '" + dir.file("zlib.vtu") + "' '" + dir.file("raw.vtu") + "' '" +
      dir.file("ascii.vtu") + "'");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const ViewMesh want = to_view_mesh(mesh);
  for (const char* name : {"zlib.vtu", "raw.vtu"})
    expect_same_mesh(read_view_mesh(dir.file(name)), want, name);
  // meshio's ascii output rounds coordinates: compare them with a tolerance.
  ViewMesh ascii = read_view_mesh(dir.file("ascii.vtu"));
  ASSERT_EQ(ascii.points.size(), want.points.size());
  for (std::size_t i = 0; i < want.points.size(); ++i) {
    EXPECT_LT(distance(ascii.points[i], want.points[i]), 1e-12) << i;
  }
  ascii.points = want.points;
  expect_same_mesh(ascii, want, "ascii.vtu");
  EXPECT_NE(rdmesh::testing::read_text(dir.file("zlib.vtu")).find("vtkZLibDataCompressor"),
            std::string::npos);
}

/// Little-endian bytes of `values` of type T.
template <class T>
std::string raw_bytes(const std::vector<T>& values) {
  std::string s(values.size() * sizeof(T), '\0');
  std::memcpy(s.data(), values.data(), s.size());
  return s;
}

TEST(Readers, ReadAppendedRawVtu) {
  // One tetrahedron and one of its faces, as VTK writes by default: appended
  // raw data, each array a UInt64 byte count followed by its bytes.
  const std::vector<std::string> arrays = {
      raw_bytes(std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1}),
      raw_bytes(std::vector<std::int64_t>{0, 1, 2, 3, 0, 2, 1}),
      raw_bytes(std::vector<std::int64_t>{4, 7}),
      raw_bytes(std::vector<std::uint8_t>{10, 5}),
      raw_bytes(std::vector<std::int32_t>{3, 0}),
      raw_bytes(std::vector<std::int32_t>{0, 9})};
  const char* names[] = {"Points", "connectivity", "offsets", "types", "subdomain", "patch"};
  const char* types[] = {"Float64", "Int64", "Int64", "UInt8", "Int32", "Int32"};
  std::string data, xml[6];
  for (int i = 0; i < 6; ++i) {
    xml[i] = std::string("<DataArray type=\"") + types[i] + "\" Name=\"" + names[i] + "\"" +
             (i == 0 ? " NumberOfComponents=\"3\"" : "") + " format=\"appended\" offset=\"" +
             std::to_string(data.size()) + "\"/>\n";
    data += raw_bytes(std::vector<std::uint64_t>{arrays[i].size()}) + arrays[i];
  }
  const std::string text =
      "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" "
      "byte_order=\"LittleEndian\" header_type=\"UInt64\">\n<UnstructuredGrid>\n"
      "<Piece NumberOfPoints=\"4\" NumberOfCells=\"2\">\n<Points>\n" +
      xml[0] + "</Points>\n<Cells>\n" + xml[1] + xml[2] + xml[3] + "</Cells>\n<CellData>\n" +
      xml[4] + xml[5] +
      "</CellData>\n</Piece>\n</UnstructuredGrid>\n<AppendedData encoding=\"raw\">\n_" + data +
      "\n</AppendedData>\n</VTKFile>\n";
  const ViewMesh m = parse_vtu(text, "appended.vtu");
  ASSERT_EQ(m.points.size(), 4u);
  EXPECT_EQ(m.points[3].z, 1.0);
  ASSERT_EQ(m.tets.size(), 1u);
  EXPECT_EQ(m.tets[0], (std::array<int, 4>{0, 1, 2, 3}));
  EXPECT_EQ(m.tet_labels[0], 3);
  ASSERT_EQ(m.triangles.size(), 1u);
  EXPECT_EQ(m.triangles[0], (std::array<int, 3>{0, 2, 1}));
  EXPECT_EQ(m.triangle_labels[0], 9);
  // The same with a byte count claiming more than the file holds.
  std::string lying = text;
  const std::size_t at = lying.find("\n_") + 2;
  lying[at + 7] = '\x7f';
  EXPECT_THROW(parse_vtu(lying, "lying.vtu"), InputError);
}

/// Calls `parse` and requires either a mesh that passes check_view_mesh or an InputError.
void expect_clean(const Parser& parse, const std::string& text, const std::string& what) {
  try {
    const ViewMesh m = parse(text, "bad");
    check_view_mesh(m, "bad");
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("bad", 0), 0u)
        << "message does not name the file: " << e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << what << ": " << e.what();
  }
}

TEST(Readers, TruncatedFilesAreRejectedCleanly) {
  const TetMesh mesh = rdmesh::testing::featured_two_cube_mesh();
  for (const Format& f : kFormats) {
    const std::string text = written(mesh, f);
    for (std::size_t cut = 0; cut < text.size();
         cut += std::max<std::size_t>(1, text.size() / 97)) {
      expect_clean(f.parse, text.substr(0, cut),
                   std::string(f.extension) + " cut at " + std::to_string(cut));
    }
  }
}

TEST(Readers, MutatedFilesAreRejectedCleanly) {
  const TetMesh mesh = rdmesh::testing::featured_two_cube_mesh();
  const char alphabet[] = "0123456789-+.eE \n\t$<>\"_=/xX#\x01\xff";
  std::uint64_t state = 7;
  auto next = [&state](std::uint64_t n) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return (state >> 33) % n;
  };
  for (const Format& f : kFormats) {
    const std::string text = written(mesh, f);
    for (int trial = 0; trial < 400; ++trial) {
      std::string mutated = text;
      for (int k = 0; k < 1 + trial % 3; ++k)
        mutated[next(mutated.size())] = alphabet[next(sizeof alphabet - 1)];
      expect_clean(f.parse, mutated, std::string(f.extension) + " trial " + std::to_string(trial));
    }
  }
}

struct BadFile {
  const char* name;
  Parser parse;
  std::string text;
  const char* expected;  ///< substring of the message
};

void PrintTo(const BadFile& c, std::ostream* os) { *os << c.name; }

class ReadersReject : public ::testing::TestWithParam<BadFile> {};

TEST_P(ReadersReject, WithAMessageNamingTheProblem) {
  const BadFile& c = GetParam();
  try {
    check_view_mesh(c.parse(c.text, "bad.file"), "bad.file");
    FAIL() << "accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind("bad.file: ", 0), 0u) << what;
    EXPECT_NE(what.find(c.expected), std::string::npos) << what;
  }
}

const std::string kMshHead = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
const std::string kVtuHead =
    "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" header_type=\"UInt64\"><UnstructuredGrid>";

const BadFile kBadFiles[] = {
    BadFile{"msh_binary", parse_gmsh,
            std::string("$MeshFormat\n4.1 1 8\n\1\0\0\0\n$EndMeshFormat\n", 40), "binary"},
    BadFile{"msh_version", parse_gmsh, "$MeshFormat\n3.0 0 8\n$EndMeshFormat\n", "not supported"},
    BadFile{"msh_not_msh", parse_gmsh, "solid cube\nfacet normal 0 0 1\n", "$MeshFormat"},
    BadFile{"msh_huge_count", parse_gmsh, kMshHead + "$Nodes\n1 4000000000 1 4000000000\n",
            "more than"},
    BadFile{"msh_no_nodes", parse_gmsh, kMshHead, "no $Nodes"},
    BadFile{"msh_nan", parse_gmsh, kMshHead + "$Nodes\n1 1 1 1\n3 1 0 1\n1\nnan 0 0\n$EndNodes\n",
            "finite"},
    BadFile{"msh_unknown_node", parse_gmsh,
            kMshHead + "$Nodes\n1 1 1 1\n3 1 0 1\n1\n0 0 0\n$EndNodes\n$Elements\n1 1 1 1\n3 1 4 "
                       "1\n1 1 1 1 7\n",
            "node 7"},
    BadFile{
        "msh_element_type", parse_gmsh,
        kMshHead + "$Nodes\n1 1 1 1\n3 1 0 1\n1\n0 0 0\n$EndNodes\n$Elements\n1 1 1 1\n3 1 99 1\n",
        "element type 99"},
    BadFile{"msh_duplicate_tags", parse_gmsh,
            kMshHead + "$Nodes\n1 2 1 1\n3 1 0 2\n1\n1\n0 0 0\n1 0 0\n$EndNodes\n", "distinct"},
    BadFile{"msh22_unterminated", parse_gmsh,
            "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n1\n1 0 0 0\n", "$EndNodes"},
    BadFile{"mesh_not_medit", parse_medit, "ply\nformat ascii 1.0\n", "MeshVersionFormatted"},
    BadFile{"mesh_2d", parse_medit, "MeshVersionFormatted 2\nDimension 2\n", "3D"},
    BadFile{"mesh_keyword", parse_medit, "MeshVersionFormatted 2\nDimension 3\nBananas 3\n",
            "Bananas"},
    BadFile{"mesh_huge_count", parse_medit,
            "MeshVersionFormatted 2\nDimension 3\nVertices 99999999999\n", "more than"},
    BadFile{"mesh_index", parse_medit,
            "MeshVersionFormatted 2\nDimension 3\nVertices 1\n0 0 0 0\nTriangles 1\n1 1 2 5\nEnd\n",
            "does not exist"},
    BadFile{"mesh_text", parse_medit,
            "MeshVersionFormatted 2\nDimension 3\nVertices 1\n0 zero 0 0\n", "line 4"},
    BadFile{"vtu_not_xml", parse_vtu, "hello", "VTKFile"},
    BadFile{"vtu_polydata", parse_vtu, "<VTKFile type=\"PolyData\">", "UnstructuredGrid"},
    BadFile{"vtu_no_piece", parse_vtu, kVtuHead + "</UnstructuredGrid></VTKFile>", "Piece"},
    BadFile{"vtu_huge_piece", parse_vtu,
            kVtuHead + "<Piece NumberOfPoints=\"99999999999\" NumberOfCells=\"1\"></Piece>",
            "file size"},
    BadFile{
        "vtu_bad_base64", parse_vtu,
        kVtuHead +
            "<Piece NumberOfPoints=\"1\" NumberOfCells=\"0\"><Points><DataArray type=\"Float64\" "
            "NumberOfComponents=\"3\" format=\"binary\">@@@@</DataArray></Points></Piece>",
        "base64"},
    BadFile{"vtu_zlib_bomb", parse_vtu,
            "<VTKFile type=\"UnstructuredGrid\" header_type=\"UInt32\" "
            "compressor=\"vtkZLibDataCompressor\">"
            "<Piece NumberOfPoints=\"1\" NumberOfCells=\"0\"><Points><DataArray type=\"Float64\" "
            "NumberOfComponents=\"3\" "
            "format=\"binary\">AQAAAAAAAEAAAAAAAQAAAA==eA==</DataArray></Points></Piece>",
            "zlib"},
    BadFile{
        "vtu_offsets", parse_vtu,
        kVtuHead +
            "<Piece NumberOfPoints=\"1\" NumberOfCells=\"1\"><Points><DataArray type=\"Float64\" "
            "NumberOfComponents=\"3\" format=\"ascii\">0 0 0</DataArray></Points><Cells>"
            "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">0</DataArray>"
            "<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">5</DataArray>"
            "<DataArray type=\"UInt8\" Name=\"types\" "
            "format=\"ascii\">1</DataArray></Cells></Piece>",
        "offset"},
    BadFile{
        "vtu_point_index", parse_vtu,
        kVtuHead +
            "<Piece NumberOfPoints=\"1\" NumberOfCells=\"1\"><Points><DataArray type=\"Float64\" "
            "NumberOfComponents=\"3\" format=\"ascii\">0 0 0</DataArray></Points><Cells>"
            "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">0 1 2</DataArray>"
            "<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">3</DataArray>"
            "<DataArray type=\"UInt8\" Name=\"types\" "
            "format=\"ascii\">5</DataArray></Cells></Piece>",
        "refers to point 1"}};

INSTANTIATE_TEST_SUITE_P(Cases, ReadersReject, ::testing::ValuesIn(kBadFiles),
                         [](const ::testing::TestParamInfo<BadFile>& info) {
                           return std::string(info.param.name);
                         });

TEST(Readers, ReadViewMeshRejectsWhatItCannotRead) {
  TempDir dir;
  EXPECT_THROW(read_view_mesh(dir.file("absent.msh")), InputError);
  EXPECT_THROW(read_view_mesh(dir.path().string() + "/"), InputError);
  rdmesh::testing::write_text(dir.file("mesh.stl"), "solid x\nendsolid x\n");
  EXPECT_THROW(read_view_mesh(dir.file("mesh.stl")), InputError);
  rdmesh::testing::write_text(dir.file("empty.mesh"),
                              "MeshVersionFormatted 2\nDimension 3\nVertices 1\n0 0 0 0\nEnd\n");
  try {
    read_view_mesh(dir.file("empty.mesh"));
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("neither tetrahedra nor triangles"), std::string::npos)
        << e.what();
  }
}

TEST(Readers, SkipElementsThePictureDoesNotDraw) {
  const std::string text =
      "MeshVersionFormatted 1\nDimension\n3\n# a comment\nVertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 "
      "0\n0 0 1 0\n"
      "Quadrilaterals\n1\n1 2 3 4 7\nTriangles\n1\n1 2 3 5\nNormals\n1\n0 0 1\nEnd\n";
  const ViewMesh m = parse_medit(text, "q.mesh");
  EXPECT_EQ(m.triangles.size(), 1u);
  EXPECT_EQ(m.triangle_labels[0], 5);
  EXPECT_EQ(m.skipped_elements, 1u);
}

}  // namespace
}  // namespace rdmesh::view::testing
