#include "rdmesh/input_file.h"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "rdmesh/errors.h"

namespace rdmesh {

void check_input_file(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (!fs::exists(status)) throw InputError(path, "no such file");
  if (fs::is_directory(status)) throw InputError(path, "is a directory");
  if (!fs::is_regular_file(status)) {
    throw InputError(path, "not a regular file (a FIFO, a device...)");
  }
  if (::access(path.c_str(), R_OK) != 0) {
    throw InputError(path, "cannot read the file (permission denied)");
  }
}

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

bool is_cad_file(const std::string& path) {
  const std::string ext = lower_extension(path);
  return ext == ".step" || ext == ".stp" || ext == ".brep" || ext == ".iges" || ext == ".igs";
}

}  // namespace rdmesh
