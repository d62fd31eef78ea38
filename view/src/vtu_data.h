// The values of one VTK XML DataArray, in any of its encodings: ascii text,
// inline base64 ("binary"), appended raw or base64 data, each optionally
// compressed with zlib (vtkZLibDataCompressor). The byte counts in the binary
// headers are untrusted: payloads are checked against the bytes present, and a
// compressed array may not claim more than zlib's largest expansion of it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace rdmesh::view::detail {

/// File-wide settings from the VTKFile element.
struct VtkEncoding {
  bool header64 = false;    ///< header_type="UInt64" (else UInt32)
  bool big_endian = false;  ///< byte_order="BigEndian"
  bool zlib = false;        ///< compressor="vtkZLibDataCompressor"
};

/// Where an array's values are.
struct ArraySource {
  std::string name;       ///< for messages
  std::string type;       ///< "Float64", "Int32", ...
  std::string format;     ///< "ascii", "binary" or "appended"
  std::string_view text;  ///< ascii or inline base64: the element's content
  /// appended: the data from this array's offset to the next array's offset
  /// (or the end of the appended section), and whether it is base64 (else raw).
  std::string_view appended;
  bool appended_base64 = false;
};

/// Decodes the array as doubles (any numeric type) or as integers (integer
/// types only). @throws InputError(file, problem) naming the array's flaw.
std::vector<double> decode_reals(const ArraySource& source, const VtkEncoding& encoding,
                                 const std::string& file);
std::vector<std::int64_t> decode_ints(const ArraySource& source, const VtkEncoding& encoding,
                                      const std::string& file);

/// Bytes of base64 text made of one or more padded pieces (VTK encodes a
/// binary header and its data separately); whitespace is ignored. Returns
/// false on a character outside the alphabet.
bool decode_base64(std::string_view text, std::vector<unsigned char>& out);

}  // namespace rdmesh::view::detail
