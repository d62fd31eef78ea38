#include "text_scanner.h"

#include <cctype>
#include <charconv>
#include <cmath>

#include "rdmesh/errors.h"

namespace rdmesh::view::detail {

namespace {

/// The token quoted for a message, shortened (it may be binary garbage).
std::string shown(std::string_view token) {
  if (token.empty()) return "the end of the file";
  std::string s(token.substr(0, 24));
  for (char& c : s) {
    if (!std::isprint(static_cast<unsigned char>(c))) c = '?';
  }
  return "'" + s + (token.size() > 24 ? "...'" : "'");
}

}  // namespace

TextScanner::TextScanner(std::string_view text, std::string file, char comment)
    : text_(text), file_(std::move(file)), comment_(comment) {}

void TextScanner::skip_space() {
  while (pos_ < text_.size()) {
    const char c = text_[pos_];
    if (c == '\n') {
      ++line_;
      ++pos_;
    } else if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
      ++pos_;
    } else if (comment_ != '\0' && c == comment_) {
      while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
    } else {
      return;
    }
  }
}

std::string_view TextScanner::peek() {
  skip_space();
  std::size_t end = pos_;
  while (end < text_.size() && !std::isspace(static_cast<unsigned char>(text_[end]))) ++end;
  return text_.substr(pos_, end - pos_);
}

std::string_view TextScanner::next() {
  const std::string_view token = peek();
  pos_ += token.size();
  return token;
}

bool TextScanner::at_end() {
  skip_space();
  return pos_ == text_.size();
}

void TextScanner::fail(const std::string& message) const {
  throw InputError(file_, "line " + std::to_string(line_) + ": " + message);
}

void TextScanner::expect(std::string_view keyword) {
  const std::string_view token = next();
  if (token != keyword) fail("expected " + std::string(keyword) + ", found " + shown(token));
}

std::int64_t TextScanner::read_int(const char* what) {
  const std::string_view token = next();
  std::int64_t value = 0;
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  if (token.empty() || ec != std::errc() || end != token.data() + token.size()) {
    fail(std::string("expected ") + what + " (an integer), found " + shown(token));
  }
  return value;
}

std::int64_t TextScanner::read_int(const char* what, std::int64_t lo, std::int64_t hi) {
  const std::int64_t value = read_int(what);
  if (value < lo || value > hi) {
    fail(std::string(what) + " " + std::to_string(value) + " is out of range [" +
         std::to_string(lo) + ", " + std::to_string(hi) + "]");
  }
  return value;
}

double TextScanner::read_double(const char* what) {
  const std::string_view token = next();
  double value = 0;
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  if (token.empty() || ec != std::errc() || end != token.data() + token.size() ||
      !std::isfinite(value)) {
    fail(std::string("expected ") + what + " (a finite number), found " + shown(token));
  }
  return value;
}

std::size_t TextScanner::read_count(const char* what, std::size_t min_chars) {
  const std::int64_t count = read_int(what);
  if (count < 0) fail(std::string(what) + " is negative");
  if (static_cast<std::uint64_t>(count) > remaining() / min_chars) {
    fail(std::string(what) + " " + std::to_string(count) +
         " is more than the rest of the file can hold (truncated or corrupt file?)");
  }
  return static_cast<std::size_t>(count);
}

std::string TextScanner::read_quoted(const char* what) {
  skip_space();
  if (pos_ >= text_.size() || text_[pos_] != '"') {
    fail(std::string("expected ") + what + " in double quotes, found " + shown(peek()));
  }
  const std::size_t close = text_.find('"', pos_ + 1);
  const std::size_t newline = text_.find('\n', pos_ + 1);
  if (close == std::string_view::npos || newline < close) fail(std::string("unterminated ") + what);
  std::string value(text_.substr(pos_ + 1, close - pos_ - 1));
  pos_ = close + 1;
  return value;
}

void TextScanner::skip_past(std::string_view keyword) {
  for (std::string_view token = next(); token != keyword; token = next()) {
    if (token.empty()) fail("missing " + std::string(keyword));
  }
}

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

}  // namespace rdmesh::view::detail
