#!/usr/bin/env bash
# The identity check (issue 34, item 4): two exactccd programs answer every query file that
# `exactccd check` reads with `check --answers --toi` at d = 0, 1e-6, 1e-3 and tmax = 1, 0.5;
# every output (stdout, stderr, exit status) must be byte-identical. Run it for every speed
# change: "answers and times of impact unchanged" is then this command.
set -euo pipefail
export LC_ALL=C  # the files' order, sort's numbers

usage() {
  cat <<'EOF'
usage: tools/identity_check.sh [options] OLD_EXACTCCD NEW_EXACTCCD [OUT_DIR]
       tools/identity_check.sh [options] --list

Runs `exactccd check --answers --toi --min-distance D --tmax T FILE` with both programs for
every query file and every question (D, T) in {0, 1e-6, 1e-3} x {1, 0.5}, rigid files with
`--motion rigid`, and compares stdout, stderr and the exit status byte for byte. A file both
programs reject (exit 2, the same message: tests/data holds malformed files on purpose) is
identical. Prints every difference (file, question, the first differing lines, the command)
and a summary line.

Query files: every *.csv under the roots. A file whose first line that is not blank and not a
'#' comment has 41 comma-separated fields is a rigid query file (data/rigid, tests/data/rigid);
the others are linear (benchmark CSV, the Scalable CCD dataset's query files). The kind is left
to check (vertex-face, edge-edge, ... in the path; a stem ending in vf or ee), except where only
a vf or ee token of the file name gives it (tests/data/rigid/hand-vf-*.csv): --kind vf|ee.

Default roots (relative to the checkout):
  data/ and tests/data/
  the shared sample, EXACTCCD_SAMPLE_QUERIES_DIR (default ../shared/data/sample-queries)
  the Scalable CCD sample, EXACTCCD_SCALABLE_SAMPLE_DIR (default ../shared/data/scalable-ccd-sample;
    its queries/*.csv, which check --answers reads without a truth file)
A shared folder that is absent is said so on stderr and skipped.

options:
  -j, --jobs N        runs at once (default: the number of cores, nproc)
  --root PATH         also compare PATH (a folder: its *.csv files; or one file); repeatable.
                      EXACTCCD_IDENTITY_ROOTS (':'-separated) adds roots too
  --no-default-roots  only the roots of --root and EXACTCCD_IDENTITY_ROOTS
  --sample-dir DIR    the shared sample (overrides EXACTCCD_SAMPLE_QUERIES_DIR)
  --scalable-dir DIR  the Scalable CCD sample (overrides EXACTCCD_SCALABLE_SAMPLE_DIR)
  --list              print the files found (motion, kind, path) and exit
  -h, --help          this text
OUT_DIR (absent or empty) keeps every output: OUT_DIR/{old,new}/fNNN-qN.{out,err,rc}, files.tsv.
Without it a temporary folder is used, removed when everything is identical.
exit codes: 0 identical, 1 a difference, 2 bad usage or a program that fails to run (cannot be
executed, an internal error: exit 1, or a crash).
EOF
}

readonly QUESTIONS=("0 1" "1e-6 1" "1e-3 1" "0 0.5" "1e-6 0.5" "1e-3 0.5")
readonly KIND_NAMES='vertex-face|edge-edge|point-edge|point-point'

die_usage() {
  echo "identity_check: $*" >&2
  echo "(tools/identity_check.sh --help)" >&2
  exit 2
}

note() { echo "identity_check: $*" >&2; }

# $1 as an absolute path ($1 relative to the caller's folder; not resolved further).
absolute() {
  case $1 in
    /*) printf '%s\n' "$1" ;;
    *) printf '%s\n' "$PWD/$1" ;;
  esac
}

# The program $1 as an absolute path (a bare name is looked up on PATH).
program_path() {
  if [[ $1 == */* ]]; then
    absolute "$1"
  else
    command -v -- "$1" || die_usage "no program '$1' on PATH"
  fi
}

