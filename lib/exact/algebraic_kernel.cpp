#include "exact/algebraic_kernel.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace exactccd::exact::algebraic {

void sort_unique(const Kernel& kernel, std::vector<Root>& times) {
  const auto compare = kernel.compare_1_object();
  std::sort(times.begin(), times.end(),
            [&](const Root& a, const Root& b) { return compare(a, b) == CGAL::SMALLER; });
  times.erase(std::unique(times.begin(), times.end(),
                          [&](const Root& a, const Root& b) { return compare(a, b) == CGAL::EQUAL; }),
              times.end());
}

TimeInterval enclose(const Kernel& kernel, const Root& t) {
  // Relative precision 2^-64 is finer than half an ulp (2^-53 relative), so after outward
  // rounding at most one double lies strictly between lo and hi.
  const auto [lower, upper] = kernel.approximate_relative_1_object()(t, 64);
  double lo = CGAL::to_interval(lower).first;
  double hi = CGAL::to_interval(upper).second;
  const auto compare = kernel.compare_1_object();
  const auto compare_to = [&](double d) { return compare(t, Root(Bound(d))); };
  constexpr double inf = std::numeric_limits<double>::infinity();
  while (std::nextafter(lo, inf) < hi) {  // step over the (at most two) doubles inside
    const double mid = std::nextafter(lo, inf);
    const CGAL::Comparison_result c = compare_to(mid);
    if (c == CGAL::EQUAL) return {mid, mid};
    if (c == CGAL::SMALLER)
      hi = mid;
    else
      lo = mid;
  }
  if (compare_to(lo) == CGAL::EQUAL) return {lo, lo};
  if (compare_to(hi) == CGAL::EQUAL) return {hi, hi};
  return {lo, hi};
}

std::size_t coefficient_bits(const IntegerPoly& p) {
  std::size_t bits = 0;
  for (int i = 0; i <= CGAL::degree(p); ++i) bits = std::max(bits, static_cast<std::size_t>(p[i].bit_size()));
  return bits;
}

}  // namespace exactccd::exact::algebraic
