// Numbers written in lines of text (the Medit writer, text MSH) or in Gmsh's
// binary layout. Text: tokens separated by one space, each line ended by
// end_line(), doubles as the shortest text that reads back the same. Binary:
// int as 4 bytes, size_t as 8, double as 8, in the machine's byte order (the
// $MeshFormat section tells readers which, with the int 1); end_line() writes
// nothing. Buffered; flush() before writing to the stream directly.
#pragma once

#include <cstdint>
#include <cstring>
#include <ostream>
#include <string>

#include "mesh_labels.h"

namespace rdmesh::io_detail {

class NumberTokens {
 public:
  NumberTokens(std::ostream& out, bool binary) : out_(out), binary_(binary) {}
  NumberTokens(const NumberTokens&) = delete;
  NumberTokens& operator=(const NumberTokens&) = delete;
  ~NumberTokens() { flush(); }

  bool binary() const { return binary_; }

  /// A 4-byte int in binary.
  void i(long long v) {
    if (binary_) return raw(static_cast<std::int32_t>(v));
    separate();
    append_int(buffer_, v);
  }
  /// An 8-byte size_t in binary.
  void z(long long v) {
    if (binary_) return raw(static_cast<std::uint64_t>(v));
    separate();
    append_int(buffer_, v);
  }
  /// An 8-byte double in binary; the shortest round-trip text otherwise.
  void d(double v) {
    if (binary_) return raw(v);
    separate();
    append_double(buffer_, v);
  }
  void end_line() {
    if (!binary_) buffer_ += '\n';
    line_start_ = true;
    if (buffer_.size() > (1 << 16)) flush();
  }
  void flush() {
    out_.write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
    buffer_.clear();
  }

 private:
  template <class T>
  void raw(T v) {
    char bytes[sizeof(T)];
    std::memcpy(bytes, &v, sizeof(T));
    buffer_.append(bytes, sizeof(T));
    if (buffer_.size() > (1 << 16)) flush();
  }
  void separate() {
    if (!line_start_) buffer_ += ' ';
    line_start_ = false;
  }

  std::ostream& out_;
  bool binary_;
  bool line_start_ = true;
  std::string buffer_;
};

}  // namespace rdmesh::io_detail
