// The options every interface shares: the one range of `threads` (0..1024: the C++ scene and
// candidate functions, the C API; the CLI's --threads has the same 0..1024, tests/cli/cli_input.cmake),
// cancellation of a scene call (SceneOptions::cancel), error messages whose numbers read back
// (shortest round-trip text), and the one version (exactccd_version(), exactccd/version.h).
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstdlib>
#include <random>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "exactccd/candidates.hpp"
#include "exactccd/ccd.hpp"
#include "exactccd/exactccd.h"
#include "exactccd/scene.hpp"
#include "exactccd/version.h"

namespace {

using namespace exactccd;

/// A small scene: one triangle and a vertex falling through it.
Scene falling_vertex() {
  Scene s;
  s.positions_t0 = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.25, 0.25, 1}, {0.25, 0.25, 2}};
  s.positions_t1 = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.25, 0.25, -1}, {0.25, 0.25, 3}};
  s.triangles = {{0, 1, 2}};
  s.edges = {{3, 4}};
  return s;
}

/// A soup of `n` small random triangles moving randomly in the unit cube: many candidates.
Scene soup(int n) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0, 1), small(-0.02, 0.02), move(-0.05, 0.05);
  Scene s;
  for (int i = 0; i < n; ++i) {
    const Vec3 c{u(rng), u(rng), u(rng)}, m{move(rng), move(rng), move(rng)};
    for (int k = 0; k < 3; ++k) {
      const Vec3 p{c.x + small(rng), c.y + small(rng), c.z + small(rng)};
      s.positions_t0.push_back(p);
      s.positions_t1.push_back({p.x + m.x, p.y + m.y, p.z + m.z});
    }
    s.triangles.push_back({3 * i, 3 * i + 1, 3 * i + 2});
  }
  return s;
}

TEST(SceneOptions, ThreadsTakeOneRange) {
  const Scene s = falling_vertex();
  for (unsigned threads : {0u, 1u, 2u, 1024u}) {
    SceneOptions o;
    o.threads = threads;
    EXPECT_NO_THROW(validate(o));
    EXPECT_EQ(find_collisions(s, o).size(), 1u) << threads;
  }
  for (unsigned threads : {1025u, 100000u, 4294967295u}) {
    SceneOptions o;
    o.threads = threads;
    EXPECT_THROW(validate(o), std::invalid_argument);
    EXPECT_THROW(find_collisions(s, o), std::invalid_argument) << threads;
    EXPECT_THROW(SceneBroadPhase(s, o), std::invalid_argument);
    try {
      is_collision_free(s, o);
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("threads must be in 0..1024 (0: every hardware thread), not " +
                                           std::to_string(threads)),
                std::string::npos)
          << e.what();
    }
  }
  // The C API: the same range.
  const double x0[6] = {0, 0, 0, 1, 0, 0}, x1[6] = {0, 0, 0, 1, 0, 0};
  const int pp[2] = {0, 1};
  exactccd_candidates c{};
  c.point_point = pp;
  c.point_point_count = 1;
  double step = -1;
  EXPECT_EQ(exactccd_candidates_max_collision_free_step(x0, x1, 2, &c, 0.5, 1.0, 1024, &step), EXACTCCD_OK);
  EXPECT_EQ(step, 1.0);
  EXPECT_EQ(exactccd_candidates_max_collision_free_step(x0, x1, 2, &c, 0.5, 1.0, 1025, &step),
            EXACTCCD_ERROR_PARAMETER);
}

TEST(SceneOptions, CancelledBeforeTheCallThrowsCancelled) {
  const Scene s = falling_vertex();
  std::atomic<bool> cancel{true};
  SceneOptions o;
  o.cancel = &cancel;
  for (unsigned threads : {1u, 2u}) {
    o.threads = threads;
    EXPECT_THROW(find_collisions(s, o), Cancelled);
    EXPECT_THROW(earliest_toi(s, o), Cancelled);
    EXPECT_THROW(is_collision_free(s, o), Cancelled);
    EXPECT_THROW(max_collision_free_step(s, o), Cancelled);
    EXPECT_THROW(SceneBroadPhase(s, o), Cancelled);
    CandidateSet set;
    set.vertex_face = {{3, 0, 1, 2}};
    EXPECT_THROW(find_collisions(s.positions_t0, s.positions_t1, set, o), Cancelled);
    EXPECT_THROW(max_collision_free_step(s.positions_t0, s.positions_t1, set, o), Cancelled);
  }
  cancel = false;  // a flag never set changes nothing
  EXPECT_EQ(find_collisions(s, o).size(), 1u);
  EXPECT_EQ(max_collision_free_step(s, o), std::nextafter(0.5, 0.0));
  const SceneBroadPhase broad(s, o);  // keeps no pointer to the flag: update() after it is gone
  EXPECT_EQ(broad.candidates().vertex_face.size(), 1u);
}

TEST(SceneOptions, CancelledDuringALongCallStopsSoon) {
  const Scene s = soup(12000);
  SceneOptions o;
  o.threads = 2;
  const auto start = std::chrono::steady_clock::now();
  const std::size_t all = find_collisions(s, o).size();
  const double full = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::atomic<bool> cancel{false};
  o.cancel = &cancel;
  std::thread setter([&] {
    std::this_thread::sleep_for(std::chrono::duration<double>(full / 10));
    cancel = true;
  });
  const auto again = std::chrono::steady_clock::now();
  bool cancelled = false;
  try {
    find_collisions(s, o);
  } catch (const Cancelled&) {
    cancelled = true;
  }
  const double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - again).count();
  setter.join();
  EXPECT_TRUE(cancelled) << "full call " << full << " s, " << all << " collisions";
  EXPECT_LT(took, full * 0.6) << "the cancelled call took " << took << " s, the full one " << full << " s";
}

TEST(ErrorMessages, NumbersReadBack) {
  const VertexFaceQuery q{};
  const auto message = [&](const CcdParams& p) {
    try {
      (void)vertex_face_toi(q, p);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message({0, 1.0000000000000002}).find("tmax must be in (0, 1], not 1.0000000000000002"), std::string::npos)
      << message({0, 1.0000000000000002});
  EXPECT_NE(message({-1e-300, 1}).find("not -1e-300"), std::string::npos) << message({-1e-300, 1});
  EXPECT_NE(message({0, 4.9406564584124654e-324 * 0}).find("not 0"), std::string::npos);
  SceneOptions o;
  o.tmax = 1.0000000000000002;
  try {
    validate(o);
    ADD_FAILURE() << "tmax accepted";
  } catch (const std::invalid_argument& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("not 1.0000000000000002"), std::string::npos) << m;
    EXPECT_EQ(std::strtod(m.substr(m.rfind(' ') + 1).c_str(), nullptr), 1.0000000000000002) << m;
  }
  o.tmax = 1;
  o.min_distance = -2.2250738585072014e-308;
  try {
    validate(o);
    ADD_FAILURE() << "min_distance accepted";
  } catch (const std::invalid_argument& e) {
    const std::string m = e.what();
    EXPECT_EQ(std::strtod(m.substr(m.rfind(' ') + 1).c_str(), nullptr), -2.2250738585072014e-308) << m;
  }
}

TEST(Version, OneVersion) {
  EXPECT_STREQ(exactccd_version(), EXACTCCD_VERSION_STRING);
  EXPECT_EQ(std::string(EXACTCCD_VERSION_STRING), std::to_string(EXACTCCD_VERSION_MAJOR) + "." +
                                                      std::to_string(EXACTCCD_VERSION_MINOR) + "." +
                                                      std::to_string(EXACTCCD_VERSION_PATCH));
}

}  // namespace
