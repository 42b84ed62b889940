// The minimum-separation families (separation_families.hpp: the construction and its claims).
#include "generators/separation_families.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "io/benchmark_csv.hpp"  // nearest_double, exact_double

namespace exactccd::separation_families {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// ---- the constructions of every kind -------------------------------------------------------
// In-plane coordinates at the contact, in units of the scale: (u, v) in space, (u) in the
// plane. For `pass`, A's near points at u = 0 lead; B's near feature lies in u >= 0 touching
// u = 0 there. Bits of `near`: point i of the kind (A's points first).
using M = Motion;

std::vector<Construction> constructions(kinds::VertexFace) {  // p | a b c
  return {{"vf_sep_face_enter", M::pass, 0b1111, {{{0, 1}, {0, -2}, {0, 2}, {4, 0}}}},
          {"vf_sep_face_corner_enter", M::pass, 0b1111, {{{0, 0}, {0, 0}, {4, -2}, {4, 2}}}},
          {"vf_sep_edge_cross", M::pass, 0b0111, {{{0, 1}, {0, -2}, {0, 2}, {3, 0}}}},
          {"vf_sep_edge_end_cross", M::pass, 0b0111, {{{0, 2}, {0, -2}, {0, 2}, {3, 0}}}},
          {"vf_sep_vertex_cross", M::pass, 0b0011, {{{0, 0}, {0, 0}, {3, -2}, {3, 2}}}},
          {"vf_sep_face_approach", M::approach, 0b1111, {{{1, 1}, {0, 0}, {4, 0}, {0, 4}}}},
          {"vf_sep_edge_approach", M::approach, 0b0111, {{{2, 0}, {0, 0}, {4, 0}, {0, 4}}}},
          {"vf_sep_face_leave", M::leave, 0b1111, {{{1, 1}, {0, 0}, {4, 0}, {0, 4}}}},
          {"vf_sep_vertex_leave", M::leave, 0b0011, {{{0, 0}, {0, 0}, {4, 0}, {0, 4}}}},
          {"vf_sep_face_slide", M::slide, 0b1111, {{{1, 1}, {0, 0}, {4, 0}, {0, 4}}}}};
}

std::vector<Construction> constructions(kinds::EdgeEdge) {  // a0 a1 | b0 b1
  return {{"ee_sep_parallel_cross", M::pass, 0b1111, {{{0, -2}, {0, 2}, {0, -1}, {0, 3}}}},
          {"ee_sep_collinear_enter", M::pass, 0b1111, {{{-4, 0}, {0, 0}, {0, 0}, {3, 0}}}},
          {"ee_sep_endpoint_enter", M::pass, 0b1111, {{{-4, 1}, {0, 1}, {0, -2}, {0, 3}}}},
          {"ee_sep_endpoint_cross", M::pass, 0b1110, {{{-4, 1}, {0, 1}, {0, -2}, {0, 3}}}},
          {"ee_sep_endpoints_cross", M::pass, 0b0110, {{{-3, 2}, {0, 0}, {0, 0}, {2, -3}}}},
          {"ee_sep_cross_approach", M::approach, 0b1111, {{{-2, 0}, {2, 0}, {0, -2}, {0, 2}}}},
          {"ee_sep_parallel_approach", M::approach, 0b1111, {{{-2, 0}, {2, 0}, {-1, 0}, {3, 0}}}},
          {"ee_sep_endpoint_approach", M::approach, 0b1110, {{{-3, 1}, {0, 0}, {0, -2}, {0, 2}}}},
          {"ee_sep_cross_leave", M::leave, 0b1111, {{{-2, 0}, {2, 0}, {0, -2}, {0, 2}}}},
          {"ee_sep_cross_slide", M::slide, 0b1111, {{{-2, 0}, {2, 0}, {0, -2}, {0, 2}}}}};
}

std::vector<Construction> constructions(kinds::PointEdge) {  // p | a b
  return {{"pe_sep_interior_cross", M::pass, 0b111, {{{0, 1}, {0, -2}, {0, 2}}}},
          {"pe_sep_end_cross", M::pass, 0b111, {{{0, 2}, {0, -2}, {0, 2}}}},
          {"pe_sep_vertex_cross", M::pass, 0b011, {{{0, 0}, {0, 0}, {3, 1}}}},
          {"pe_sep_collinear_enter", M::pass, 0b111, {{{0, 0}, {0, 0}, {4, 0}}}},
          {"pe_sep_interior_approach", M::approach, 0b111, {{{1, 0}, {0, 0}, {4, 0}}}},
          {"pe_sep_interior_leave", M::leave, 0b111, {{{1, 0}, {0, 0}, {4, 0}}}},
          {"pe_sep_slide", M::slide, 0b111, {{{1, 0}, {0, 0}, {4, 0}}}}};
}

std::vector<Construction> constructions(kinds::PointPoint) {  // p | q
  return {{"pp_sep_cross", M::pass, 0b11, {{{0, 0}, {0, 0}}}},
          {"pp_sep_approach", M::approach, 0b11, {{{0, 0}, {0, 0}}}},
          {"pp_sep_leave", M::leave, 0b11, {{{0, 0}, {0, 0}}}},
          {"pp_sep_slide", M::slide, 0b11, {{{0, 0}, {0, 0}}}}};
}

std::vector<Construction> constructions(kinds::EdgeEdge2d) {  // a0 a1 | b0 b1, (u) only
  return {{"ee2_sep_collinear_enter", M::pass, 0b1111, {{{-4}, {0}, {0}, {3}}}},
          {"ee2_sep_endpoint_enter", M::pass, 0b0111, {{{-4}, {0}, {0}, {2}}}},
          {"ee2_sep_endpoint_slide_in", M::pass, 0b1110, {{{-3}, {0}, {0}, {3}}}},
          {"ee2_sep_endpoints_cross", M::pass, 0b0110, {{{-3}, {0}, {0}, {2}}}},
          {"ee2_sep_parallel_approach", M::approach, 0b1111, {{{-2}, {2}, {-1}, {3}}}},
          {"ee2_sep_endpoint_approach", M::approach, 0b1110, {{{-2}, {0}, {-1}, {3}}}},
          {"ee2_sep_parallel_leave", M::leave, 0b1111, {{{-2}, {2}, {-1}, {3}}}},
          {"ee2_sep_parallel_slide", M::slide, 0b1111, {{{-2}, {2}, {-1}, {3}}}}};
}

std::vector<Construction> constructions(kinds::PointEdge2d) {  // p | a b
  return {{"pe2_sep_enter", M::pass, 0b111, {{{0}, {0}, {4}}}},
          {"pe2_sep_vertex_cross", M::pass, 0b011, {{{0}, {0}, {3}}}},
          {"pe2_sep_interior_approach", M::approach, 0b111, {{{1}, {0}, {4}}}},
          {"pe2_sep_interior_leave", M::leave, 0b111, {{{1}, {0}, {4}}}},
          {"pe2_sep_slide", M::slide, 0b111, {{{1}, {0}, {4}}}}};
}

std::vector<Construction> constructions(kinds::PointPoint2d) {  // p | q
  return {{"pp2_sep_cross", M::pass, 0b11, {{{0}, {0}}}},
          {"pp2_sep_approach", M::approach, 0b11, {{{0}, {0}}}},
          {"pp2_sep_leave", M::leave, 0b11, {{{0}, {0}}}},
          {"pp2_sep_slide", M::slide, 0b11, {{{0}, {0}}}}};
}

// ---- one instance ----------------------------------------------------------------------------

/// The local frame: per row (the points at t0, then at t1), (u, v, n) in space, (u, n, 0) in
/// the plane.
using Local = std::array<std::array<double, 3>, 8>;

/// Everything an instance draws from its placement seed (not from k or the direction).
struct Draw {
  int scale = 0;          ///< S = 2^scale: the construction's size
  int speed = 0;          ///< W = 2^speed S: the in-plane speed of `pass` and `slide`
  int contact = 0;        ///< the contact time: 0 at tmax, 1..7 at tmax j / 8, 8 at 0
  bool perturb_time = false;  ///< perturb the contact time (pass, approach), else the gap
  int rate = 0;           ///< approach and leave: the gap changes by 2^-rate g over the step
  std::array<int, 4> rise{};  ///< how far the points off the near planes are, in units
  std::array<int, 3> axes{0, 1, 2};
  std::array<bool, 3> flip{};
  std::array<int, 2> in_plane_scale{};        ///< 2^e per in-plane axis
  std::array<int, 3> shift{}, shift_exp{};    ///< translation m 2^e per axis
  std::array<int, 3> drift{}, drift_exp{};    ///< common velocity m 2^e per axis
};

Draw draw_placement(int dimension, std::mt19937_64& rng) {
  std::uniform_int_distribution<int> coin(0, 1), quarter(0, 3), mild(-8, 8), wide(-60, 60), speed(-2, 3),
      contact(0, 9), rate(-3, 3), rise(1, 4), axis_scale(-4, 4), small(-8, 8), exponent(-30, 30);
  Draw d;
  d.scale = quarter(rng) == 0 ? wide(rng) : mild(rng);
  d.speed = speed(rng);
  d.contact = std::min(contact(rng), 8);  // at tmax twice as often
  d.perturb_time = coin(rng) == 1;
  d.rate = rate(rng);
  for (int& r : d.rise) r = rise(rng);
  std::shuffle(d.axes.begin(), d.axes.begin() + dimension, rng);
  for (bool& f : d.flip) f = coin(rng) == 1;
  for (int& e : d.in_plane_scale) e = quarter(rng) == 0 ? axis_scale(rng) : 0;
  for (int a = 0; a < 3; ++a) {
    d.shift[a] = small(rng);
    d.shift_exp[a] = d.scale + exponent(rng);
    d.drift[a] = quarter(rng) == 0 ? small(rng) : 0;
    d.drift_exp[a] = d.scale + exponent(rng);
  }
  return d;
}

/// x (1 + sign 2^-k) rounded to the nearest double, at least one ulp from x in that direction;
/// x itself when that leaves the finite doubles or crosses zero.
double perturbed(double x, int k, int sign) {
  const mpq_class scaled = mpq_class(x) * (1 + sign * (mpq_class(1) >> k));
  double y = io::nearest_double(scaled);
  if (y == x) y = std::nextafter(x, sign > 0 ? kInf : -kInf);
  return std::isfinite(y) && y >= 0 ? y : x;
}

/// The gap and the contact time of an instance (before rounding the motion).
struct Targets {
  double gap = 0, contact = 0;
};

Targets targets(const Construction& c, const Draw& draw, const CcdParams& p, int k, bool toward) {
  Targets t{p.min_distance, p.tmax};
  if (draw.contact == 8) t.contact = 0;
  else if (draw.contact > 0) t.contact = io::nearest_double(mpq_class(p.tmax) * draw.contact / 8);
  if (k == kUnperturbed) return t;
  // A gap that falls through d reaches it by tmax however it is perturbed unless it does so at
  // tmax: the perturbations of `approach` start from a contact at tmax.
  if (c.motion == Motion::approach) t.contact = p.tmax;
  // At d = 0 an approaching gap can only reach 0 at t = 1 (it must not go below): nothing to move.
  const bool can_move_time = c.motion == Motion::pass || (c.motion == Motion::approach && !p.contact_only());
  const bool time = can_move_time && (draw.perturb_time || (p.contact_only() && toward));
  if (time) {
    t.contact = perturbed(p.tmax, k, toward ? -1 : 1);  // toward: before tmax
  } else if (!p.contact_only()) {
    t.gap = perturbed(p.min_distance, k, toward ? -1 : 1);  // toward: closer than d
  } else if (!toward) {
    t.gap = std::ldexp(1.0, draw.scale - k);
  }
  return t;
}

/// The gap at t = 0 and t = 1 (h0, h1 of the claim) for the motion, never negative: a gap g
/// reached at the contact time, changing by g 2^-rate over the step (the rate lowered until the
/// gap stays >= 0); a zero gap is approached from d (from W when d = 0) and reached at t = 1.
std::pair<double, double> gaps(const Construction& c, const Draw& draw, const Targets& t, double d) {
  const double w = std::ldexp(1.0, draw.scale + draw.speed);
  if (c.motion == Motion::pass || c.motion == Motion::slide) return {t.gap, t.gap};
  if (t.gap == 0) return {c.motion == Motion::approach ? (d > 0 ? d : w) : 0.0, c.motion == Motion::approach ? 0.0 : w};
  const mpq_class g(t.gap), tc(t.contact);
  int rate = draw.rate;
  while (c.motion == Motion::approach && tc < 1 && (mpq_class(std::ldexp(1.0, -rate)) * (1 - tc)) > 1) ++rate;
  const mpq_class v(std::ldexp(t.gap, -rate));
  if (c.motion == Motion::leave) return {t.gap, io::nearest_double(g + v)};
  return {io::nearest_double(g + v * tc), io::nearest_double(g - v * (1 - tc))};
}

/// h + rise R rounded, R a power of two at least S and above h: strictly above h.
double above(double h, int rise, int scale) {
  const int e = h > 0 ? std::max(scale, std::ilogb(h) + 1) : scale;
  return io::nearest_double(mpq_class(h) + mpq_class(std::ldexp(rise, e)));
}

Local local_rows(const Family& f, const Draw& draw, const Targets& t, std::pair<double, double> h) {
  const Construction& c = *f.construction;
  const int n = f.dimension - 1;  // the normal axis
  const double s = std::ldexp(1.0, draw.scale), w = std::ldexp(1.0, draw.scale + draw.speed);
  Local r{};
  for (int tau = 0; tau < 2; ++tau) {
    const double gap = tau == 0 ? h.first : h.second;
    for (int i = 0; i < f.points; ++i) {
      std::array<double, 3>& x = r[static_cast<std::size_t>(tau * f.points + i)];
      const bool in_a = i < f.first_points, near = (c.near >> i) & 1;
      for (int j = 0; j < n; ++j) x[j] = c.at_contact[i][j] * s;
      if (c.motion == Motion::pass && in_a) x[0] = io::nearest_double(mpq_class(x[0]) + (tau - mpq_class(t.contact)) * w);
      if (c.motion == Motion::slide) x[0] += tau * w;  // exact: small integers times 2^scale
      x[n] = in_a ? (near ? gap : above(gap, draw.rise[i], draw.scale)) : (near ? 0.0 : -draw.rise[i] * s);
    }
  }
  return r;
}

Claim claim_of(const Construction& c, const CcdParams& p, const Targets& t, std::pair<double, double> h,
               int scale, int speed) {
  Claim out;
  out.motion = c.motion;
  out.h0 = h.first;
  out.h1 = h.second;
  const mpq_class d(p.min_distance), tmax(p.tmax);
  if (c.motion == Motion::pass) {
    // The leading near points of A: u = 0 at the contact, rounded alike.
    const double w = std::ldexp(1.0, scale + speed);
    const mpq_class x0(io::nearest_double(-mpq_class(t.contact) * w));
    const mpq_class x1(io::nearest_double((1 - mpq_class(t.contact)) * w));
    if (x0 != x1) out.contact = mpq_class(-x0 / (x1 - x0));
    else if (x0 == 0) out.contact = mpq_class(0);
    const bool meets = out.contact && *out.contact <= tmax;
    if (out.h0 > d) out.expected = false;
    else if (meets || out.h0 == d) out.expected = meets;
    out.minimum_is_d = out.h0 == d && meets;
    return out;
  }
  const mpq_class at_tmax = out.h0 + (out.h1 - out.h0) * tmax;
  if (out.h0 <= d) out.contact = mpq_class(0);
  else if (out.h1 < out.h0) out.contact = mpq_class((out.h0 - d) / (out.h0 - out.h1));
  out.expected = std::min(out.h0, at_tmax) <= d;
  out.minimum_is_d = std::min(out.h0, at_tmax) == d;
  return out;
}

/// Replaces column `axis` of r by f(value, row) when every new value is exactly a double.
template <class F>
void map_column_if_exact(Local& r, int rows, int axis, F&& f) {
  std::array<double, 8> out{};
  for (int i = 0; i < rows; ++i) {
    const std::optional<double> x = io::exact_double(f(mpq_class(r[i][axis]), i));
    if (!x) return;
    out[i] = *x;
  }
  for (int i = 0; i < rows; ++i) r[i][axis] = out[i];
}

/// The placement: in-plane scales, translations, a common velocity, reflections and an axis
/// permutation, each applied to an axis only where it keeps every coordinate exact.
Rows placed(const Family& f, const Draw& draw, Local r) {
  const int rows = 2 * f.points;
  for (int a = 0; a < f.dimension; ++a) {
    if (a < f.dimension - 1 && draw.in_plane_scale[a] != 0) {
      const mpq_class factor(std::ldexp(1.0, draw.in_plane_scale[a]));
      map_column_if_exact(r, rows, a, [&](const mpq_class& x, int) { return mpq_class(x * factor); });
    }
    const mpq_class shift(std::ldexp(draw.shift[a], draw.shift_exp[a]));
    map_column_if_exact(r, rows, a, [&](const mpq_class& x, int) { return mpq_class(x + shift); });
    const mpq_class drift(std::ldexp(draw.drift[a], draw.drift_exp[a]));
    map_column_if_exact(r, rows, a, [&](const mpq_class& x, int i) {
      return mpq_class(i >= f.points ? x + drift : x);
    });
  }
  Rows out{};
  for (int i = 0; i < rows; ++i) {
    std::array<double, 3> x{};
    for (int a = 0; a < f.dimension; ++a) x[draw.axes[a]] = draw.flip[a] ? -r[i][a] : r[i][a];
    out[i] = {x[0], x[1], x[2]};
  }
  return out;
}

template <class Kind>
void add_families(std::vector<Family>& out) {
  static const std::vector<Construction> list = constructions(Kind{});
  for (const Construction& c : list)
    out.push_back({c.name, Kind::name, Kind::points, Kind::first_points, Kind::dimension, &c});
}

}  // namespace