parse_args() {
  jobs=$(nproc 2>/dev/null || echo 2)
  roots=() positional=() defaults=1 list=0
  # The defaults relative to the checkout (as CMake's), a folder given relative to the caller's.
  sample_dir=../shared/data/sample-queries scalable_dir=../shared/data/scalable-ccd-sample
  if [[ -n ${EXACTCCD_SAMPLE_QUERIES_DIR:-} ]]; then sample_dir=$(absolute "$EXACTCCD_SAMPLE_QUERIES_DIR"); fi
  if [[ -n ${EXACTCCD_SCALABLE_SAMPLE_DIR:-} ]]; then scalable_dir=$(absolute "$EXACTCCD_SCALABLE_SAMPLE_DIR"); fi
  if [[ -n ${EXACTCCD_IDENTITY_ROOTS:-} ]]; then
    local -a env_roots
    IFS=: read -r -a env_roots <<<"$EXACTCCD_IDENTITY_ROOTS"
    for r in "${env_roots[@]}"; do
      if [[ -n $r ]]; then roots+=("$(absolute "$r")"); fi
    done
  fi
  while (($#)); do
    case $1 in
      -h | --help) usage; exit 0 ;;
      -j | --jobs) (($# >= 2)) || die_usage "$1 needs a value"; jobs=$2; shift ;;
      --root) (($# >= 2)) || die_usage "$1 needs a value"; roots+=("$(absolute "$2")"); shift ;;
      --no-default-roots) defaults=0 ;;
      --sample-dir) (($# >= 2)) || die_usage "$1 needs a value"; sample_dir=$(absolute "$2"); shift ;;
      --scalable-dir) (($# >= 2)) || die_usage "$1 needs a value"; scalable_dir=$(absolute "$2"); shift ;;
      --list) list=1 ;;
      --) shift; positional+=("$@"); break ;;
      -*) die_usage "unknown option '$1'" ;;
      *) positional+=("$1") ;;
    esac
    shift
  done
  [[ $jobs =~ ^[1-9][0-9]{0,3}$ ]] || die_usage "--jobs takes a whole number from 1 to 9999, not '$jobs'"
}

