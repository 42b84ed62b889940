#!/usr/bin/env bash
# The merge step of a sharded exactccd run (tools/cluster/README.md): from WORK/part-0 ..
# WORK/part-(N-1), writes OUTPUT, byte-identical to the output of the same command run once:
#   merge.sh WORK N COMMAND OUTPUT [--out DIR]
#   check:                 the parts concatenated in shard order (check --answers);
#   compare:               `exactccd merge` of the partial files;
#   fuzz-against:          `exactccd merge --out DIR` (the report; DIR gets the run's files).
# Fails, writing nothing, when a part is missing. OUTPUT appears only complete.
# EXACTCCD: the exactccd program (default: exactccd on the PATH).
set -euo pipefail
if [ $# -lt 4 ]; then
  echo "usage: merge.sh WORK N COMMAND OUTPUT [--out DIR]" >&2
  exit 2
fi
work=$1 shards=$2 command=$3 output=$4
shift 4
exe=${EXACTCCD:-exactccd}
parts=()
for ((i = 0; i < shards; i++)); do
  if [ ! -f "$work/part-$i" ]; then
    echo "merge.sh: $work/part-$i is missing (did shard $i of $shards fail?)" >&2
    exit 1
  fi
  parts+=("$work/part-$i")
done
tmp="$output.tmp.$$"
trap 'rm -f "$tmp"' EXIT
case "$command" in
  check) cat "${parts[@]}" > "$tmp" ;;
  compare|fuzz-against) "$exe" merge "$@" "${parts[@]}" > "$tmp" ;;
  *) echo "merge.sh: '$command' has no shards (check, compare, fuzz-against)" >&2; exit 2 ;;
esac
mv "$tmp" "$output"
trap - EXIT
