#!/usr/bin/env bash
# Scene-level CCD cost against size: cloth over a sphere at several resolutions (up to ~1M
# triangles), wall time and peak memory of `exactccd scene` per step. Writes
# docs/figures/scene_scaling.{csv,png}. Needs build/exactccd, /usr/bin/time and Debian's
# python3-matplotlib. Usage: bash tools/plot/scene_scaling.sh [RESOLUTIONS...]
set -euo pipefail
cd "$(dirname "$0")/../.."
resolutions=("$@")
[ ${#resolutions[@]} -gt 0 ] || resolutions=(16 32 64 128 256 512 708)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
out=docs/figures/scene_scaling.csv
echo "resolution,triangles,candidates,seconds,max_rss_kb" > "$out.tmp"
for r in "${resolutions[@]}"; do
  build/exactccd generate scene --scene cloth --resolution "$r" --seed 1 --out "$work/$r" > /dev/null
  /usr/bin/time -v build/exactccd scene --threads 2 "$work/$r/T0.obj" "$work/$r/T1.obj" \
    > "$work/$r/out.txt" 2> "$work/$r/time.txt"
  tri=$(awk '/^triangles/ {print $2}' "$work/$r/out.txt")
  cand=$(awk '/^candidates/ {print $2}' "$work/$r/out.txt")
  el=$(awk '/Elapsed/ {print $NF}' "$work/$r/time.txt")
  rss=$(awk '/Maximum resident/ {print $NF}' "$work/$r/time.txt")
  echo "$r,$tri,$cand,$el,$rss" >> "$out.tmp"
  rm -rf "${work:?}/$r"
done
mv "$out.tmp" "$out"
/usr/bin/python3 tools/plot/scene_scaling.py "$out" docs/figures/scene_scaling.png
cat "$out"
