// A line-oriented tokenizer for the text mesh formats (OFF, ASCII STL, OBJ, PLY).
#pragma once

#include <charconv>
#include <cmath>
#include <istream>
#include <string>
#include <string_view>
#include <vector>

#include "rdmesh/errors.h"

namespace rdmesh {

/// Reads non-empty lines, splits them into whitespace-separated tokens (text
/// after '#' is a comment) and parses numbers; errors name the file and line.
class LineReader {
 public:
  LineReader(std::istream& in, const std::string& file) : in_(in), file_(file) {}

  /// The tokens of the next line that has any; false at the end of the input.
  /// The views stay valid until the next call.
  bool next(std::vector<std::string_view>& tokens) {
    tokens.clear();
    while (tokens.empty()) {
      if (!std::getline(in_, line_)) return false;
      ++line_number_;
      std::string_view s(line_);
      if (const auto hash = s.find('#'); hash != std::string_view::npos) s = s.substr(0, hash);
      std::size_t i = 0;
      while (i < s.size()) {
        while (i < s.size() && is_space(s[i])) ++i;
        const std::size_t j = i;
        while (i < s.size() && !is_space(s[i])) ++i;
        if (i > j) tokens.push_back(s.substr(j, i - j));
      }
    }
    return true;
  }

  /// A finite real number; fail() otherwise.
  double real(std::string_view token) const {
    double v = 0;
    const char* begin = token.data();
    if (!token.empty() && *begin == '+') ++begin;
    const auto [end, ec] = std::from_chars(begin, token.data() + token.size(), v);
    if (ec != std::errc() || end != token.data() + token.size()) {
      fail("'" + std::string(token) + "' is not a number");
    }
    if (!std::isfinite(v)) fail("non-finite coordinate '" + std::string(token) + "'");
    return v;
  }

  /// An integer; fail() otherwise.
  long long integer(std::string_view token) const {
    long long v = 0;
    const char* begin = token.data();
    if (!token.empty() && *begin == '+') ++begin;
    const auto [end, ec] = std::from_chars(begin, token.data() + token.size(), v);
    if (ec != std::errc() || end != token.data() + token.size()) {
      fail("'" + std::string(token) + "' is not an integer");
    }
    return v;
  }

  /// Throws InputError "FILE: line N: message".
  [[noreturn]] void fail(const std::string& message) const {
    throw InputError(file_, "line " + std::to_string(line_number_) + ": " + message);
  }

  int line_number() const { return line_number_; }
  std::istream& stream() { return in_; }

 private:
  static bool is_space(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
  }

  std::istream& in_;
  std::string file_;
  std::string line_;
  int line_number_ = 0;
};

}  // namespace rdmesh
