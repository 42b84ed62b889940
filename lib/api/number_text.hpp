// Numbers in the library's error messages, written so that they read back: the shortest
// decimal that converts back to the same double (std::to_chars), as Python's repr() does
// ("1.0000000000000002", "-1e-300", "nan", "inf"), never std::to_string's "%f" ("1.000000",
// "-0.000000"), which loses the value that was refused.
#pragma once

#include <array>
#include <charconv>
#include <string>

namespace exactccd {

/// `x` as the shortest decimal text that reads back as `x` (strtod, Python's float()).
inline std::string shortest_text(double x) {
  std::array<char, 32> buffer{};  // the longest shortest form: "-2.2250738585072014e-308", 24
  const auto [end, error] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), x);
  if (error != std::errc()) return "?";  // cannot happen with 32 characters
  return std::string(buffer.data(), end);
}

}  // namespace exactccd
