#include "vtu_data.h"

#include <zlib.h>

#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>

#include "rdmesh/errors.h"

namespace rdmesh::view::detail {
namespace {

/// zlib never expands data by more than this factor (deflate's best case is ~1032:1).
constexpr std::uint64_t kMaxZlibRatio = 1032;

struct TypeInfo {
  int size = 0;  ///< 0: unknown type
  bool is_float = false;
  bool is_signed = false;
};

TypeInfo type_info(const std::string& type) {
  if (type == "Float64") return {8, true, true};
  if (type == "Float32") return {4, true, true};
  if (type == "Int64") return {8, false, true};
  if (type == "UInt64") return {8, false, false};
  if (type == "Int32") return {4, false, true};
  if (type == "UInt32") return {4, false, false};
  if (type == "Int16") return {2, false, true};
  if (type == "UInt16") return {2, false, false};
  if (type == "Int8" || type == "Char") return {1, false, true};
  if (type == "UInt8" || type == "UChar") return {1, false, false};
  return {};
}

class ArrayDecoder {
 public:
  ArrayDecoder(const ArraySource& source, const VtkEncoding& encoding, const std::string& file)
      : src_(source), enc_(encoding), file_(file), info_(type_info(source.type)) {
    if (info_.size == 0) fail("unsupported type '" + source.type + "'");
  }

  [[noreturn]] void fail(const std::string& problem) const {
    throw InputError(file_, "DataArray '" + src_.name + "': " + problem);
  }

  template <class T>
  std::vector<T> decode() {
    if (src_.format == "ascii") return decode_ascii<T>();
    if (src_.format != "binary" && src_.format != "appended") {
      fail("unknown format '" + src_.format + "'");
    }
    const std::string_view data = binary_payload();
    if (data.size() % static_cast<std::size_t>(info_.size) != 0) {
      fail("its byte count is not a multiple of the size of " + src_.type);
    }
    std::vector<T> values(data.size() / static_cast<std::size_t>(info_.size));
    for (std::size_t i = 0; i < values.size(); ++i)
      values[i] = value<T>(data.data() + i * info_.size);
    return values;
  }

  void require_integers() const {
    if (info_.is_float) fail("expected an integer type, found " + src_.type);
  }

 private:
  template <class T>
  std::vector<T> decode_ascii() const {
    std::vector<T> values;
    const char* p = src_.text.data();
    const char* end = p + src_.text.size();
    while (true) {
      while (p < end && (*p == ' ' || *p == '\n' || *p == '\t' || *p == '\r')) ++p;
      if (p == end) break;
      T v{};
      const auto [next, ec] = std::from_chars(p, end, v);
      if (ec != std::errc() || (next < end && !std::isspace(static_cast<unsigned char>(*next)))) {
        fail(std::string("a value is not a number of type ") + src_.type);
      }
      if constexpr (std::is_floating_point_v<T>) {
        if (!std::isfinite(v)) fail("a value is not finite");
      }
      values.push_back(v);
      p = next;
    }
    return values;
  }

  /// Unsigned integer of `size` bytes at `p` in the file's byte order.
  std::uint64_t read_unsigned(const unsigned char* p, int size) const {
    std::uint64_t v = 0;
    for (int k = 0; k < size; ++k) {
      const int byte = enc_.big_endian ? k : size - 1 - k;
      v = (v << 8) | p[byte];
    }
    return v;
  }

  template <class T>
  T value(const char* p) const {
    const std::uint64_t bits = read_unsigned(reinterpret_cast<const unsigned char*>(p), info_.size);
    if (info_.is_float) {
      double d;
      if (info_.size == 8) {
        std::memcpy(&d, &bits, 8);
      } else {
        const auto b32 = static_cast<std::uint32_t>(bits);
        float f;
        std::memcpy(&f, &b32, 4);
        d = f;
      }
      if (!std::isfinite(d)) fail("a value is not finite");
      return static_cast<T>(d);
    }
    if (info_.is_signed) {
      const int shift = 64 - 8 * info_.size;  // sign-extend
      return static_cast<T>(static_cast<std::int64_t>(bits << shift) >> shift);
    }
    if (bits > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max())) {
      fail("a value is too large");
    }
    return static_cast<T>(bits);
  }

  /// The raw bytes before decompression: decoded base64, or the appended raw bytes.
  std::string_view encoded_bytes() {
    const bool base64 = src_.format == "binary" || src_.appended_base64;
    const std::string_view text = src_.format == "binary" ? src_.text : src_.appended;
    if (!base64) return text;
    if (!decode_base64(text, decoded_)) fail("invalid base64 data");
    return {reinterpret_cast<const char*>(decoded_.data()), decoded_.size()};
  }

