#!/usr/bin/env bash
# Submits a sharded exactccd run to Slurm: a job array of N shards, then the merge step as a job
# that starts when every shard has succeeded (tools/cluster/README.md).
#   submit.sh [--shards N] [--work DIR] [--output FILE] [--out DIR] [--wait]
#             [--sbatch "OPTIONS"] -- COMMAND ARGS...
# COMMAND ARGS... is an exactccd command line without --shard (check needs --answers; compare and
# fuzz-against are given without --partial, and fuzz-against without --out: pass --out DIR here).
#   --shards N      number of array tasks (default 16)
#   --work DIR      where the parts go (default: exactccd-run-<time>); created
#   --output FILE   the merged output (default: WORK/output.txt)
#   --out DIR       fuzz-against: where the merge writes the disagreement files
#   --wait          wait for the merge job and exit with its status
#   --sbatch OPTS   extra sbatch options for every job (partition, account, time limit...)
# EXACTCCD: the exactccd program the jobs run (default: exactccd on the PATH; give an absolute
# path visible on the compute nodes).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
shards=16 work="" output="" out_dir="" wait=0 sbatch_extra=""
while [ $# -gt 0 ]; do
  case "$1" in
    --shards) shards=$2; shift 2 ;;
    --work) work=$2; shift 2 ;;
    --output) output=$2; shift 2 ;;
    --out) out_dir=$2; shift 2 ;;
    --wait) wait=1; shift ;;
    --sbatch) sbatch_extra=$2; shift 2 ;;
    --) shift; break ;;
    *) echo "submit.sh: unknown option '$1' (the exactccd command goes after --)" >&2; exit 2 ;;
  esac
done
if [ $# -lt 1 ]; then echo "submit.sh: no exactccd command after --" >&2; exit 2; fi
if ! [[ "$shards" =~ ^[1-9][0-9]*$ ]]; then echo "submit.sh: --shards '$shards' is not a positive integer" >&2; exit 2; fi
command=$1
for a in "$@"; do
  case "$a" in
    --shard|--shard=*|--partial|--partial=*) echo "submit.sh: give the command without $a (the recipe adds it)" >&2; exit 2 ;;
  esac
done
case "$command" in
  check)
    printf '%s\n' "$@" | grep -qx -- '--answers' || { echo "submit.sh: check needs --answers (its answers concatenate)" >&2; exit 2; } ;;
  compare) ;;
  fuzz-against)
    [ -n "$out_dir" ] || { echo "submit.sh: fuzz-against needs --out DIR (given to the merge step)" >&2; exit 2; } ;;
  *) echo "submit.sh: '$command' has no shards (check, compare, fuzz-against)" >&2; exit 2 ;;
esac
work=${work:-exactccd-run-$(date +%Y%m%d-%H%M%S)}
mkdir -p "$work"
work=$(cd "$work" && pwd)
output=${output:-$work/output.txt}
export EXACTCCD=${EXACTCCD:-exactccd}
merge_args=()
[ -n "$out_dir" ] && merge_args=(--out "$out_dir")
# shellcheck disable=SC2086  # $sbatch_extra is a list of options
array=$(sbatch --parsable $sbatch_extra --export=ALL --array="0-$((shards - 1))" \
          --output="$work/slurm-%A_%a.log" "$here/shard.sbatch" "$work" "$shards" "$@")
array=${array%%;*}
wait_flag=()
[ "$wait" = 1 ] && wait_flag=(--wait)
echo "submit.sh: shards: job array $array ($shards tasks), parts in $work"
# With --wait, sbatch returns when the merge job ends, with its exit status (non-zero when a
# shard failed: the dependency can then never be met and the merge job is cancelled).
status=0
# shellcheck disable=SC2086
merge=$(sbatch --parsable $sbatch_extra --export=ALL --dependency="afterok:$array" --kill-on-invalid-dep=yes \
          --job-name=exactccd-merge --output="$work/slurm-merge-%j.log" "${wait_flag[@]}" \
          "$here/merge.sh" "$work" "$shards" "$command" "$output" "${merge_args[@]}") || status=$?
merge=${merge%%;*}
echo "submit.sh: merge: job ${merge:-?}, writes $output"
if [ "$wait" = 1 ]; then
  # A merge job cancelled before it ran (a shard failed: its dependency can never be met)
  # leaves sbatch --wait with status 0: the job's final state says whether it completed.
  state=$(scontrol show job -o "$merge" 2> /dev/null | grep -o 'JobState=[A-Z_]*' || true)
  if [ "$status" -eq 0 ] && [ "$state" != JobState=COMPLETED ]; then status=1; fi
  if [ "$status" -ne 0 ]; then
    echo "submit.sh: the run failed (merge job ${state:-state unknown}, exit $status); logs in $work/slurm-*.log" >&2
    exit "$status"
  fi
  echo "submit.sh: done: $output"
fi
