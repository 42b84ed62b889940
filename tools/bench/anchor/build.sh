#!/usr/bin/env bash
# Builds the anchor of docs/scene.md's side-by-side measurement: the Scalable CCD CPU pipeline
# (its sort-and-sweep broad phase on oneTBB, then Tight Inclusion's CPU narrow phase, pruned by
# the earliest time of impact found so far), driven by tools/bench/anchor/scalable_ccd_step.cpp.
# Neither project is part of exactccd: bring them beside the repository (never into it), e.g.
#   SRC=/work/ext: $SRC/Scalable-CCD and $SRC/Tight-Inclusion (public repositories
#   Continuous-Collision-Detection/Scalable-CCD and .../Tight-Inclusion),
# then
#   bash tools/bench/anchor/build.sh SRC BUILD_DIR
# It compiles their sources directly with Debian's oneTBB, Eigen, spdlog and fmt
# (apt-get install libtbb-dev libeigen3-dev libspdlog-dev libfmt-dev), without their CMake
# (which downloads its dependencies), with -O3 -DNDEBUG as their Release build, and writes
# BUILD_DIR/scalable_ccd_step. tools/plot/anchor_step.sh runs it.
set -euo pipefail
src=$(realpath "$1")
build=$(realpath -m "$2")
here=$(cd "$(dirname "$0")" && pwd)
sccd=$src/Scalable-CCD/src
ticcd=$src/Tight-Inclusion/src
for d in "$sccd/scalable_ccd" "$ticcd/tight_inclusion"; do
  [ -d "$d" ] || { echo "build.sh: $d not found" >&2; exit 2; }
done
mkdir -p "$build/include/scalable_ccd" "$build/include/tight_inclusion" "$build/obj"
# Their config headers, as their CMake would configure them (double precision, no profiler).
sed -e 's/@PROJECT_NAME@/ScalableCCD/; s/@PROJECT_VERSION[A-Z_]*@/0/' \
    -e 's|#cmakedefine SCALABLE_CCD_USE_DOUBLE|#define SCALABLE_CCD_USE_DOUBLE|' \
    -e 's|#cmakedefine \(.*\)|/* #undef \1 */|' "$sccd/scalable_ccd/config.hpp.in" > "$build/include/scalable_ccd/config.hpp"
sed -e 's/@PROJECT_NAME@/TightInclusion/; s/@PROJECT_VERSION[A-Z_]*@/0/' \
    -e 's|#cmakedefine TIGHT_INCLUSION_WITH_DOUBLE_PRECISION|#define TIGHT_INCLUSION_WITH_DOUBLE_PRECISION|' \
    -e 's|#cmakedefine \(.*\)|/* #undef \1 */|' "$ticcd/tight_inclusion/config.hpp.in" > "$build/include/tight_inclusion/config.hpp"
# Debian's spdlog uses the system fmt; Scalable CCD's logger includes spdlog's bundled copy.
mkdir -p "$build/include/spdlog/fmt/bundled"
echo '#include <fmt/ranges.h>' > "$build/include/spdlog/fmt/bundled/ranges.h"
flags=(-std=c++17 -O3 -DNDEBUG -DNOMINMAX -DSPDLOG_FMT_EXTERNAL -I"$build/include" -I"$sccd" -I"$ticcd" -I/usr/include/eigen3)
sources=("$sccd"/scalable_ccd/broad_phase/{aabb,sort_and_sweep}.cpp "$sccd"/scalable_ccd/utils/{logger,merge_local_overlaps}.cpp
         "$ticcd"/tight_inclusion/{avx,ccd,interval,interval_root_finder,logger}.cpp "$here/scalable_ccd_step.cpp")
objects=()
for s in "${sources[@]}"; do
  o="$build/obj/$(basename "$(dirname "$s")")_$(basename "$s" .cpp).o"
  g++ "${flags[@]}" -c "$s" -o "$o" &
  objects+=("$o")
  [ "$(jobs -r | wc -l)" -ge 2 ] && wait -n
done
wait
g++ -o "$build/scalable_ccd_step" "${objects[@]}" -ltbb -lspdlog -lfmt -pthread
echo "built $build/scalable_ccd_step"
