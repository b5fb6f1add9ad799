#!/usr/bin/env bash
# `course grade-class --shard` on a real one-node Slurm cluster: Debian's
# slurmctld and slurmd with munge, started here for the test and stopped at its
# end, run a job array of three slices of a small class; `course merge-class`
# puts them together, and the gradebook must be byte-identical to one run's.
# Exits 77 (SKIP, with the reason) where the cluster cannot run: not root, no
# cgroup filesystem, or slurmctld, slurmd, munged or sbatch missing
# (LAB_SETUP_TESTS=1 scripts/setup.sh installs them).
# tests/grading/test_grade_class.cpp runs three slices as parallel processes
# wherever this cannot.
#
#   tests/grading/test_slurm_class.sh BIN_DIR SOURCE_DIR OUT_DIR
set -uo pipefail
bin=$1 source=$2 out=$3
skip() { echo "SKIP: $*"; exit 77; }
[ "$(id -u)" = 0 ] || skip "a one-node Slurm cluster needs root (munged and slurmd run as root here)"
for exe in slurmctld slurmd munged sbatch squeue scontrol; do
  command -v "$exe" >/dev/null || [ -x "/usr/sbin/$exe" ] ||
    skip "$exe is missing (Debian's slurmctld, slurmd, slurm-client and munge packages)"
done
export PATH=$PATH:/usr/sbin
# slurmd initialises its cgroup plugin at start, whatever ProctrackType says.
mountpoint -q /sys/fs/cgroup ||
  skip "no cgroup filesystem at /sys/fs/cgroup (a chroot or container without one): slurmd cannot start"

rm -rf "$out" && mkdir -p "$out"
cluster=$out/cluster
mkdir -p "$cluster"/{state,spool,munge,log}
chmod 0755 "$out" "$cluster"
pids=()
cleanup() {
  for p in "${pids[@]}"; do kill "$p" 2>/dev/null; done
  wait 2>/dev/null
}
trap cleanup EXIT

# munge: a key of its own, a socket in the test's folder.
key=$cluster/munge/munge.key
dd if=/dev/urandom of="$key" bs=1024 count=1 status=none
chmod 0400 "$key"
socket=$cluster/munge/munge.socket
munged --foreground --force --key-file="$key" --socket="$socket" \
  --pid-file="$cluster/munge/munged.pid" --log-file="$cluster/log/munged.log" --seed-file="$cluster/munge/seed" \
  >"$cluster/log/munged.out" 2>&1 &
pids+=($!)

host=$(hostname -s)
cpus=$(nproc)
cat >"$cluster/slurm.conf" <<EOF
ClusterName=gllabs
SlurmctldHost=$host(127.0.0.1)
SlurmUser=root
SlurmdUser=root
SlurmctldPort=$((20000 + RANDOM % 10000))
SlurmdPort=$((30000 + RANDOM % 10000))
AuthType=auth/munge
AuthInfo=socket=$socket
CredType=cred/munge
StateSaveLocation=$cluster/state
SlurmdSpoolDir=$cluster/spool
SlurmctldPidFile=$cluster/slurmctld.pid
SlurmdPidFile=$cluster/slurmd.pid
SlurmctldLogFile=$cluster/log/slurmctld.log
SlurmdLogFile=$cluster/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
MpiDefault=none
NodeName=$host NodeAddr=127.0.0.1 CPUs=$cpus State=UNKNOWN
PartitionName=grading Nodes=$host Default=YES MaxTime=INFINITE State=UP
EOF
export SLURM_CONF=$cluster/slurm.conf
slurmctld -D -i -f "$SLURM_CONF" >"$cluster/log/slurmctld.out" 2>&1 &
pids+=($!)
slurmd -D -f "$SLURM_CONF" >"$cluster/log/slurmd.out" 2>&1 &
pids+=($!)
for _ in $(seq 60); do
  sinfo -h -o %t 2>/dev/null | grep -qE '^(idle|mix|alloc)' && break
  sleep 1
done
sinfo -h -o %t 2>/dev/null | grep -qE '^(idle|mix|alloc)' ||
  { tail -20 "$cluster"/log/*.log; echo "FAIL: the one-node cluster did not come up"; exit 1; }

# A class of four: two solutions, a starting copy, one that does not build.
file=labs/01_transforms/transforms_math.cpp
subs=$out/subs
for s in ann ben; do mkdir -p "$subs/$s" && cp "$source/$file" "$subs/$s/"; done
"$bin/course" release --out "$out/release" >/dev/null
mkdir -p "$subs/cat" "$subs/dan"
cp "$out/release/$file" "$subs/cat/"
{ cat "$source/$file"; echo "not C++"; } >"$subs/dan/transforms_math.cpp"

array=$(sbatch --parsable --array=1-3 --cpus-per-task=1 --output="$out/slice-%a.log" \
  --wrap="'$bin/course' grade-class '$subs' --out \"$out/slice\$SLURM_ARRAY_TASK_ID\" \
--labs transforms --jobs 1 --shard \$SLURM_ARRAY_TASK_ID/\$SLURM_ARRAY_TASK_COUNT")
[ -n "$array" ] || { echo "FAIL: sbatch gave no job id"; exit 1; }
echo "submitted job array $array"
for _ in $(seq 300); do
  [ -z "$(squeue -h -j "$array" 2>/dev/null)" ] && break
  sleep 1
done
[ -z "$(squeue -h -j "$array" 2>/dev/null)" ] || { echo "FAIL: the array did not end in 300 s"; exit 1; }
cat "$out"/slice-*.log

"$bin/course" merge-class "$out/merged" "$out/slice1" "$out/slice2" "$out/slice3"
"$bin/course" grade-class "$subs" --out "$out/one" --labs transforms --jobs 2 >/dev/null 2>&1
if cmp "$out/merged/grades.csv" "$out/one/grades.csv"; then
  echo "PASS: the Slurm array's merged grades.csv is byte-identical to one run's"
  cat "$out/merged/grades.csv"
  cleanup
  rm -rf "$out"
else
  diff "$out/merged/grades.csv" "$out/one/grades.csv"
  echo "FAIL: the merged grades.csv differs from one run's"
  exit 1
fi
