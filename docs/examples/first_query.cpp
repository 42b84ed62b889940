#include <cstdio>
#include <exactccd/exactccd.hpp>

int main() {
  // A vertex falling through a fixed triangle: points at t = 0, then at t = 1.
  const exactccd::VertexFaceQuery q{{0.25, 0.25, 1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0},
                                    {0.25, 0.25, -1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const bool hit = exactccd::vertex_face_ccd(q);              // exact: true
  const auto toi = exactccd::vertex_face_toi(q);              // [0.5, 0.5]
  // Within 0.25 of the triangle, looking only at t in [0, 0.75]: from t = 3/8.
  const auto near = exactccd::vertex_face_toi(q, exactccd::CcdParams{0.25, 0.75});
  std::printf("hit %d, toi [%g, %g], within 0.25 from [%g, %g]\n", hit, toi->lo, toi->hi, near->lo, near->hi);
}