const char* motion_name(Motion m) {
  switch (m) {
    case Motion::pass: return "pass";
    case Motion::approach: return "approach";
    case Motion::leave: return "leave";
    case Motion::slide: return "slide";
  }
  return "?";
}

const std::vector<Family>& all_families() {
  static const std::vector<Family> families = [] {
    std::vector<Family> out;
    kinds::for_each_kind([&](auto kind) { add_families<decltype(kind)>(out); });
    return out;
  }();
  return families;
}

const Family* find_family(const std::string& name) {
  for (const Family& f : all_families())
    if (f.name == name) return &f;
  return nullptr;
}

Instance make(const Family& family, const CcdParams& params, int k, bool toward, std::uint64_t placement_seed) {
  std::mt19937_64 rng(placement_seed);
  const Draw draw = draw_placement(family.dimension, rng);
  const Construction& c = *family.construction;
  const Targets t = targets(c, draw, params, k, toward);
  const std::pair<double, double> h = gaps(c, draw, t, params.min_distance);
  Instance out;
  out.rows = placed(family, draw, local_rows(family, draw, t, h));
  out.claim = claim_of(c, params, t, h, draw.scale, draw.speed);
  return out;
}

Instance random_instance(const std::vector<const Family*>& pool, const CcdParams& params, std::mt19937_64& rng) {
  if (pool.empty()) throw std::invalid_argument("separation_families::random_instance: no family");
  std::uniform_int_distribution<std::size_t> which(0, pool.size() - 1);
  std::uniform_int_distribution<int> k(kUnperturbed, 60), coin(0, 1);
  const Family& f = *pool[which(rng)];
  const int kk = k(rng);
  const bool toward = coin(rng) == 1;
  return make(f, params, kk, toward, rng());
}

