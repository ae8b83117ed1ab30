#pragma once
// How the CLI prints a number in messages and summaries: six significant digits (%.6g).

#include <cstdio>
#include <string>

namespace linesurf::cli {

inline std::string ShortNumber(double v) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.6g", v);
  return text;
}

}  // namespace linesurf::cli
