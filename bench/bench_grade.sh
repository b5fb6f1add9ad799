#!/usr/bin/env bash
# Wall time of `course grade`: all labs and each lab alone, with Mesa's shader
# cache cold (MESA_SHADER_CACHE_DISABLE=true) and warm, and --jobs 1 against
# --jobs 2. Goals on a 2-core machine: every lab graded in under 3 s warm;
# --jobs 2 at least 1.6 times faster than --jobs 1. Prints figures (median of
# RUNS runs); it is not a test.
#
#   bench/bench_grade.sh [RUNS=3] [extra course grade options, e.g. --backend osmesa]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
course="$root/build/bin/course"
[ -x "$course" ] || { echo "bench_grade: $course not built; run scripts/setup.sh" >&2; exit 2; }
runs=${1:-3}
shift || true
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

# Median wall seconds of `course grade "$@"` over $runs runs.
median_seconds() {
  local times=()
  for ((i = 0; i < runs; i++)); do
    local start end
    start=$(date +%s.%N)
    "$course" grade --out "$out/r" "$@" >/dev/null 2>&1 || true
    end=$(date +%s.%N)
    times+=("$(awk -v a="$start" -v b="$end" 'BEGIN {print b - a}')")
  done
  printf '%s\n' "${times[@]}" | sort -n | awk '{a[NR]=$1} END {printf "%.2f", a[int((NR+1)/2)]}'
}

labs=$(cd "$root/labs" && for d in [0-9][0-9]_*/; do
  sed -n 's/.*"lab"[[:space:]]*:[[:space:]]*"\([^"]*\)".*/\1/p' "$d/checkpoints.json" | head -1
done)

export MESA_SHADER_CACHE_DIR="$out/mesa-cache"
echo "course grade, median of $runs runs, $(nproc) cores, options: ${*:-(none)}"
cold1=$(MESA_SHADER_CACHE_DISABLE=true median_seconds --jobs 1 "$@")
median_seconds --jobs 1 "$@" >/dev/null  # fills the cache
warm1=$(median_seconds --jobs 1 "$@")
warm2=$(median_seconds --jobs 2 "$@")
cold2=$(MESA_SHADER_CACHE_DISABLE=true median_seconds --jobs 2 "$@")
printf '%-28s %8s %8s\n' "all labs" "cold" "warm"
printf '%-28s %8s %8s\n' "  --jobs 1" "$cold1" "$warm1"
printf '%-28s %8s %8s\n' "  --jobs 2" "$cold2" "$warm2"
awk -v a="$warm1" -v b="$warm2" 'BEGIN {printf "jobs 1 / jobs 2 (warm): %.2f  (goal >= 1.6)\n", a / b}' 
printf 'all labs warm, --jobs 2: %s s  (goal < 3 s)\n' "$warm2"
echo "per lab (--jobs 1):"
for lab in $labs; do
  c=$(MESA_SHADER_CACHE_DISABLE=true median_seconds "$lab" --jobs 1 "$@")
  w=$(median_seconds "$lab" --jobs 1 "$@")
  printf '  %-26s %8s %8s\n' "$lab" "$c" "$w"
done
