#!/usr/bin/env bash
# What one submission costs on Gradescope's default machine (half a CPU, 768
# MB of memory). The autograder folder (`course gradescope`) is set up once in
# a scratch /autograder (its setup.sh, without apt), as Gradescope builds its
# image; then run_autograder grades two submissions, each on a tree that holds
# the solution:
#   one lab   the solution, with lab 0's C++ files changed (a comment added)
#   all labs  the solution, with every lab's C++ files changed
#   lab 0     an assignment of lab 0 alone (`course gradescope --out DIR
#             pipeline`: its run_autograder and file list put in place), its
#             files submitted with their C++ changed
# each three times: on one core (taskset -c 0); in a cgroup with a CPU quota
# of half a core and a 768 MB memory limit, where root can make one (cgroup v1
# cpu and memory controllers, or v2); and there again without the shader
# cache setup.sh warmed (course-bin/shader-cache), as every submission was
# graded before there was one. Every run has Gradescope's profile: root
# without CAP_SYS_ADMIN, /sys/fs/cgroup read-only (so every lab's child stays
# in the measured cgroup). Prints, per run, the seconds course
# autograde spent copying, building and grading and the total, and the peak
# memory (the cgroup's peak, page cache included), whether the limit
# killed anything, and whether the warmed shader cache served the grading
# (served; missed: Mesa keys it by the CPUs, and a run pinned to one core is
# not on the CPUs setup.sh warmed it on; none), and the CPU seconds of the
# grading (cpu c+l: course's own, plus the labs' children's, from its CPU:
# line; at half a core, grading's wall time is about twice their sum). Needs
# root. Prints figures; it is not a test.
#
#   sudo bench/bench_gradescope.sh
set -euo pipefail
root_dir=$(cd "$(dirname "$0")/.." && pwd)
course="$root_dir/build/bin/course"
[ -x "$course" ] || { echo "bench_gradescope: $course not built; run scripts/setup.sh" >&2; exit 2; }
[ "$(id -u)" -eq 0 ] || { echo "bench_gradescope: needs root (setup.sh, cgroups)" >&2; exit 2; }