# The programs and the output folder from the positional arguments.
parse_positionals() {
  if ((list)); then
    ((${#positional[@]} == 0)) || die_usage "--list takes no program"
    return
  fi
  ((${#positional[@]} == 2 || ${#positional[@]} == 3)) || die_usage "expected OLD_EXACTCCD NEW_EXACTCCD [OUT_DIR]"
  old=$(program_path "${positional[0]}")
  new=$(program_path "${positional[1]}")
  out_dir=""
  if ((${#positional[@]} == 3)); then out_dir=$(absolute "${positional[2]}"); fi
}

# The roots to search, relative to the checkout where they are the defaults.
collect_roots() {
  local r
  search_roots=()
  if ((defaults)); then
    search_roots+=(data tests/data)
    for r in "$sample_dir" "$scalable_dir"; do
      if [[ -d $r ]]; then
        search_roots+=("$(realpath -s --relative-to=. -- "$r")")
      else
        note "the shared folder $r is absent: its files are NOT compared"
      fi
    done
  fi
  for r in "${roots[@]}"; do
    [[ -e $r ]] || die_usage "no such root: $r"
    search_roots+=("$(realpath -s --relative-to=. -- "$r")")
  done
  ((${#search_roots[@]})) || die_usage "no root to search (--no-default-roots without --root)"
}

# "rigid" when the first line that is not blank or a comment has 41 comma-separated fields.
motion_of() {
  local fields
  fields=$(awk -F, '/^[[:space:]]*(#|$)/ { next } { print NF; exit }' "$1")
  if [[ $fields == 41 ]]; then echo rigid; else echo linear; fi
}

# "auto" where check finds the kind in the path (a long name, or a stem ending in vf or ee not
# after a letter), else vf or ee from a token of the file name.
kind_of() {
  local name
  name=$(basename -- "$1")
  if [[ $1 =~ $KIND_NAMES || ${name%.*} =~ (^|[^[:alpha:]])(vf|ee)$ ]]; then
    echo auto
  elif [[ $name =~ (^|[^[:alpha:]])(vf|ee)([^[:alpha:]]|$) ]]; then
    echo "${BASH_REMATCH[2]}"
  else
    echo auto
  fi
}

# files.tsv: one line per query file, "fNNN <tab> motion <tab> kind <tab> root <tab> path".
find_files() {
  local root file n=0
  for root in "${search_roots[@]}"; do
    while IFS= read -r -d '' file; do
      file=$(realpath -s --relative-to=. -- "$file")
      printf '%s\t%s\n' "$root" "$file"
    done < <(find -L "$root" -type f -name '*.csv' -print0 | sort -z)
  done | awk -F'\t' '!seen[$2]++' >"$work/roots.tsv"
  while IFS=$'\t' read -r root file; do
    printf 'f%03d\t%s\t%s\t%s\t%s\n' "$n" "$(motion_of "$file")" "$(kind_of "$file")" "$root" "$file"
    n=$((n + 1))
  done <"$work/roots.tsv" >"$work/files.tsv"
  [[ -s $work/files.tsv ]] || die_usage "no *.csv file under the roots: ${search_roots[*]}"
}

# Per root: how many files of each motion.
print_roots() {
  awk -F'\t' '{ n[$4]++; m[$4 "\t" $2]++; if (!($4 in order)) { order[$4] = ++k; name[k] = $4 } }
    END { for (i = 1; i <= k; i++) { r = name[i]
            printf "identity_check: root %s: %d files (%d linear, %d rigid)\n", r, n[r], m[r "\tlinear"], m[r "\trigid"] } }' \
    "$work/files.tsv" >&2
}

# The arguments of check for a file and question, one a line (motion, kind, d, tmax, file).
check_args() {
  printf '%s\n' check --answers --toi --min-distance "$3" --tmax "$4"
  if [[ $1 == rigid ]]; then printf '%s\n' --motion rigid; fi
  if [[ $2 != auto ]]; then printf '%s\n' --kind "$2"; fi
  printf '%s\n' "$5"
}

# One run (a line of jobs.tsv): side, program, id, motion, kind, d, tmax, file. Writes
# $work/side/id.{out,err,rc,time}.
run_job() {
  local side prog id motion kind d tmax file rc=0 start
  IFS=$'\t' read -r side prog id motion kind d tmax file <<<"$1"
  local -a args
  mapfile -t args < <(check_args "$motion" "$kind" "$d" "$tmax" "$file")
  start=$EPOCHREALTIME
  "$prog" "${args[@]}" >"$work/$side/$id.out" 2>"$work/$side/$id.err" </dev/null || rc=$?
  echo "$rc" >"$work/$side/$id.rc"
  echo "$start $EPOCHREALTIME" | awk '{ printf "%.3f\n", $2 - $1 }' >"$work/$side/$id.time"
}

# jobs.tsv: every (side, file, question), the largest files first (for the parallel runs).
write_jobs() {
  local id motion kind root file size q d tmax side prog
  while IFS=$'\t' read -r id motion kind root file; do
    size=$(stat -L -c %s -- "$file")
    for q in "${!QUESTIONS[@]}"; do
      read -r d tmax <<<"${QUESTIONS[$q]}"
      for side in old new; do
        if [[ $side == old ]]; then prog=$old; else prog=$new; fi
        printf '%s\t%s\t%s\t%s-q%d\t%s\t%s\t%s\t%s\t%s\n' "$size" "$side" "$prog" "$id" "$q" "$motion" "$kind" "$d" "$tmax" "$file"
      done
    done
  done <"$work/files.tsv" | sort -t$'\t' -k1,1nr -s | cut -f2- >"$work/jobs.tsv"
}

run_all() {
  mkdir -p "$work/old" "$work/new"
  export work
  export -f run_job check_args
  # shellcheck disable=SC2016  # $1 is bash -c's argument
  xargs -d '\n' -P "$jobs" -n 1 bash -c 'run_job "$1"' run_job <"$work/jobs.tsv" ||
    die_usage "the runs could not be made (outputs in $work)"
}

# A program that cannot run at all is a usage error before any file.
check_program() {
  local version
  [[ -x $1 && ! -d $1 ]] || die_usage "$1 is not an executable program"
  version=$("$1" --version 2>&1 | head -n 1) || true
  [[ $version == exactccd* ]] || die_usage "$1 --version does not say exactccd: '$version'"
  note "$2 = $1 ($version)"
}

# The first differing line of $1 and $2 (stdout or stderr), and the two lines after it.
show_first_difference() {
  local line
  line=$(cmp -- "$1" "$2" 2>&1 | sed -n 's/.*line \([0-9]*\).*/\1/p') || true  # cmp exits 1
  line=${line:-1}
  echo "    first difference at line $line:"
  sed -n "${line},$((line + 2))p" -- "$1" | sed 's/^/      old: /'
  [[ -n $(sed -n "${line}p" -- "$1") ]] || echo "      old: (end of output)"
  sed -n "${line},$((line + 2))p" -- "$2" | sed 's/^/      new: /'
  [[ -n $(sed -n "${line}p" -- "$2") ]] || echo "      new: (end of output)"
}

# Prints a difference of one (file, question) run; the arguments as a line of files.tsv plus q.
report_difference() {
  local id=$1 motion=$2 kind=$3 file=$4 q=$5 d tmax stream
  read -r d tmax <<<"${QUESTIONS[$q]}"
  echo "DIFFERENCE $file, d = $d, tmax = $tmax:"
  if ! cmp -s "$work/old/$id-q$q.rc" "$work/new/$id-q$q.rc"; then
    echo "    exit status: old $(<"$work/old/$id-q$q.rc"), new $(<"$work/new/$id-q$q.rc")"
  fi
  for stream in out err; do
    if ! cmp -s "$work/old/$id-q$q.$stream" "$work/new/$id-q$q.$stream"; then
      echo "  std$stream differs"
      show_first_difference "$work/old/$id-q$q.$stream" "$work/new/$id-q$q.$stream"
    fi
  done
  echo "    command: exactccd $(check_args "$motion" "$kind" "$d" "$tmax" "$file" | paste -sd' ')"
}

# Whether an exit status is one of check's answers: 0 ran, 2 rejected input.
is_answer_status() { [[ $1 == 0 || $1 == 2 ]]; }

# Compares the two runs of one file at question $6 (the other arguments: a line of files.tsv);
# prints a failure or difference. Exit status 0 identical, 1 different; sets failed (0 or 1).
compare_one() {
  local id=$1 motion=$2 kind=$3 file=$5 q=$6 base=$1-q$6 a b
  a=$(<"$work/old/$base.rc") b=$(<"$work/new/$base.rc")
  failed=0
  if ! is_answer_status "$a" || ! is_answer_status "$b"; then
    failed=1
    echo "FAILED TO RUN $file, d = ${QUESTIONS[$q]% *}, tmax = ${QUESTIONS[$q]#* }: exit status old $a," \
      "new $b (stderr: $work/{old,new}/$base.err)"
  fi
  if cmp -s "$work/old/$base.rc" "$work/new/$base.rc" && cmp -s "$work/old/$base.out" "$work/new/$base.out" &&
    cmp -s "$work/old/$base.err" "$work/new/$base.err"; then
    return 0
  fi
  report_difference "$id" "$motion" "$kind" "$file" "$q"
  return 1
}

# Compares every run (files.tsv order); sets differences, failures, compared and rejected (both
# programs exit 2 with the same message). Notes the files rejected alike at every question.
compare_all() {
  local id motion kind root file q alike
  differences=0 failures=0 compared=0 rejected=0
  while IFS=$'\t' read -r id motion kind root file; do
    alike=0
    for q in "${!QUESTIONS[@]}"; do
      compared=$((compared + 1))
      if compare_one "$id" "$motion" "$kind" "$root" "$file" "$q"; then
        if [[ $(<"$work/old/$id-q$q.rc") == 2 ]]; then alike=$((alike + 1)); fi
      else
        differences=$((differences + 1))
      fi
      failures=$((failures + failed))
    done
    rejected=$((rejected + alike))
    if ((alike == ${#QUESTIONS[@]})); then note "rejected by both alike: $(head -n 1 "$work/old/$id-q0.err")"; fi
  done <"$work/files.tsv"
}

# The slowest runs (a file too slow at some question shows here).
print_slowest() {
  local side t secs run
  note "slowest runs (s, side, run, file):"
  for side in old new; do
    for t in "$work/$side"/*.time; do printf '%s\t%s\t%s\n' "$(<"$t")" "$side" "$(basename "$t" .time)"; done
  done | sort -t$'\t' -k1,1gr | awk 'NR <= 3' | while IFS=$'\t' read -r secs side run; do
    note "  $secs $side $run $(awk -F'\t' -v id="${run%-q*}" '$1 == id { print $5 }' "$work/files.tsv")"
  done
}

# The output folder: OUT_DIR (absent or empty), or a temporary one.
make_work_dir() {
  if [[ -n $out_dir ]]; then
    if [[ -e $out_dir ]] && [[ -n $(ls -A -- "$out_dir") ]]; then die_usage "OUT_DIR $out_dir is not empty"; fi
    mkdir -p -- "$out_dir"
    work=$out_dir
  else
    work=$(mktemp -d "${TMPDIR:-/tmp}/identity_check.XXXXXX")
  fi
}

main() {
  parse_args "$@"
  parse_positionals
  cd "$(dirname "$0")/.."
  collect_roots
  if ((list)); then
    work=$(mktemp -d "${TMPDIR:-/tmp}/identity_check.XXXXXX")
    trap 'rm -rf -- "$work"' EXIT
    find_files
    print_roots
    cut -f2,3,5 "$work/files.tsv"
    return 0
  fi
  check_program "$old" OLD
  check_program "$new" NEW
  make_work_dir
  find_files
  print_roots
  local start=$SECONDS files
  files=$(wc -l <"$work/files.tsv")
  note "$files files x ${#QUESTIONS[@]} questions, $((2 * files * ${#QUESTIONS[@]})) runs on $jobs jobs"
  write_jobs
  run_all
  compare_all
  print_slowest
  echo "identity_check: $files files x ${#QUESTIONS[@]} questions = $compared compared ($rejected rejected by both" \
    "alike), $differences differences, $failures failed runs, $((SECONDS - start)) s on $jobs jobs"
  if ((failures)); then echo "identity_check: outputs kept in $work"; return 2; fi
  if ((differences)); then echo "identity_check: outputs kept in $work"; return 1; fi
  [[ -n $out_dir ]] || rm -rf -- "$work"
}

main "$@"
