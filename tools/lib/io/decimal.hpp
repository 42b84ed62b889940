// The one rule of the text readers for a leading plus sign, before std::from_chars (which takes
// none): "+1" is 1, but "+-1" and "++1" are no numbers.
#pragma once

namespace exactccd::io {

/// Where std::from_chars should start reading the number in [first, last): after one leading
/// '+', unless another sign follows it (from_chars would then read "+-1" as -1).
inline const char* after_plus_sign(const char* first, const char* last) {
  if (first != last && *first == '+' && (last - first == 1 || (first[1] != '-' && first[1] != '+'))) return first + 1;
  return first;
}

}  // namespace exactccd::io