Rows random_near(int points, int dimension, const CcdParams& params, std::mt19937_64& rng) {
  std::uniform_int_distribution<int> grid(-4, 4), spread(-3, 3), coin(0, 1), edit(0, 2);
  std::uniform_int_distribution<int> point(0, points - 1), axis(0, dimension - 1);
  const int base = !params.contact_only() ? std::ilogb(params.min_distance) : 0;
  const int e = std::clamp(base + spread(rng), -1074, 1000);
  Rows r{};
  for (int i = 0; i < 2 * points; ++i) {
    double x[3] = {0, 0, 0};
    for (int a = 0; a < dimension; ++a) x[a] = std::ldexp(grid(rng), e);
    r[i] = {x[0], x[1], x[2]};
  }
  for (int i = 0; i < points; ++i)
    if (coin(rng)) r[points + i] = r[i];  // a static point
  const int i = point(rng), j = point(rng), a = axis(rng);
  switch (edit(rng)) {
    case 0:  // a repeated point (a degenerate primitive, or shared by both)
      r[j] = r[i];
      r[points + j] = r[points + i];
      break;
    case 1:  // one coordinate of every point flattened: coplanar (collinear in the plane)
      for (int row = 0; row < 2 * points; ++row) (a == 0 ? r[row].x : a == 1 ? r[row].y : r[row].z) = 0;
      break;
    default:  // a point's position copied from the other time
      r[points + i] = r[i];
      break;
  }
  return r;
}

}  // namespace exactccd::separation_families