work=$(mktemp -d /tmp/bench-gradescope.XXXXXX)
chmod 755 "$work"
# make_cgroup runs in a command substitution (a subshell): the cgroups are
# found again by their names, which carry this script's pid.
cleanup() {
  for g in /sys/fs/cgroup/bench-gradescope-"$$"-* /sys/fs/cgroup/*/bench-gradescope-"$$"-*; do
    if [ -d "$g" ]; then rmdir "$g" 2>/dev/null || true; fi
  done
  rm -rf "$work"
}
trap cleanup EXIT
ag="$work/autograder"
mkdir -p "$ag/results" "$ag/submission"
"$course" gradescope --out "$ag/source" >/dev/null
cp "$ag/source/run_autograder" "$ag/run_autograder"
start=$(date +%s.%N)
SKIP_APT=1 AUTOGRADER_ROOT="$ag" bash "$ag/source/setup.sh" >"$work/setup.log" 2>&1 ||
  { tail -30 "$work/setup.log"; echo "bench_gradescope: setup.sh failed" >&2; exit 1; }
printf 'setup.sh (once, when Gradescope builds the image): %.1f s\n' \
  "$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN {print b - a}')"

mapfile -t files < <(grep -v '^$' "$ag/source/student_files.txt")
declare -A solution
for rel in "${files[@]}"; do solution[$rel]=$(cat "$ag/source/$rel"; printf x); done

# The submission: every student file of the autograder's list flat, as the
# solution has it, those whose path matches $1 with a comment added.
submission() {
  rm -rf "$ag/submission"
  mkdir -p "$ag/submission"
  local rel text listed
  mapfile -t listed < <(grep -v '^$' "$ag/source/student_files.txt")
  for rel in "${listed[@]}"; do
    text=${solution[$rel]%x}
    if [[ $rel == *.cpp && $rel =~ $1 ]]; then text+="// changed $(date +%s%N)"$'\n'; fi
    printf '%s' "$text" >"$ag/submission/$(basename "$rel")"
  done
}

# A cgroup (v1 cpu + memory, else v2) with a CPU quota of $2 of $3 us
# (none when $2 is max) and a memory limit of $4 bytes (none when max); its
# folders, the memory one last; empty where root cannot make one.
make_cgroup() {
  local name="bench-gradescope-$$-$1" quota=$2 period=$3 limit=$4
  if [ -w /sys/fs/cgroup/cpu ] && [ -w /sys/fs/cgroup/memory ] &&
     mkdir "/sys/fs/cgroup/cpu/$name" "/sys/fs/cgroup/memory/$name" 2>/dev/null; then
    echo "$period" >"/sys/fs/cgroup/cpu/$name/cpu.cfs_period_us"
    [ "$quota" = max ] || echo "$quota" >"/sys/fs/cgroup/cpu/$name/cpu.cfs_quota_us"
    [ "$limit" = max ] || echo "$limit" >"/sys/fs/cgroup/memory/$name/memory.limit_in_bytes"
    echo "/sys/fs/cgroup/cpu/$name /sys/fs/cgroup/memory/$name"
  elif [ -f /sys/fs/cgroup/cgroup.controllers ] && mkdir "/sys/fs/cgroup/$name" 2>/dev/null; then
    echo "$quota $period" >"/sys/fs/cgroup/$name/cpu.max"
    echo "$limit" >"/sys/fs/cgroup/$name/memory.max"
    echo "/sys/fs/cgroup/$name"
  fi
}

# Runs run_autograder on the submission now in place, in the cgroup $1 (its
# folders, "" for none), pinned to CPU 0 when $2 is pin; prints a row.
run() {
  local folders=$1 pin=$2 label=$3 machine=$4 log="$work/run.log" peak="?" t0 t1
  local groups=()
  read -r -a groups <<<"$folders"
  local prefix=()
  [ "$pin" = pin ] && prefix=(taskset -c 0)
  # Gradescope's profile: root without CAP_SYS_ADMIN and no cgroup it may
  # write, so that course makes no cgroups of its own, whose labs would run
  # outside this one's quota and memory limit (and outside its peak).
  prefix+=(unshare --mount sh -c
    'mount -t tmpfs -o ro none /sys/fs/cgroup && exec setpriv --bounding-set=-sys_admin -- "$@"' sh)
  t0=$(date +%s.%N)
  ( for g in "${groups[@]}"; do echo $BASHPID >"$g/cgroup.procs"; done
    exec env AUTOGRADER_ROOT="$ag" "${prefix[@]}" bash "$ag/run_autograder" ) >"$log" 2>&1
  t1=$(date +%s.%N)
  if ((${#groups[@]})); then
    local mem=${groups[-1]} kills
    if [ -f "$mem/memory.max_usage_in_bytes" ]; then
      peak="$(($(cat "$mem/memory.max_usage_in_bytes") >> 20)) MB"
      kills=$(awk '/oom_kill / {print $2}' "$mem/memory.oom_control")
    else
      peak="$(($(cat "$mem/memory.peak" 2>/dev/null || echo 0) >> 20)) MB"
      kills=$(awk '/oom_kill / {print $2}' "$mem/memory.events")
    fi
    peak+=", OOM kills ${kills:-?}"
  fi
  layers=$(sed -n 's/^Sandbox: //p' "$log" | tr ';' '\n' | sed -n 's/^ *on: \([^(]*\) (.*/\1/p' |
    paste -sd, -)
  step() { sed -n "s/.*$1.* took \([0-9.]*\) s.*/\1/p" "$log" | tail -1; }
  # Whether the warmed shader cache served the labs' children: course grade
  # notes it when Mesa keyed their cache otherwise (other CPUs than setup.sh's).
  local seed=served
  grep -q 'shader-cache' "$log" || seed=none
  grep -q 'was warmed on a machine whose CPUs differ' "$log" && seed=missed
  # course's CPU seconds and its children's, from the CPU: line of its summary.
  local cpu
  cpu=$(sed -n 's/^CPU: \([0-9.]*\) s in course.*, \([0-9.]*\) s in the labs.*/\1+\2/p' "$log" | tail -1)
  printf '%-9s %-20s %6s %6s %6s %7.1f  %-22s %-6s %-9s %s\n' "$label" "$machine" "$(step copying)" \
    "$(step building)" "$(step grading)" "$(awk -v a="$t0" -v b="$t1" 'BEGIN {print b - a}')" \
    "$peak" "$seed" "${cpu:-?}" \
    "$(sed -n 's/^ *"score": \([0-9.]*\),*$/\1/p' "$ag/results/results.json" | head -1)"
}

printf '%-9s %-20s %6s %6s %6s %7s  %-22s %-6s %-9s %s\n' submission machine copy build grade total \
  "peak memory (cgroup)" cache "cpu c+l" score
for scenario in "one lab:labs/00_" "all labs:labs/" "lab 0:labs/00_"; do
  label=${scenario%%:*}
  pattern=${scenario#*:}
  if [ "$label" = "lab 0" ]; then
    # The same image as the autograder of an assignment of lab 0 alone.
    "$course" gradescope --out "$work/lab0" pipeline >/dev/null
    cp "$work/lab0/run_autograder" "$ag/run_autograder"
    cp "$work/lab0/student_files.txt" "$ag/source/student_files.txt"
  fi
  for machine in "1 core" "half a core, 768 MB" "half, no warm cache"; do
    submission '^$'  # the solution: the tree holds it again (not measured)
    AUTOGRADER_ROOT="$ag" bash "$ag/run_autograder" >/dev/null 2>&1
    submission "^$pattern"
    if [ "$machine" = "1 core" ]; then
      run "$(make_cgroup "${label// /-}-core" max 100000 max)" pin "$label" "$machine"
    else
      group=$(make_cgroup "${label// /-}-${machine//[ ,]/-}" 50000 100000 $((768 << 20)))
      if [ -z "$group" ]; then
        printf '%-9s %-20s (root cannot make a cgroup here)\n' "$label" "$machine"
        continue
      fi
      # Without the shader cache setup.sh warmed: every shader compiles.
      cache="$ag/source/course-bin/shader-cache"
      [ "$machine" = "half, no warm cache" ] && [ -d "$cache" ] && mv "$cache" "$cache.off"
      run "$group" no "$label" "$machine"
      [ -d "$cache.off" ] && mv "$cache.off" "$cache"
    fi
  done
done
echo "sandbox layers on in the last run: ${layers:-unknown}"
