// SHA-256 (FIPS 180-4) of a byte string or a file: the report names the exact
// input it meshed, and `sha256sum FILE` gives the same hex digest.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace rdmesh {

/// Incremental SHA-256.
class Sha256 {
 public:
  Sha256();
  void update(std::string_view bytes);
  /// The digest as 64 lowercase hex digits; the object is then spent.
  std::string hex_digest();

 private:
  void block(const unsigned char* p);

  std::uint32_t h_[8];
  unsigned char buffer_[64];
  std::size_t buffered_ = 0;
  std::uint64_t length_ = 0;  ///< bytes hashed so far
};

/// SHA-256 of the bytes of the file at `path`, as 64 hex digits.
/// @throws InputError(path, ...) when the file cannot be read.
std::string sha256_of_file(const std::string& path);

}  // namespace rdmesh
