// write_mesh: dispatch by extension, failure modes and atomic replacement.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <sstream>

#include "io/io_test_util.h"
#include "io/test_meshes.h"
#include "rdmesh/errors.h"
#include "rdmesh/mesh_writers.h"

namespace rdmesh {
namespace {

namespace fs = std::filesystem;
using testing::TempDir;

/// Names of the entries of `dir`.
std::vector<std::string> entries(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

TEST(FormatFromPath, KnownExtensions) {
  EXPECT_EQ(format_from_path("a/b.mesh"), MeshFormat::Medit);
  EXPECT_EQ(format_from_path("b.msh"), MeshFormat::Gmsh41);
  EXPECT_EQ(format_from_path("/x/y.z/b.vtu"), MeshFormat::Vtu);
  EXPECT_EQ(format_from_path("B.MSH"), MeshFormat::Gmsh41);
}

TEST(FormatFromPath, UnknownExtensionIsAnInputErrorNamingTheFile) {
  for (const char* path : {"out.stl", "out", "out.mesh.gz", "dir.msh/out"}) {
    try {
      format_from_path(path);
      ADD_FAILURE() << path << " accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), path);
      EXPECT_NE(std::string(e.what()).find("expected .mesh, .msh or .vtu"), std::string::npos);
    }
  }
}

TEST(WriteMesh, WritesWhatTheStreamWriterWrites) {
  TempDir dir;
  const TetMesh mesh = testing::two_cube_mesh(0.1);
  std::ostringstream medit, gmsh, vtu;
  write_medit(mesh, medit);
  write_gmsh41(mesh, gmsh);
  write_vtu(mesh, vtu);
  write_mesh(mesh, dir.file("a.mesh"));
  write_mesh(mesh, dir.file("a.msh"));
  write_mesh(mesh, dir.file("a.vtu"));
  EXPECT_EQ(testing::read_text(dir.file("a.mesh")), medit.str());
  EXPECT_EQ(testing::read_text(dir.file("a.msh")), gmsh.str());
  EXPECT_EQ(testing::read_text(dir.file("a.vtu")), vtu.str());
  EXPECT_EQ(entries(dir.path()), (std::vector<std::string>{"a.mesh", "a.msh", "a.vtu"}));
}

TEST(WriteMesh, UnknownExtensionCreatesNothing) {
  TempDir dir;
  EXPECT_THROW(write_mesh(testing::two_cube_mesh(), dir.file("a.obj")), InputError);
  EXPECT_TRUE(entries(dir.path()).empty());
}

TEST(WriteMesh, MissingDirectoryIsAnOutputError) {
  TempDir dir;
  const std::string path = dir.file("no/such/dir/a.msh");
  try {
    write_mesh(testing::two_cube_mesh(), path);
    FAIL() << "no exception";
  } catch (const OutputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(path + ": ", 0), 0u) << e.what();
  }
  EXPECT_TRUE(entries(dir.path()).empty());
}

TEST(WriteMesh, ReadOnlyDirectoryIsAnOutputError) {
  if (::geteuid() == 0) {
    // Root ignores permission bits; procfs refuses new files even to root.
    EXPECT_THROW(write_mesh(testing::two_cube_mesh(), "/proc/rdmesh_test.vtu"), OutputError);
    return;
  }
  TempDir dir;
  fs::permissions(dir.path(), fs::perms::owner_read | fs::perms::owner_exec);
  EXPECT_THROW(write_mesh(testing::two_cube_mesh(), dir.file("a.vtu")), OutputError);
  fs::permissions(dir.path(), fs::perms::owner_all);
  EXPECT_TRUE(entries(dir.path()).empty());
}

TEST(WriteMesh, ParentThatIsAFileIsAnOutputError) {
  TempDir dir;
  testing::write_text(dir.file("plain"), "x");
  EXPECT_THROW(write_mesh(testing::two_cube_mesh(), dir.file("plain/a.mesh")), OutputError);
  EXPECT_EQ(entries(dir.path()), std::vector<std::string>{"plain"});
}

TEST(WriteMesh, PathThatIsADirectoryIsAnOutputError) {
  TempDir dir;
  fs::create_directory(dir.file("taken.msh"));
  EXPECT_THROW(write_mesh(testing::two_cube_mesh(), dir.file("taken.msh")), OutputError);
  EXPECT_EQ(entries(dir.path()), std::vector<std::string>{"taken.msh"});
  EXPECT_TRUE(fs::is_directory(dir.file("taken.msh")));
}

TEST(WriteMesh, ExistingFileIsReplacedAtomically) {
  TempDir dir;
  const std::string path = dir.file("a.mesh");
  testing::write_text(path, "old contents that are longer than nothing\n");
  // A reader holding the old file keeps seeing the old inode (rename, not truncate).
  std::ifstream old_reader(path);
  write_mesh(testing::two_cube_mesh(0.1), path);
  std::ostringstream expected;
  write_medit(testing::two_cube_mesh(0.1), expected);
  EXPECT_EQ(testing::read_text(path), expected.str());
  std::string old_line;
  std::getline(old_reader, old_line);
  EXPECT_EQ(old_line, "old contents that are longer than nothing");
  EXPECT_EQ(entries(dir.path()), std::vector<std::string>{"a.mesh"});
}

TEST(WriteMesh, FailedWriteLeavesThePreviousFileAndNoTemporary) {
  TempDir dir;
  const std::string path = dir.file("a.msh");
  testing::write_text(path, "previous\n");
  TetMesh broken = testing::two_cube_mesh();
  broken.tets[0][0] = 99;  // the writer rejects the mesh after the temp file exists
  EXPECT_THROW(write_mesh(broken, path), InternalError);
  EXPECT_EQ(testing::read_text(path), "previous\n");
  EXPECT_EQ(entries(dir.path()), std::vector<std::string>{"a.msh"});
}

TEST(StageMesh, TheFileWaitsUnderItsTemporaryNameUntilCommitted) {
  TempDir dir;
  const std::string path = dir.file("a.mesh");
  testing::write_text(path, "previous\n");
  std::ostringstream expected;
  write_medit(testing::two_cube_mesh(0.1), expected);
  StagedFile staged = stage_mesh(testing::two_cube_mesh(0.1), path);
  // Written in full beside the file, which is not touched yet.
  ASSERT_FALSE(staged.temp_path().empty());
  EXPECT_EQ(testing::read_text(staged.temp_path()), expected.str());
  EXPECT_EQ(testing::read_text(path), "previous\n");
  EXPECT_EQ(entries(dir.path()).size(), 2u);
  // A move hands the temporary file over; the moved-from object owns nothing.
  StagedFile moved = std::move(staged);
  EXPECT_TRUE(staged.temp_path().empty());  // NOLINT(bugprone-use-after-move): what a move leaves
  moved.commit();
  EXPECT_EQ(testing::read_text(path), expected.str());
  EXPECT_EQ(entries(dir.path()), std::vector<std::string>{"a.mesh"});
  EXPECT_THROW(moved.commit(), InternalError);
}

TEST(StageMesh, ADroppedStageLeavesThePreviousFileAndNoTemporary) {
  TempDir dir;
  const std::string path = dir.file("a.msh");
  testing::write_text(path, "previous\n");
  {
    StagedFile staged = stage_mesh(testing::two_cube_mesh(), path);
    EXPECT_EQ(entries(dir.path()).size(), 2u);
  }
  EXPECT_EQ(testing::read_text(path), "previous\n");
  EXPECT_EQ(entries(dir.path()), std::vector<std::string>{"a.msh"});
  // Moving a stage over another drops the one overwritten.
  StagedFile first = stage_mesh(testing::two_cube_mesh(), path);
  first = stage_mesh(testing::two_cube_mesh(0.1), path);
  EXPECT_EQ(entries(dir.path()).size(), 2u);
}

TEST(StageMesh, ACommitThatCannotRenameIsAnOutputErrorAndRemovesTheTemporary) {
  TempDir dir;
  const std::string path = dir.file("a.msh");
  StagedFile staged = stage_mesh(testing::two_cube_mesh(), path);
  fs::create_directory(path);  // a directory appeared where the file goes
  fs::create_directory(path + "/inside");
  EXPECT_THROW(staged.commit(), OutputError);
  EXPECT_EQ(entries(dir.path()), std::vector<std::string>{"a.msh"});
  EXPECT_TRUE(fs::is_directory(path));
}

}  // namespace
}  // namespace rdmesh
