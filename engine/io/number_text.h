#pragma once
// Shortest round-trip text for doubles, shared by every text writer (JSON, OBJ, OFF, ASCII PLY).

#include <charconv>
#include <cmath>
#include <string>
#include <string_view>

namespace linesurf::io {

/// Appends the shortest decimal text that reads back (strtod) to exactly `value`. Integral values
/// get a trailing ".0" so a reader keeps them floating point and -0.0 keeps its sign. `value`
/// must be finite (callers check; JSON has no NaN or infinity).
inline void AppendDouble(std::string& out, double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  const std::string_view text(buffer, static_cast<std::size_t>(result.ptr - buffer));
  out.append(text);
  if (text.find_first_of(".e") == std::string_view::npos) out.append(".0");
}

/// Appends an unsigned integer in decimal.
inline void AppendUnsigned(std::string& out, unsigned long long value) {
  char buffer[24];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  out.append(buffer, result.ptr);
}

}  // namespace linesurf::io
