// Fuzzer bytes -> queries biased to degeneracies; the format is in fuzz_input.hpp.
#include "generators/fuzz_input.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <sstream>

#include "generators/catalogue.hpp"
#include "generators/families.hpp"
#include "io/benchmark_csv.hpp"

namespace exactccd::fuzzing {
namespace {

/// Reads bytes in order; past the end every read is 0.
class ByteReader {
 public:
  ByteReader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  std::uint8_t u8() { return pos_ < size_ ? data_[pos_++] : (pos_++, std::uint8_t{0}); }
  std::uint64_t u64() {
    std::uint64_t v = 0;
    for (int i = 0; i < 8; ++i) v |= static_cast<std::uint64_t>(u8()) << (8 * i);
    return v;
  }
  bool done() const { return pos_ >= size_; }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

double& coord(Rows& r, int c) {
  Vec3& p = r[static_cast<std::size_t>(c / 3)];
  return c % 3 == 0 ? p.x : (c % 3 == 1 ? p.y : p.z);
}

double& axis(Vec3& p, int a) { return a == 0 ? p.x : (a == 1 ? p.y : p.z); }

constexpr int kGridScales[16] = {0, 0, -1, -2, -3, -4, -10, -30, -52, -60, -520, -1066, -1072, 20, 52, 996};

constexpr double kSpecialValues[] = {
    0.0,        -0.0,       0x1p-1074, -0x1p-1074, 0x1p-1022,  0x0.fffffffffffffp-1022,
    1e300,      -1e300,     0x1p1000,  1.0,        -1.0,       0.5,
    0x1p53,     0x1p53 + 2, 0x1p-53,   1 + 0x1p-52, 1 - 0x1p-53, 0x1.fffffffffffffp1023};
constexpr std::size_t kSpecialCount = sizeof(kSpecialValues) / sizeof(kSpecialValues[0]);

constexpr double kLineParameters[8] = {-2.0, -1.0, 0.25, 0.75, 1.5, 3.0, 1.0 / 3.0, 2.0 / 3.0};

constexpr int kAxisPermutations[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};

Vec3 lerp(const Vec3& p, const Vec3& q, double s) {
  return {p.x + s * (q.x - p.x), p.y + s * (q.y - p.y), p.z + s * (q.z - p.z)};
}

constexpr int kEditCount = 15;

void apply_edit(Rows& r, std::uint8_t op, std::uint8_t a, std::uint8_t b) {
  switch (op % kEditCount) {
    case 0:  // a shared / repeated vertex
      r[b % 8] = r[a % 8];
      break;
    case 1: {  // a static vertex
      const std::size_t j = a % 4;
      if (b & 1) r[j] = r[j + 4]; else r[j + 4] = r[j];
      break;
    }
    case 2: {  // every point in one axis-aligned plane: coplanar for all t
      const int ax = a % 3;
      const double v = axis(r[b % 8], ax);
      for (Vec3& p : r) axis(p, ax) = v;
      break;
    }
    case 3: {  // a few ulps
      double& x = coord(r, a % 24);
      constexpr int kSteps[8] = {-4, -3, -2, -1, 1, 2, 3, 4};
      const int steps = kSteps[b % 8];
      const double to = steps < 0 ? -std::numeric_limits<double>::infinity()
                                  : std::numeric_limits<double>::infinity();
      for (int s = 0; s < std::abs(steps); ++s) x = std::nextafter(x, to);
      break;
    }
    case 4:  // midpoint: collinear
      r[a % 8] = lerp(r[b % 8], r[(b >> 3) % 8], 0.5);
      break;
    case 5:  // reflection of p through q: collinear, beyond q
      r[a % 8] = lerp(r[b % 8], r[(b >> 3) % 8], 2.0);
      break;
    case 6: {  // power-of-two scale
      const int e = static_cast<int>(a) - 128;
      for (Vec3& p : r) p = {std::ldexp(p.x, e), std::ldexp(p.y, e), std::ldexp(p.z, e)};
      break;
    }
    case 7: {  // power-of-two translation along one axis
      const int ax = a % 3;
      const double shift = std::ldexp(static_cast<double>(static_cast<int>((a / 3) % 17) - 8),
                                      static_cast<int>(b) - 100);
      for (Vec3& p : r) axis(p, ax) += shift;
      break;
    }
    case 8:  // a special value: zeros, subnormals, huge, 2^53 + 2, 1 - 2^-53, ...
      coord(r, a % 24) = kSpecialValues[b % kSpecialCount];
      break;
    case 9:
      std::swap(r[a % 8], r[b % 8]);
      break;
    case 10: {  // mirror
      const int ax = a % 3;
      for (Vec3& p : r) axis(p, ax) = -axis(p, ax);
      break;
    }
    case 11:  // a shared coordinate value
      coord(r, b % 24) = coord(r, a % 24);
      break;
    case 12: {  // permute axes
      const int* perm = kAxisPermutations[a % 6];
      for (Vec3& p : r) {
        const double c[3] = {p.x, p.y, p.z};
        p = {c[perm[0]], c[perm[1]], c[perm[2]]};
      }
      break;
    }
    case 13:  // a point on the line through two others (rounded for 1/3, 2/3: nearly collinear)
      r[a % 8] = lerp(r[b % 8], r[(b >> 3) % 8], kLineParameters[(a >> 3) % 8]);
      break;
    case 14: {  // one axis scaled by 2^e, e in [-1152, 1151]: exponent spreads across axes
      const int ax = a % 3;
      const int e = (static_cast<int>(b) - 128) * 9 + (a / 3) % 9;
      for (Vec3& p : r) axis(p, ax) = std::ldexp(axis(p, ax), e);
      break;
    }
  }
}

int k_from_byte(std::uint8_t b) { return b < 192 ? b % 64 - 1 : 62 + (b - 191) * 16; }

std::uint8_t byte_from_k(int k) {
  if (k <= 62) return static_cast<std::uint8_t>(std::max(k, -1) + 1);
  return static_cast<std::uint8_t>(std::min(191 + (k - 62 + 15) / 16, 255));
}

}  // namespace

const char* mode_name(Mode m) {
  switch (m) {
    case Mode::grid: return "grid";
    case Mode::raw: return "raw";
    case Mode::family: return "family";
    case Mode::catalogue: return "catalogue";
  }
  return "?";
}

Mode mode_of(const std::uint8_t* data, std::size_t size) {
  return size == 0 ? Mode::grid : static_cast<Mode>(data[0] % kModeCount);
}

Rows decode(const std::uint8_t* data, std::size_t size, const KindSources& sources) {
  ByteReader in(data, size);
  Rows r{};
  switch (static_cast<Mode>(in.u8() % kModeCount)) {
    case Mode::grid: {
      const int scale = kGridScales[in.u8() % 16];
      for (int c = 0; c < 24; ++c) coord(r, c) = std::ldexp(static_cast<int>(in.u8() % 17) - 8, scale);
      break;
    }
    case Mode::raw:
      for (int c = 0; c < 24; ++c) {
        const std::uint64_t bits = in.u64();
        double x;
        std::memcpy(&x, &bits, sizeof x);
        coord(r, c) = std::isfinite(x) ? x : 0.0;
      }
      break;
    case Mode::family: {
      const std::vector<const families::Family*>& pool = sources.families;
      const families::Family* f = pool[in.u8() % pool.size()];
      const int k = k_from_byte(in.u8());
      const std::uint8_t direction = in.u8();
      const bool toward = (direction & 1) != 0;
      const int placement = (direction >> 1) % (families::kWideStyleCount + 1);
      std::mt19937_64 rng(in.u64());
      std::optional<families::Instance> inst;
      if (placement > 0)
        inst = families::make_wide(*f, k, toward, static_cast<families::WideStyle>(placement - 1), rng);
      if (!inst) inst = f->make(k, toward, rng);  // the own placement (also if no wide draw was exact)
      std::visit([&r](const auto& q) { r = rows(q); }, inst->query);
      break;
    }
    case Mode::catalogue: {
      const std::vector<Rows>& entries = sources.catalogue;
      const std::size_t index = in.u8() | (static_cast<std::size_t>(in.u8()) << 8);
      r = entries[index % entries.size()];
      break;
    }
  }
  while (!in.done()) {
    const std::uint8_t op = in.u8(), a = in.u8(), b = in.u8();
    apply_edit(r, op, a, b);
  }
  return r;
}

bool all_finite(const Rows& r) {
  for (const Vec3& p : r)
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return false;
  return true;
}

int exponent_spread(const Rows& r) {
  int lo = 0, hi = 0;
  bool any = false;
  for (const Vec3& p : r)
    for (double x : {p.x, p.y, p.z}) {
      if (x == 0 || !std::isfinite(x)) continue;
      const int e = std::ilogb(x);
      lo = any ? std::min(lo, e) : e;
      hi = any ? std::max(hi, e) : e;
      any = true;
    }
  return hi - lo;
}

std::vector<std::uint8_t> encode_raw(const Rows& r) {
  std::vector<std::uint8_t> out{static_cast<std::uint8_t>(Mode::raw)};
  Rows copy = r;
  for (int c = 0; c < 24; ++c) {
    const double x = std::isfinite(coord(copy, c)) ? coord(copy, c) : 0.0;
    std::uint64_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    for (int i = 0; i < 8; ++i) out.push_back(static_cast<std::uint8_t>(bits >> (8 * i)));
  }
  return out;
}

std::vector<std::uint8_t> encode_family(std::size_t family_index, int k, bool toward,
                                        std::uint64_t seed, std::optional<families::WideStyle> wide) {
  const int placement = wide ? static_cast<int>(*wide) + 1 : 0;
  std::vector<std::uint8_t> out{static_cast<std::uint8_t>(Mode::family),
                                static_cast<std::uint8_t>(family_index), byte_from_k(k),
                                static_cast<std::uint8_t>((toward ? 1 : 0) | (placement << 1))};
  for (int i = 0; i < 8; ++i) out.push_back(static_cast<std::uint8_t>(seed >> (8 * i)));
  return out;
}

std::vector<std::uint8_t> encode_catalogue(std::size_t index) {
  return {static_cast<std::uint8_t>(Mode::catalogue), static_cast<std::uint8_t>(index & 0xff),
          static_cast<std::uint8_t>((index >> 8) & 0xff)};
}

void append_edit(std::vector<std::uint8_t>& bytes, std::uint8_t op, std::uint8_t a, std::uint8_t b) {
  bytes.insert(bytes.end(), {op, a, b});
}

std::vector<std::uint8_t> random_input(std::mt19937_64& rng, Mode mode) {
  std::uniform_int_distribution<int> byte(0, 255), edits(0, 4), coin(0, 1);
  std::vector<std::uint8_t> out{static_cast<std::uint8_t>(mode)};
  const auto random_bytes = [&](int n) {
    for (int i = 0; i < n; ++i) out.push_back(static_cast<std::uint8_t>(byte(rng)));
  };
  switch (mode) {
    case Mode::grid: random_bytes(25); break;
    case Mode::raw: {
      // Three times in four uniform doubles in [-1, 1], else arbitrary bit patterns (every
      // exponent, subnormals to 1e308); the edits then add the degeneracies.
      Rows r;
      const bool bits = coin(rng) == 1 && coin(rng) == 1;
      std::uniform_real_distribution<double> unit(-1.0, 1.0);
      for (int c = 0; c < 24; ++c) {
        if (bits) {
          const std::uint64_t pattern = rng();
          double x;
          std::memcpy(&x, &pattern, sizeof x);
          coord(r, c) = x;
        } else {
          coord(r, c) = unit(rng);
        }
      }
      out = encode_raw(r);
      break;
    }
    case Mode::family: random_bytes(11); break;
    case Mode::catalogue: random_bytes(2); break;
  }
  for (int e = edits(rng); e > 0; --e) random_bytes(3);
  return out;
}

std::string hex_rows(const Rows& r, const std::array<std::string, 8>& row_names) {
  std::string out;
  char line[160];
  for (std::size_t i = 0; i < 8; ++i) {
    std::snprintf(line, sizeof line, "  %-5s %a %a %a\n", row_names[i].c_str(), r[i].x, r[i].y, r[i].z);
    out += line;
  }
  return out;
}

std::string benchmark_csv(const Rows& r, bool truth) {
  io::BenchmarkQueries q;
  std::array<RationalVec3, 8> rational;
  for (std::size_t i = 0; i < 8; ++i) rational[i] = {mpq_class(r[i].x), mpq_class(r[i].y), mpq_class(r[i].z)};
  q.rows.push_back(rational);
  q.truth.push_back(truth);
  std::ostringstream out;
  io::write_benchmark_csv(out, q);
  return out.str();
}

}  // namespace exactccd::fuzzing
