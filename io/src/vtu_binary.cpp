#include "vtu_binary.h"

#include <zlib.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <vector>

#include "rdmesh/errors.h"

namespace rdmesh::io_detail {
namespace {

constexpr std::size_t kBlock = 32768;

template <class T>
void append_little_endian(std::string& bytes, T v) {
  static_assert(sizeof(T) <= 8);
  unsigned char raw[sizeof(T)];
  std::memcpy(raw, &v, sizeof(T));
  if constexpr (sizeof(T) > 1) {
    const std::uint16_t probe = 1;
    unsigned char first = 0;
    std::memcpy(&first, &probe, 1);
    if (first == 0) std::reverse(raw, raw + sizeof(T));  // big-endian machine
  }
  bytes.append(reinterpret_cast<const char*>(raw), sizeof(T));
}

std::string base64(const std::string& bytes) {
  static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const std::uint32_t v = std::uint32_t(static_cast<unsigned char>(bytes[i])) << 16 |
                            std::uint32_t(static_cast<unsigned char>(bytes[i + 1])) << 8 |
                            static_cast<unsigned char>(bytes[i + 2]);
    for (int k = 3; k >= 0; --k) out += digits[(v >> (6 * k)) & 63];
  }
  const std::size_t left = bytes.size() - i;
  if (left > 0) {
    std::uint32_t v = std::uint32_t(static_cast<unsigned char>(bytes[i])) << 16;
    if (left == 2) v |= std::uint32_t(static_cast<unsigned char>(bytes[i + 1])) << 8;
    out += digits[(v >> 18) & 63];
    out += digits[(v >> 12) & 63];
    out += left == 2 ? digits[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

}  // namespace

void append_binary_value(std::string& bytes, const std::string& type, double real,
                         long long integer) {
  if (type == "Float64") return append_little_endian(bytes, real);
  if (type == "Int64") return append_little_endian(bytes, static_cast<std::int64_t>(integer));
  if (type == "Int32") return append_little_endian(bytes, static_cast<std::int32_t>(integer));
  if (type == "UInt8") return append_little_endian(bytes, static_cast<std::uint8_t>(integer));
  throw InternalError("vtu writer: no binary layout for type " + type);
}

std::string zlib_base64(const std::string& bytes) {
  const std::size_t blocks = (bytes.size() + kBlock - 1) / kBlock;
  std::string header, data;
  append_little_endian(header, static_cast<std::uint64_t>(blocks));
  append_little_endian(header, static_cast<std::uint64_t>(kBlock));
  const std::size_t last = bytes.size() % kBlock;
  append_little_endian(header, static_cast<std::uint64_t>(blocks > 0 && last == 0 ? kBlock : last));
  std::vector<Bytef> buffer(compressBound(kBlock));
  for (std::size_t b = 0; b < blocks; ++b) {
    const std::size_t size = std::min(kBlock, bytes.size() - b * kBlock);
    uLongf produced = static_cast<uLongf>(buffer.size());
    if (compress2(buffer.data(), &produced,
                  reinterpret_cast<const Bytef*>(bytes.data() + b * kBlock),
                  static_cast<uLong>(size), Z_DEFAULT_COMPRESSION) != Z_OK) {
      throw OutputError("write_vtu: zlib could not compress a data block");
    }
    append_little_endian(header, static_cast<std::uint64_t>(produced));
    data.append(reinterpret_cast<const char*>(buffer.data()), produced);
  }
  return base64(header) + base64(data);
}

}  // namespace rdmesh::io_detail