  std::string_view binary_payload() {
    const std::string_view bytes = encoded_bytes();
    const std::size_t h = enc_.header64 ? 8 : 4;
    auto header = [&](std::size_t i) {
      return read_unsigned(reinterpret_cast<const unsigned char*>(bytes.data()) + i * h,
                           static_cast<int>(h));
    };
    if (!enc_.zlib) {
      if (bytes.size() < h) fail("truncated data");
      const std::uint64_t n = header(0);
      if (n > bytes.size() - h) fail("claims more bytes than the file holds");
      return bytes.substr(h, n);
    }
    if (bytes.size() < 3 * h) fail("truncated compressed data");
    const std::uint64_t blocks = header(0), block_size = header(1), last = header(2);
    if (blocks > bytes.size() / h - 3) fail("claims more blocks than the file holds");
    const std::size_t data_start = (3 + blocks) * h;
    std::uint64_t compressed = 0;
    for (std::uint64_t b = 0; b < blocks; ++b) compressed += header(3 + b);
    if (compressed > bytes.size() - data_start) fail("compressed blocks run past the file's end");
    if (block_size > (std::uint64_t{1} << 32) || last > block_size) fail("invalid block sizes");
    const std::uint64_t total =
        blocks == 0 ? 0 : (blocks - 1) * block_size + (last ? last : block_size);
    if (total > kMaxZlibRatio * compressed + 1024) fail("claims more data than zlib can expand to");
    inflated_.resize(total);
    std::uint64_t in = data_start, out = 0;
    for (std::uint64_t b = 0; b < blocks; ++b) {
      const std::uint64_t size = header(3 + b);
      const std::uint64_t expected = b + 1 < blocks || last == 0 ? block_size : last;
      uLongf produced = static_cast<uLongf>(expected);
      if (::uncompress(inflated_.data() + out, &produced,
                       reinterpret_cast<const Bytef*>(bytes.data() + in),
                       static_cast<uLong>(size)) != Z_OK ||
          produced != expected) {
        fail("corrupt compressed block");
      }
      in += size;
      out += expected;
    }
    return {reinterpret_cast<const char*>(inflated_.data()), inflated_.size()};
  }

  const ArraySource& src_;
  const VtkEncoding& enc_;
  const std::string& file_;
  TypeInfo info_;
  std::vector<unsigned char> decoded_, inflated_;
};

int base64_value(char c) {
  if (c >= 'A' && c <= 'Z') return c - 'A';
  if (c >= 'a' && c <= 'z') return c - 'a' + 26;
  if (c >= '0' && c <= '9') return c - '0' + 52;
  if (c == '+') return 62;
  if (c == '/') return 63;
  return -1;
}

}  // namespace

bool decode_base64(std::string_view text, std::vector<unsigned char>& out) {
  out.clear();
  out.reserve(text.size() / 4 * 3);
  std::uint32_t bits = 0;
  int have = 0;     // characters of the current quad
  int padding = 0;  // '=' seen in the current quad
  for (char c : text) {
    if (c == ' ' || c == '\n' || c == '\r' || c == '\t') continue;
    if (c == '=') {
      if (have + padding < 2) return false;
      ++padding;
    } else {
      const int v = base64_value(c);
      if (v < 0 || padding > 0) return false;
      bits = (bits << 6) | static_cast<std::uint32_t>(v);
      ++have;
    }
    if (have + padding == 4) {
      bits <<= 6 * padding;
      for (int k = 0; k < 3 - padding; ++k)
        out.push_back(static_cast<unsigned char>(bits >> (16 - 8 * k)));
      bits = 0;
      have = padding = 0;
    }
  }
  if (padding > 0) return false;
  if (have == 1) return false;
  if (have > 1) {  // unpadded end
    bits <<= 6 * (4 - have);
    for (int k = 0; k < have - 1; ++k)
      out.push_back(static_cast<unsigned char>(bits >> (16 - 8 * k)));
  }
  return true;
}

std::vector<double> decode_reals(const ArraySource& source, const VtkEncoding& encoding,
                                 const std::string& file) {
  ArrayDecoder decoder(source, encoding, file);
  return decoder.decode<double>();
}

std::vector<std::int64_t> decode_ints(const ArraySource& source, const VtkEncoding& encoding,
                                      const std::string& file) {
  ArrayDecoder decoder(source, encoding, file);
  decoder.require_integers();
  return decoder.decode<std::int64_t>();
}

}  // namespace rdmesh::view::detail
