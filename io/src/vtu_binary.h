// VTK XML binary data arrays: values as bytes of the array's type, and those
// bytes zlib-compressed in 32 KiB blocks and base64-encoded the way VTK's
// vtkZLibDataCompressor does (UInt64 header: block count, block size, size of
// the last block, each block's compressed size; header and blocks encoded apart).
#pragma once

#include <string>

namespace rdmesh::io_detail {

/// Appends one value as `type` ("Int32", "Int64", "UInt8" or "Float64"; little-endian):
/// `real` for Float64, `integer` otherwise.
void append_binary_value(std::string& bytes, const std::string& type, double real,
                         long long integer);

/// The compressed, encoded text of `bytes`. Throws OutputError if zlib fails.
std::string zlib_base64(const std::string& bytes);

}  // namespace rdmesh::io_detail
