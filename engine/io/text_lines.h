#pragma once
// Line-by-line tokenising of text formats (OBJ, OFF, ASCII PLY, Line3D++, NVM, COLMAP), with
// 1-based line numbers for error messages.

#include <cctype>
#include <charconv>
#include <cmath>
#include <string_view>
#include <system_error>
#include <vector>

namespace linesurf::io {

/// Splits text into lines and whitespace-separated tokens.
class LineReader {
 public:
  explicit LineReader(std::string_view text) : text_(text) {}

  /// Next line's tokens (empty for a blank line); false at the end of the text.
  bool Next(std::vector<std::string_view>& tokens) {
    tokens.clear();
    if (pos_ >= text_.size()) return false;
    std::size_t end = text_.find('\n', pos_);
    if (end == std::string_view::npos) end = text_.size();
    const std::string_view line = text_.substr(pos_, end - pos_);
    pos_ = end + 1;
    ++line_number_;
    std::size_t i = 0;
    while (i < line.size()) {
      while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
      std::size_t j = i;
      while (j < line.size() && !std::isspace(static_cast<unsigned char>(line[j]))) ++j;
      if (j > i) tokens.push_back(line.substr(i, j - i));
      i = j;
    }
    return true;
  }
  /// 1-based number of the line last returned by Next().
  [[nodiscard]] std::size_t line_number() const { return line_number_; }
  /// Byte offset just past the line last returned by Next().
  [[nodiscard]] std::size_t position() const { return pos_; }

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t line_number_ = 0;
};

/// Parses the whole token as a double (from_chars: locale-independent, correctly rounded).
inline bool ParseDouble(std::string_view token, double& value) {
  const auto result = std::from_chars(token.data(), token.data() + token.size(), value);
  return result.ec == std::errc() && result.ptr == token.data() + token.size();
}

/// Parses the whole token as a signed integer.
inline bool ParseInt(std::string_view token, long long& value) {
  const auto result = std::from_chars(token.data(), token.data() + token.size(), value);
  return result.ec == std::errc() && result.ptr == token.data() + token.size();
}

/// Parses tokens[first .. first + n) as finite doubles into out[0 .. n); false when there are
/// too few tokens or one is not a finite number.
inline bool ParseFiniteNumbers(const std::vector<std::string_view>& tokens, std::size_t first,
                               std::size_t n, double* out) {
  if (tokens.size() < first + n) return false;
  for (std::size_t k = 0; k < n; ++k) {
    if (!ParseDouble(tokens[first + k], out[k]) || !std::isfinite(out[k])) return false;
  }
  return true;
}

}  // namespace linesurf::io
