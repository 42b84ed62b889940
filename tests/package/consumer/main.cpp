// Uses the installed package: exits 0 only if the answers are right.
#include <exactccd/exactccd.h>
#include <exactccd/exactccd.hpp>

// The double API needs no GMP headers (rational queries are in exactccd/rational.hpp).
#ifdef __GMP_PLUSPLUS__
#error "exactccd's double API pulled in gmpxx.h"
#endif

int main() {
  const exactccd::VertexFaceQuery q{{0.25, 0.25, 1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0},
                                    {0.25, 0.25, -1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const auto toi = exactccd::vertex_face_toi(q);
  if (!toi || toi->lo != 0.5 || toi->hi != 0.5) return 1;
  const double flat[24] = {2, 2, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 2, 2, -1, 0, 0, 0, 1, 0, 0, 0, 1, 0};
  int collides = -1;
  if (exactccd_vertex_face_ccd(flat, &collides) != EXACTCCD_OK || collides != 0) return 2;
  // Both methods of the library are exact (the baselines are not in the installed package).
  for (exactccd::Method m : {exactccd::Method::filtered, exactccd::Method::exact})
    if (!exactccd::vertex_face_ccd(q, m)) return 3;
  return 0;
}
