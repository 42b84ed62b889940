// Numbers in error messages as they read back: the shortest decimal that strtod turns into
// the same double (1.0000000000000002 for 1 + 2^-52, -1e-300, not 1.000000 or -0.000000).
#pragma once

#include <cstdio>
#include <cstdlib>
#include <string>

namespace exactccd::api {

/// The shortest "%.{p}g" text of x (p = 1 .. 17) that reads back as x; "nan", "inf", "-inf" for
/// the non-finite values.
inline std::string number_text(double x) {
  char buffer[32];
  for (int precision = 1; precision <= 17; ++precision) {
    std::snprintf(buffer, sizeof buffer, "%.*g", precision, x);
    if (std::strtod(buffer, nullptr) == x) break;  // NaN never compares equal: "%.17g" of it
  }
  return buffer;
}

}  // namespace exactccd::api
