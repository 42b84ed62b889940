#!/usr/bin/env bash
# Integration test of the cluster recipe (tools/cluster/) on a real one-node Slurm cluster that
# this script starts on loopback (munged with its own key and socket, slurmctld and slurmd on
# free ports, all state under WORK) and stops again, whatever happens. For check, compare and
# fuzz-against it submits a sharded run with tools/cluster/submit.sh --wait and requires the
# merged output (and fuzz-against's output directory) to be byte-identical to one plain run.
# Skipped (exit 77, "SKIPPED: ..." on stdout) when Slurm or munge is not installed or when not
# run as root (slurmd must start jobs as their user).
#   cluster_slurm.sh EXE PLUGIN DATA_DIR RECIPE_DIR WORK
set -euo pipefail
exe=$(realpath "$1") plugin=$(realpath "$2") data=$(realpath "$3") recipe=$(realpath "$4") work=$5

for tool in munged slurmctld slurmd sbatch sinfo scontrol; do
  if ! command -v "$tool" > /dev/null 2>&1 && ! [ -x "/usr/sbin/$tool" ]; then
    echo "SKIPPED: '$tool' is not installed (Debian packages slurm-wlm and munge; tools/install-deps.sh installs them)"
    exit 77
  fi
done
if [ "$(id -u)" -ne 0 ]; then
  echo "SKIPPED: the one-node Slurm cluster needs root (slurmd starts jobs as their user)"
  exit 77
fi
export PATH="$PATH:/usr/sbin"

rm -rf "$work"
mkdir -p "$work"/{state,spool,log,runs}
work=$(cd "$work" && pwd)
chmod 755 "$work"
conf="$work/slurm.conf"
export SLURM_CONF="$conf"
node=$(hostname -s)

cleanup() {
  scontrol shutdown > /dev/null 2>&1 || true
  for f in slurmd.pid slurmctld.pid; do
    [ -f "$work/$f" ] && kill "$(cat "$work/$f")" > /dev/null 2>&1 || true
  done
  munged --stop --socket="$work/munge.socket" > /dev/null 2>&1 || true
}
fail() {
  echo "FAIL: $*" >&2
  for log in "$work"/log/*.log; do echo "--- $log" >&2; tail -n 20 "$log" >&2 || true; done
  exit 1
}
trap cleanup EXIT

# munge: a fresh key, readable by root only, and a socket of our own.
dd if=/dev/urandom of="$work/munge.key" bs=1024 count=1 status=none
chmod 400 "$work/munge.key"
munged --force --key-file="$work/munge.key" --socket="$work/munge.socket" --pid-file="$work/munged.pid" \
       --log-file="$work/log/munged.log" --seed-file="$work/munged.seed" || fail "munged did not start"

read -r ctld_port slurmd_port < <(python3 -c '
import socket
s = [socket.socket() for _ in range(2)]
for x in s: x.bind(("127.0.0.1", 0))
print(*(x.getsockname()[1] for x in s))')
cat > "$conf" <<CONF
ClusterName=exactccdtest
SlurmctldHost=$node(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
AuthType=auth/munge
AuthInfo=socket=$work/munge.socket
CredType=cred/munge
SlurmUser=root
SlurmdUser=root
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/log/slurmctld.log
SlurmdLogFile=$work/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
MpiDefault=none
SwitchType=switch/none
ReturnToService=2
SchedulerType=sched/builtin
SchedulerParameters=sched_interval=1
NodeName=$node NodeAddr=127.0.0.1 CPUs=$(nproc) State=UNKNOWN
PartitionName=test Nodes=$node Default=YES MaxTime=INFINITE State=UP
CONF
slurmctld -f "$conf" -i || fail "slurmctld did not start"
slurmd -f "$conf" || fail "slurmd did not start"
for ((i = 0; i < 60; i++)); do
  state=$(sinfo -h -n "$node" -o %T 2> /dev/null || true)
  [ "$state" = idle ] && break
  sleep 1
done
[ "$state" = idle ] || fail "the node did not become idle (state '$state')"
echo "one-node Slurm cluster up: node $node, slurmctld port $ctld_port"

export EXACTCCD="$exe"
runs="$work/runs"
submit() { "$recipe/submit.sh" --wait "$@" > /dev/null || fail "submit.sh $*"; }

# check: answers and TOIs of two simulation files, 3 shards.
files=("$data/sim-fold-edge-edge.csv" "$data/sim-strip-vertex-face.csv")
"$exe" check --answers --toi "${files[@]}" > "$runs/check-single.txt"
submit --shards 3 --work "$runs/check" --output "$runs/check-merged.txt" -- check --answers --toi "${files[@]}"
cmp "$runs/check-single.txt" "$runs/check-merged.txt" || fail "check: merged output differs from one run"
echo "check: 3 shards merged == one run ($(wc -l < "$runs/check-single.txt") answers)"

# compare --toi: another code's times of impact (the exact ones, some moved late), 4 shards.
file="$data/sim-fold-edge-edge.csv"
"$exe" check --answers --toi "$file" | awk '{ if ($1 == "0") print "0"; else if (NR % 2) print "1", $3; else print "1", $2 / 2 }' > "$runs/theirs.txt"
"$exe" compare --toi "$runs/theirs.txt" "$file" > "$runs/compare-single.txt"
grep -q "unsafe [1-9]" "$runs/compare-single.txt" || fail "compare: the test's answers should have unsafe TOIs"
submit --shards 4 --work "$runs/compare" --output "$runs/compare-merged.txt" -- compare --toi "$runs/theirs.txt" "$file"
cmp "$runs/compare-single.txt" "$runs/compare-merged.txt" || fail "compare: merged report differs from one run"
echo "compare: 4 shards merged == one run"

# fuzz-against: the textbook method as a plug-in, 3 shards; report and output directory.
(cd "$runs" && "$exe" fuzz-against "$plugin" --kind vf --queries 240 --seed 11 --out fuzz-out > fuzz-single.txt 2> /dev/null)
mv "$runs/fuzz-out" "$runs/fuzz-single-dir"
grep -q "disagreements (FP" "$runs/fuzz-single.txt" || fail "fuzz-against: no report"
(cd "$runs" && submit --shards 3 --work fuzz --output fuzz-merged.txt --out fuzz-out -- \
                fuzz-against "$plugin" --kind vf --queries 240 --seed 11)
cmp "$runs/fuzz-single.txt" "$runs/fuzz-merged.txt" || fail "fuzz-against: merged report differs from one run"
diff -r "$runs/fuzz-single-dir" "$runs/fuzz-out" > /dev/null || fail "fuzz-against: merged files differ from one run"
echo "fuzz-against: 3 shards merged == one run ($(ls "$runs/fuzz-out" | wc -l) files)"

# A failed shard: the merge never runs and the recipe reports the failure.
if "$recipe/submit.sh" --wait --shards 2 --work "$runs/bad" --output "$runs/bad.txt" -- \
     check --answers "$runs/no-such-file.csv" > /dev/null 2>&1; then
  fail "a run whose shards fail was reported as done"
fi
[ ! -e "$runs/bad.txt" ] || fail "a failed run left an output file"
echo "a failed shard fails the run, no output written"
echo "PASSED"
