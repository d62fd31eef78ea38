// Whitespace-separated tokens of an untrusted text file, with the checks every
// reader needs: numbers that parse completely, counts no larger than what the
// rest of the file can hold, and errors that name the file and the line.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace rdmesh::view::detail {

class TextScanner {
 public:
  /// `comment` starts a comment running to the end of the line ('\0': none).
  TextScanner(std::string_view text, std::string file, char comment = '\0');

  /// The next token, or an empty view at the end of the text.
  std::string_view next();
  /// The next token without consuming it.
  std::string_view peek();
  bool at_end();

  /// The next token, which must be `keyword` (exact).
  void expect(std::string_view keyword);
  std::int64_t read_int(const char* what);
  /// An integer in [lo, hi].
  std::int64_t read_int(const char* what, std::int64_t lo, std::int64_t hi);
  double read_double(const char* what);
  /// A count of items each taking at least `min_chars` characters of the file:
  /// rejects counts the rest of the file cannot hold, so callers may reserve it.
  std::size_t read_count(const char* what, std::size_t min_chars);
  /// A double-quoted string (Gmsh names); the quotes are not part of the result.
  std::string read_quoted(const char* what);
  /// Skips tokens up to and including `keyword`.
  void skip_past(std::string_view keyword);

  /// Characters not yet read.
  std::size_t remaining() const { return text_.size() - pos_; }
  const std::string& file() const { return file_; }
  /// Throws InputError("file: line N: message") at the current line.
  [[noreturn]] void fail(const std::string& message) const;

 private:
  void skip_space();

  std::string_view text_;
  std::string file_;
  char comment_;
  std::size_t pos_ = 0;
  std::size_t line_ = 1;
};

/// Lower-case copy of an ASCII keyword.
std::string lower(std::string_view s);

}  // namespace rdmesh::view::detail
