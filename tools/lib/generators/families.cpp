// The degenerate families. Each base configuration is written in a local frame with small
// exact coordinates; d = 2^-k is the perturbation (0 when unperturbed), applied towards or
// away from contact. The comment on each states the answer by construction and, when it
// collides, the earliest contact time (TOI). Then an exact symmetry (axis permutation, sign
// flips), a power-of-two scale and an integer offset place it randomly; the answer is kept
// only if every coordinate stayed exact (checked with TwoSum). make_wide() places it by
// per-axis scales over the whole double range instead (see the comment above it).
#include "generators/families.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>

namespace exactccd::families {

KnownToi rational_toi(const mpq_class& r) { return {{-r, mpq_class(1)}, r, r}; }

namespace {

int sign_of(const mpq_class& x) { return sgn(x); }

mpq_class evaluate(const std::vector<mpq_class>& polynomial, const mpq_class& t) {
  mpq_class v = 0;
  for (auto c = polynomial.rbegin(); c != polynomial.rend(); ++c) v = v * t + *c;
  return v;
}

}  // namespace

bool is_tightest_enclosure(const KnownToi& known, const TimeInterval& toi) {
  if (!std::isfinite(toi.lo) || !std::isfinite(toi.hi) || toi.lo > toi.hi) return false;
  const mpq_class lo(toi.lo), hi(toi.hi);
  if (known.from == known.to) {  // the rational time r = from
    const mpq_class& r = known.from;
    if (toi.lo == toi.hi) return lo == r;
    return toi.hi == std::nextafter(toi.lo, std::numeric_limits<double>::infinity()) && lo < r && r < hi;
  }
  // The only root of the polynomial in [from, to], simple: the sign at from holds before it,
  // the sign at to after it.
  const int before = sign_of(evaluate(known.polynomial, known.from));
  const int after = sign_of(evaluate(known.polynomial, known.to));
  if (before == 0 || after != -before) return false;  // not an isolating interval
  if (lo < known.from || hi > known.to) return false;
  const int at_lo = sign_of(evaluate(known.polynomial, lo));
  if (toi.lo == toi.hi) return at_lo == 0;
  return toi.hi == std::nextafter(toi.lo, std::numeric_limits<double>::infinity()) && at_lo == before &&
         sign_of(evaluate(known.polynomial, hi)) == after;
}

std::string to_string(const KnownToi& known) {
  if (known.from == known.to) return known.from.get_str();
  std::string out = "root of [";
  for (std::size_t i = 0; i < known.polynomial.size(); ++i)
    out += (i ? ", " : "") + known.polynomial[i].get_str();
  return out + "] in [" + known.from.get_str() + ", " + known.to.get_str() + "]";
}

std::optional<std::string> disagreement(const Instance& instance, bool collides,
                                        const std::optional<TimeInterval>& toi) {
  if (!instance.expected) return std::nullopt;
  const auto answer = [](bool c) { return std::string(c ? "collides" : "no collision"); };
  if (collides != *instance.expected || toi.has_value() != *instance.expected)
    return "constructed: " + answer(*instance.expected) + "; given: " + answer(collides) + ", TOI " +
           (toi ? "given" : "none");
  if (instance.toi && toi && !is_tightest_enclosure(*instance.toi, *toi)) {
    char interval[96];
    std::snprintf(interval, sizeof interval, "[%a, %a]", toi->lo, toi->hi);
    return std::string("the TOI ") + interval + " is not the tightest enclosure of the constructed TOI " +
           to_string(*instance.toi);
  }
  return std::nullopt;
}

namespace {

using V = Vec3;

VertexFaceQuery vf(V p0, V a0, V b0, V c0, V p1, V a1, V b1, V c1) {
  return {p0, a0, b0, c0, p1, a1, b1, c1};
}
EdgeEdgeQuery ee(V a00, V a10, V b00, V b10, V a01, V a11, V b01, V b11) {
  return {a00, a10, b00, b10, a01, a11, b01, b11};
}

// The unit triangle (0,0,0), (1,0,0), (0,1,0), static, and the static edge [-1, 1] on x.
VertexFaceQuery point_vs_triangle(V p0, V p1) {
  return vf(p0, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, p1, {0, 0, 0}, {1, 0, 0}, {0, 1, 0});
}
EdgeEdgeQuery edge_vs_axis(V b0_t0, V b1_t0, V b0_t1, V b1_t1) {
  return ee({-1, 0, 0}, {1, 0, 0}, b0_t0, b1_t0, {-1, 0, 0}, {1, 0, 0}, b0_t1, b1_t1);
}

/// A base configuration: the answer and, when it is "collides", the TOI.
using Base = Instance;

/// `when` if the condition holds, else "unknown".
std::optional<bool> known_if(bool condition, bool when) {
  return condition ? std::optional<bool>(when) : std::nullopt;
}

/// The configuration with its answer; `toi` is kept only where the answer is "collides".
Base base(AnyQuery query, std::optional<bool> expected, const KnownToi& toi) {
  Base b{std::move(query), expected, std::nullopt};
  if (expected == true) b.toi = toi;
  return b;
}

mpq_class half() { return mpq_class(1, 2); }

// --- vertex-face --------------------------------------------------------------------------
// The triangle is static in z = 0, so contact needs p_z = 0 (V is a positive multiple of p_z).
// p falls through z = 0 at t = 1/2 at (-s d, -s d): a vertex hit for d = 0; s = +1 (away)
// puts it outside both edges at a, s = -1 (toward) inside the triangle while 2d <= 1.
// TOI 1/2 (p_z = 1 - 2t vanishes only there).
Base vertex_through_vertex(double d, bool toward) {
  const double s = toward ? -d : d;
  return base(point_vs_triangle({-s, -s, 1}, {-s, -s, -1}), toward ? known_if(d <= 0.5, true) : d == 0,
              rational_toi(half()));
}
// Through the edge ab at (1/2, -s d): outside for away, inside for toward while d <= 1/2.
// TOI 1/2.
Base vertex_through_edge(double d, bool toward) {
  const double s = toward ? -d : d;
  return base(point_vs_triangle({0.5, -s, 1}, {0.5, -s, -1}), toward ? known_if(d <= 0.5, true) : d == 0,
              rational_toi(half()));
}
// Everything in z = 0 (coplanar for all t) but p at height e: p slides (2 - 3t, 1/4) into
// the triangle. Any e != 0 keeps p off the plane (V constant nonzero): no contact either way.
// e = 0: p enters through bc (x + y <= 1) when 2 - 3t = 3/4: TOI 5/12.
Base coplanar_sliding_vf(double d, bool toward) {
  const double e = toward ? -d : d;
  return base(point_vs_triangle({2, 0.25, e}, {-1, 0.25, e}), d == 0, rational_toi(mpq_class(5, 12)));
}
// Grazing: V = (t - 1/2)^2 + e (catalogue's vf_grazing with p raised by e). e > 0 (away):
// V > 0, no contact. e < 0 (toward, |e| <= 1/4): first root t* = 1/2 - sqrt(|e|), where
// p = a + (1/4)(b - a) + (1/2 - sqrt(|e|)/2)(c - a): inside. TOI t* (e = 0: the double root
// 1/2): rational when d is an even power of two, else the root of t^2 - t + 1/4 - d in
// [0, 1/2] (irrational, simple; the polynomial is 1/4 - d > 0 at 0 and -d < 0 at 1/2).
Base grazing_vf(double d, bool toward) {
  const double e = toward ? -d : d;
  const VertexFaceQuery q = vf({0.25, 0.25, 0.5 + e}, {0, 0, 0}, {1, 0, 0}, {0, 1, 1},
                               {0.25, 0.75, -0.5 + e}, {0, 0, 0}, {1, 0, 0}, {0, 1, -1});
  const std::optional<bool> expected = toward ? known_if(d <= 0.25, true) : d == 0;
  int exponent = 0;
  std::frexp(d, &exponent);  // d = 2^(exponent - 1) when d != 0
  if (d == 0 || (exponent - 1) % 2 == 0) {  // sqrt(d) = 2^((exponent - 1) / 2), exactly
    const mpq_class root = d == 0 ? mpq_class(0) : mpq_class(std::ldexp(1.0, (exponent - 1) / 2));
    return base(q, expected, rational_toi(mpq_class(half() - root)));
  }
  const mpq_class m(d);
  return base(q, expected, {{mpq_class(mpq_class(1, 4) - m), mpq_class(-1), mpq_class(1)}, mpq_class(0), half()});
}
// p starts at height e above the interior and rises: contact at t = 0 only if e = 0; e < 0
// (toward) starts below and crosses the interior at t = -e / (1 - e) > 0: TOI d / (1 + d)
// (0 for d = 0).
Base contact_at_t0_vf(double d, bool toward) {
  const double e = toward ? -d : d;
  const mpq_class m(d);
  return base(point_vs_triangle({0.25, 0.25, e}, {0.25, 0.25, 1}), toward || d == 0,
              rational_toi(mpq_class(m / (1 + m))));
}
// p falls from 1 to height e at t = 1: contact at t = 1 iff e <= 0; p_z = 1 - t (1 - e)
// vanishes at TOI 1 / (1 + d) for e = -d.
Base contact_at_t1_vf(double d, bool toward) {
  const double e = toward ? -d : d;
  return base(point_vs_triangle({0.25, 0.25, 1}, {0.25, 0.25, e}), toward || d == 0,
              rational_toi(mpq_class(1 / (1 + mpq_class(d)))));
}
// The collinear triangle (0,0,0), (1,0,0), (2,0,0) (its hull: [0, 2] on x); p falls through
// z = 0 at (1/2, e): on the hull only if e = 0, at TOI 1/2.
Base degenerate_triangle(double d, bool toward) {
  const double e = toward ? -d : d;
  return base(vf({0.5, e, 1}, {0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0.5, e, -1}, {0, 0, 0}, {1, 0, 0}, {2, 0, 0}),
              d == 0, rational_toi(half()));
}
// Nothing moves; p rests at height e over the interior: contact only if e = 0, TOI 0.
Base nearly_static_vf(double d, bool toward) {
  const double e = toward ? -d : d;
  return base(point_vs_triangle({0.25, 0.25, e}, {0.25, 0.25, e}), d == 0, rational_toi(0));
}

// --- edge-edge ----------------------------------------------------------------------------
// b (parallel to y) falls through z = 0 at t = 1/2 at x = 1 + s d: through a's endpoint for
// d = 0; toward (x < 1) crosses a, away (x > 1) misses it. TOI 1/2.
Base edge_through_endpoint(double d, bool toward) {
  const double x = 1 + (toward ? -d : d);
  return base(edge_vs_axis({x, -1, 1}, {x, 1, 1}, {x, -1, -1}, {x, 1, -1}), toward || d == 0,
              rational_toi(half()));
}
// a = [0, 1] on x; b = [1/2, 3/2] parallel to a at height e, sweeping y = 1 - 2t: the lines
// are parallel (always coplanar); at e = 0 they become collinear and overlap at t = 1/2
// (TOI; b is on the line y = 0 only then).
Base parallel_edges(double d, bool toward) {
  const double e = toward ? -d : d;
  return base(ee({0, 0, 0}, {1, 0, 0}, {0.5, 1, e}, {1.5, 1, e}, {0, 0, 0}, {1, 0, 0}, {0.5, -1, e},
                 {1.5, -1, e}),
              d == 0, rational_toi(half()));
}
// Static collinear a = [0, 1], b = [1 + s d, 2]: toward overlaps, away leaves a gap. TOI 0.
Base collinear_edges(double d, bool toward) {
  const double x = 1 + (toward ? -d : d);
  return base(ee({0, 0, 0}, {1, 0, 0}, {x, 0, 0}, {2, 0, 0}, {0, 0, 0}, {1, 0, 0}, {x, 0, 0}, {2, 0, 0}),
              toward || d == 0, rational_toi(0));
}
// Grazing (catalogue's ee_grazing) at xb = 1 + s d: V = -2 (t - 1/2)^2, contact only at
// t = 1/2 where b crosses the x axis at xb: inside a for toward, outside for away. TOI 1/2.
Base grazing_ee(double d, bool toward) {
  const double xb = 1 + (toward ? -d : d);
  return base(ee({-1, 0, 0}, {1, 0, 0}, {xb, -1, -0.5}, {xb, 0.5, 0.5}, {-1, 0, 0}, {1, 0, 0},
                 {xb, -1, 0.5}, {xb, 1.5, -0.5}),
              toward || d == 0, rational_toi(half()));
}
// b crossing a at height e rises to 1: contact at t = 0 iff e = 0; toward starts below and
// reaches z = 0 at TOI d / (1 + d).
Base contact_at_t0_ee(double d, bool toward) {
  const double e = toward ? -d : d;
  const mpq_class m(d);
  return base(edge_vs_axis({0, -1, e}, {0, 1, e}, {0, -1, 1}, {0, 1, 1}), toward || d == 0,
              rational_toi(mpq_class(m / (1 + m))));
}
// b falls from 1 to height e at t = 1: z = 1 - t (1 - e) vanishes at TOI 1 / (1 + d) for
// e = -d (1 for d = 0).
Base contact_at_t1_ee(double d, bool toward) {
  const double e = toward ? -d : d;
  return base(edge_vs_axis({0, -1, 1}, {0, 1, 1}, {0, -1, e}, {0, 1, e}), toward || d == 0,
              rational_toi(mpq_class(1 / (1 + mpq_class(d)))));
}
// b is a point falling through z = 0 at (1/2, e): on a only if e = 0, at TOI 1/2.
Base zero_length_edge(double d, bool toward) {
  const double e = toward ? -d : d;
  return base(edge_vs_axis({0.5, e, 1}, {0.5, e, 1}, {0.5, e, -1}, {0.5, e, -1}), d == 0,
              rational_toi(half()));
}
// Nothing moves; b crosses over a at height e: contact only if e = 0, TOI 0.
Base nearly_static_ee(double d, bool toward) {
  const double e = toward ? -d : d;
  return base(edge_vs_axis({0, -1, e}, {0, 1, e}, {0, -1, e}, {0, 1, e}), d == 0, rational_toi(0));
}
// In z = 0 for all t: a = [0, 1] on x; b on the line x = 1 + s d slides down y (from
// [2, 3] to [-1, 0]): it reaches y = 0 at t = 2/3, on a iff x <= 1 (x = 1 - d >= 0 for
// toward): TOI 2/3.
Base coplanar_sliding_ee(double d, bool toward) {
  const double x = 1 + (toward ? -d : d);
  return base(ee({0, 0, 0}, {1, 0, 0}, {x, 2, 0}, {x, 3, 0}, {0, 0, 0}, {1, 0, 0}, {x, -1, 0}, {x, 0, 0}),
              toward || d == 0, rational_toi(mpq_class(2, 3)));
}

/// x + o, and whether it is exact (Knuth's TwoSum error term is zero).
double exact_sum(double x, double o, bool& exact) {
  const double s = x + o;
  const double bb = s - x;
  const double err = (x - (s - bb)) + (o - bb);
  exact = exact && err == 0;
  return s;
}

/// Applies an exact symmetry (axis permutation, sign flips), the scale 2^scale and the offset;
/// `exact` turns false if any coordinate was rounded.
template <class Query>
Query place(const Query& q, const std::array<int, 3>& axes, const std::array<double, 3>& signs,
            int scale, const std::array<double, 3>& offset, bool& exact) {
  std::array<Vec3, 8> r = rows(q);
  for (Vec3& p : r) {
    const double c[3] = {p.x, p.y, p.z};
    double out[3];
    for (int k = 0; k < 3; ++k) out[k] = exact_sum(std::ldexp(signs[k] * c[axes[k]], scale), offset[k], exact);
    p = {out[0], out[1], out[2]};
  }
  return from_rows<Query>(r);
}

/// A random placement with offsets of magnitude 2^e, e in [min_offset_exponent,
/// max_offset_exponent], times an integer in [-8, 8].
Instance randomly_placed(const Base& base, std::mt19937_64& rng, int min_offset_exponent,
                         int max_offset_exponent) {
  std::array<int, 3> axes = {0, 1, 2};
  std::shuffle(axes.begin(), axes.end(), rng);
  std::uniform_int_distribution<int> coin(0, 1), scale(-4, 4), offset(-8, 8),
      exponent(min_offset_exponent, max_offset_exponent);
  const std::array<double, 3> signs = {coin(rng) ? 1.0 : -1.0, coin(rng) ? 1.0 : -1.0, coin(rng) ? 1.0 : -1.0};
  std::array<double, 3> shift;
  for (double& o : shift) o = std::ldexp(offset(rng), exponent(rng));
  const int s = scale(rng);
  bool exact = true;
  Instance out;
  std::visit([&](const auto& q) { out.query = place(q, axes, signs, s, shift, exact); }, base.query);
  if (exact) {
    out.expected = base.expected;
    out.toi = base.toi;
  }
  return out;
}

/// How many coordinates differ between two queries, if each differs by exactly +-d; -1 if
/// some coordinate differs by anything else (the perturbation was rounded).
int perturbed_coordinates(const AnyQuery& base, const AnyQuery& moved, double d) {
  const auto a = std::visit([](const auto& q) { return rows(q); }, base);
  const auto b = std::visit([](const auto& q) { return rows(q); }, moved);
  int count = 0;
  for (int i = 0; i < 8; ++i)
    for (const auto& [x, y] : {std::pair{a[i].x, b[i].x}, {a[i].y, b[i].y}, {a[i].z, b[i].z}}) {
      if (x == y) continue;
      if (std::fabs(y - x) != d) return -1;  // nearby doubles: the difference is exact
      ++count;
    }
  return count;
}

/// The configuration in its local frame at (k, toward), its answer and TOI reset where the
/// perturbation was rounded.
template <Base (*Make)(double, bool)>
Instance local(int k, bool toward) {
  const double d = k == kUnperturbed ? 0.0 : std::ldexp(1.0, -k);
  Base base = Make(d, toward);
  if (d != 0) {
    // The construction's answer holds only if every coordinate it perturbs moved by exactly d,
    // as at a coarse d (2^-10) where nothing can round.
    const Base still = Make(0, toward);
    const double coarse = 0x1p-10;
    const int expected_moves = perturbed_coordinates(still.query, Make(coarse, toward).query, coarse);
    if (perturbed_coordinates(still.query, base.query, d) != expected_moves) {
      base.expected.reset();
      base.toi.reset();
    }
  }
  return base;
}

template <Base (*Make)(double, bool), int MinOffsetExponent = 0, int MaxOffsetExponent = 0>
Instance generate(int k, bool toward, std::mt19937_64& rng) {
  return randomly_placed(local<Make>(k, toward), rng, MinOffsetExponent, MaxOffsetExponent);
}

// --- wide placements ------------------------------------------------------------------------
// Why the answer and the TOI survive. Let A(x) = L x + o be an invertible affine map of R^3
// (L = S D P: a permutation with sign flips P, a positive diagonal D of powers of two, shears S
// = I + c e_i e_j^T, i != j, each of determinant 1; o a translation). Applied to all eight
// points it maps every trajectory onto the trajectory of the images:
//     A(x0 + t (x1 - x0)) = A(x0) + t (A(x1) - A(x0)),
// since A preserves affine combinations. For the same reason it maps the closed triangle (the
// convex hull) a(t) b(t) c(t) onto the closed triangle of the images, a closed segment onto a
// closed segment, and, being a bijection, a point lies in a hull (two segments share a point)
// iff the images do. So at every t the transformed query is in contact iff the original is:
// the set of contact times in [0, 1], hence the answer and the earliest time (the TOI), are
// unchanged. Degenerate hulls (a segment, a point) are hulls too, so this covers every family.
// This holds for the exact images; it says nothing about rounded ones, so the images are
// computed in rational arithmetic and an instance is kept only if every image coordinate is
// exactly a double (converted, then converted back with GMP and compared). With powers of two
// as scales, translations m 2^f fitted to each axis's bits, and small dyadic shear
// coefficients, most draws are exact; the others are discarded and redrawn.

using ExactRows = std::array<std::array<mpq_class, 3>, 8>;

/// Exponents of the lowest set bit and of the top bit over the nonzero values of one axis of
/// dyadic rationals; `any` false when every value is 0.
struct AxisBits {
  bool any = false;
  long lo = 0;
  long hi = 0;
};

AxisBits axis_bits(const ExactRows& r, int axis) {
  AxisBits b;
  for (const auto& p : r) {
    const mpq_class& x = p[static_cast<std::size_t>(axis)];
    if (x == 0) continue;
    // x = n / 2^j (canonical form: the denominator of a dyadic rational is 2^j)
    const long j = static_cast<long>(mpz_sizeinbase(x.get_den_mpz_t(), 2)) - 1;
    mpz_class n = abs(x.get_num());
    const long lo = static_cast<long>(mpz_scan1(n.get_mpz_t(), 0)) - j;
    const long hi = static_cast<long>(mpz_sizeinbase(n.get_mpz_t(), 2)) - 1 - j;
    b.lo = b.any ? std::min(b.lo, lo) : lo;
    b.hi = b.any ? std::max(b.hi, hi) : hi;
    b.any = true;
  }
  return b;
}

/// x as a double if it is exactly one (a dyadic rational with at most 53 significant bits,
/// lowest bit >= 2^-1074, below 2^1024), confirmed by converting back with GMP; else nullopt.
std::optional<double> exact_double(const mpq_class& x) {
  if (x == 0) return 0.0;
  if (mpz_popcount(x.get_den_mpz_t()) != 1) return std::nullopt;  // not dyadic
  const long j = static_cast<long>(mpz_sizeinbase(x.get_den_mpz_t(), 2)) - 1;
  mpz_class n = abs(x.get_num());
  const long shift = static_cast<long>(mpz_scan1(n.get_mpz_t(), 0));
  const long lo = shift - j;
  const long hi = static_cast<long>(mpz_sizeinbase(n.get_mpz_t(), 2)) - 1 - j;
  if (hi - lo > 52 || lo < -1074 || hi > 1023) return std::nullopt;
  mpz_class odd = n >> static_cast<mp_bitcnt_t>(shift);
  const double d = std::ldexp(odd.get_d(), static_cast<int>(lo)) * sgn(x);  // odd < 2^53: exact
  if (!std::isfinite(d) || mpq_class(d) != x) return std::nullopt;  // the check, by GMP
  return d;
}

/// Multiplies every value of an axis by 2^e.
void scale_axis(ExactRows& r, int axis, long e) {
  for (auto& p : r) {
    mpq_class& x = p[static_cast<std::size_t>(axis)];
    if (e >= 0) mpq_mul_2exp(x.get_mpq_t(), x.get_mpq_t(), static_cast<mp_bitcnt_t>(e));
    else mpq_div_2exp(x.get_mpq_t(), x.get_mpq_t(), static_cast<mp_bitcnt_t>(-e));
  }
}

long uniform(std::mt19937_64& rng, long lo, long hi) {
  return std::uniform_int_distribution<long>(lo, std::max(lo, hi))(rng);
}

/// One draw of a wide placement of the local rows; nullopt if some image is not a double.
std::optional<std::array<Vec3, 8>> wide_draw(const std::array<Vec3, 8>& local_rows, WideStyle style,
                                             std::mt19937_64& rng) {
  // The exact symmetry.
  std::array<int, 3> axes = {0, 1, 2};
  std::shuffle(axes.begin(), axes.end(), rng);
  std::uniform_int_distribution<int> coin(0, 1);
  const std::array<bool, 3> flip = {coin(rng) == 1, coin(rng) == 1, coin(rng) == 1};
  ExactRows r;
  for (std::size_t i = 0; i < 8; ++i) {
    const double c[3] = {local_rows[i].x, local_rows[i].y, local_rows[i].z};
    for (std::size_t a = 0; a < 3; ++a) {
      r[i][a] = mpq_class(c[axes[a]]);
      if (flip[a]) r[i][a] = -r[i][a];
    }
  }
  // Shears in the local frame (small coordinates: the sums are exact rationals anyway).
  if (style == WideStyle::sheared) {
    static const mpq_class kShear[8] = {mpq_class(1, 2), mpq_class(1), mpq_class(2), mpq_class(3),
                                        mpq_class(-1, 2), mpq_class(-1), mpq_class(-2), mpq_class(-3)};
    for (int n = 1 + coin(rng); n > 0; --n) {
      const int i = static_cast<int>(uniform(rng, 0, 2));
      const int j = (i + 1 + static_cast<int>(uniform(rng, 0, 1))) % 3;
      const mpq_class& c = kShear[uniform(rng, 0, 7)];
      for (auto& p : r) p[static_cast<std::size_t>(i)] += c * p[static_cast<std::size_t>(j)];
    }
  }
  // Per-axis scales 2^e over the whole range where the axis's values stay doubles: the lowest
  // bit at or above 2^-1074, the top bit at or below 2^1023.
  std::array<AxisBits, 3> bits;
  for (int a = 0; a < 3; ++a) bits[static_cast<std::size_t>(a)] = axis_bits(r, a);
  std::array<long, 3> e{};
  for (int a = 0; a < 3; ++a) {
    const AxisBits& b = bits[static_cast<std::size_t>(a)];
    if (b.any) e[static_cast<std::size_t>(a)] = uniform(rng, -1074 - b.lo, 1023 - b.hi);
  }
  if (style == WideStyle::extremes) {
    // One axis at the subnormal end, another at the overflow end (axes holding nonzero values).
    std::array<int, 3> order = {0, 1, 2};
    std::shuffle(order.begin(), order.end(), rng);
    std::vector<int> nonzero;
    for (int a : order)
      if (bits[static_cast<std::size_t>(a)].any) nonzero.push_back(a);
    if (!nonzero.empty()) {
      const auto low = static_cast<std::size_t>(nonzero[0]);
      e[low] = -1074 - bits[low].lo + uniform(rng, 0, 2);
    }
    if (nonzero.size() > 1) {
      const auto high = static_cast<std::size_t>(nonzero[1]);
      e[high] = 1023 - bits[high].hi - uniform(rng, 0, 2);
    }
  }
  for (int a = 0; a < 3; ++a) scale_axis(r, a, e[static_cast<std::size_t>(a)]);
  // Translations m 2^f, |m| <= 8, f from the axis's lowest bit up to 48 bits above it (the sums
  // then need at most 53 bits when the axis spans at most 48); an axis of zeros anywhere.
  if (style == WideStyle::translated || style == WideStyle::sheared) {
    for (int a = 0; a < 3; ++a) {
      if (coin(rng) == 0 && style == WideStyle::sheared) continue;
      const AxisBits b = axis_bits(r, a);
      if (b.any && b.hi - b.lo > 48) continue;  // no room: a translation could not stay exact
      const long f = b.any ? uniform(rng, b.lo, b.lo + 48) : uniform(rng, -1074, 1019);
      long m = uniform(rng, -8, 7);
      if (m >= 0) ++m;  // nonzero
      mpq_class o(m);
      if (f >= 0) mpq_mul_2exp(o.get_mpq_t(), o.get_mpq_t(), static_cast<mp_bitcnt_t>(f));
      else mpq_div_2exp(o.get_mpq_t(), o.get_mpq_t(), static_cast<mp_bitcnt_t>(-f));
      for (auto& p : r) p[static_cast<std::size_t>(a)] += o;
    }
  }
  std::array<Vec3, 8> out;
  for (std::size_t i = 0; i < 8; ++i) {
    const std::optional<double> x = exact_double(r[i][0]), y = exact_double(r[i][1]), z = exact_double(r[i][2]);
    if (!x || !y || !z) return std::nullopt;
    out[i] = {*x, *y, *z};
  }
  return out;
}

}  // namespace

const std::vector<Family>& all_families() {
  constexpr std::string_view vf = kinds::VertexFace::name, ee = kinds::EdgeEdge::name;  // the kinds
  static const std::vector<Family> families = {
      {"vf_vertex_through_vertex", vf, generate<vertex_through_vertex>, local<vertex_through_vertex>},
      {"vf_vertex_through_edge", vf, generate<vertex_through_edge>, local<vertex_through_edge>},
      {"vf_coplanar_sliding", vf, generate<coplanar_sliding_vf>, local<coplanar_sliding_vf>},
      {"vf_grazing", vf, generate<grazing_vf>, local<grazing_vf>},
      {"vf_contact_at_t0", vf, generate<contact_at_t0_vf>, local<contact_at_t0_vf>},
      {"vf_contact_at_t1", vf, generate<contact_at_t1_vf>, local<contact_at_t1_vf>},
      {"vf_degenerate_triangle", vf, generate<degenerate_triangle>, local<degenerate_triangle>},
      {"vf_nearly_static", vf, generate<nearly_static_vf>, local<nearly_static_vf>},
      {"vf_large_offset", vf, generate<vertex_through_edge, 20, 60>, local<vertex_through_edge>},
      {"ee_edge_through_endpoint", ee, generate<edge_through_endpoint>, local<edge_through_endpoint>},
      {"ee_parallel", ee, generate<parallel_edges>, local<parallel_edges>},
      {"ee_collinear", ee, generate<collinear_edges>, local<collinear_edges>},
      {"ee_grazing", ee, generate<grazing_ee>, local<grazing_ee>},
      {"ee_contact_at_t0", ee, generate<contact_at_t0_ee>, local<contact_at_t0_ee>},
      {"ee_contact_at_t1", ee, generate<contact_at_t1_ee>, local<contact_at_t1_ee>},
      {"ee_zero_length_edge", ee, generate<zero_length_edge>, local<zero_length_edge>},
      {"ee_nearly_static", ee, generate<nearly_static_ee>, local<nearly_static_ee>},
      {"ee_coplanar_sliding", ee, generate<coplanar_sliding_ee>, local<coplanar_sliding_ee>},
      {"ee_large_offset", ee, generate<edge_through_endpoint, 20, 60>, local<edge_through_endpoint>},
  };
  return families;
}

const Family* find_family(const std::string& name) {
  for (const Family& f : all_families())
    if (f.name == name) return &f;
  return nullptr;
}

const char* wide_style_name(WideStyle style) {
  switch (style) {
    case WideStyle::axes_only: return "axes_only";
    case WideStyle::extremes: return "extremes";
    case WideStyle::translated: return "translated";
    case WideStyle::sheared: return "sheared";
  }
  return "?";
}

std::optional<Instance> make_wide(const Family& family, int k, bool toward, WideStyle style,
                                  std::mt19937_64& rng) {
  const Instance base = family.local(k, toward);
  const std::array<Vec3, 8> local_rows = std::visit([](const auto& q) { return rows(q); }, base.query);
  constexpr int kDraws = 8;
  for (int draw = 0; draw < kDraws; ++draw) {
    const std::optional<std::array<Vec3, 8>> placed = wide_draw(local_rows, style, rng);
    if (!placed) continue;  // some image is not a double: discarded, never rounded
    Instance out = base;
    std::visit([&](const auto& q) { out.query = from_rows<std::decay_t<decltype(q)>>(*placed); }, base.query);
    return out;
  }
  return std::nullopt;
}

Instance random_instance(std::mt19937_64& rng, const std::vector<const Family*>& pool) {
  std::uniform_int_distribution<std::size_t> pick(0, pool.size() - 1);
  std::uniform_int_distribution<int> k(-1, 60), coin(0, 1);
  return pool[pick(rng)]->make(k(rng), coin(rng) == 1, rng);
}

Instance random_instance(std::mt19937_64& rng) {
  static const std::vector<const Family*> pool = [] {
    std::vector<const Family*> all;
    for (const Family& f : all_families()) all.push_back(&f);
    return all;
  }();
  return random_instance(rng, pool);
}

}  // namespace exactccd::families
