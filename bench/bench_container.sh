#!/usr/bin/env bash
# The container's first page as a user meets it (docs/running.md says how
# it is run), without a container runtime: the Dockerfile's build,
# `scripts/setup.sh` with the image's variables and no others (LAB_PRESET=
# container, a fresh CCACHE_DIR) in a copy of the commit without its .git, as
# `COPY . /labs` makes it; then that copy replaced by a fresh `git clone` of
# the same commit, as `-v "$PWD:/labs"` mounts it over the image's, and the
# image's command run there with the image's variables plus the caller's
# locale (CALLER_LANG, default C.UTF-8: a shell's LANG that reaches the
# container). Prints, with the goal beside it:
#   the image's build (seconds, compilations, cache hits)
#   the first page after the command starts      <= 60 s
#   the command's compilations that hit the image's cache
# Prints figures; it is not a test. Installs the packages setup.sh lists
# where they are missing (as the image's build does).
#
#   bench/bench_container.sh [LAB=pipeline]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
lab=${1:-pipeline}
caller_lang=${CALLER_LANG:-C.UTF-8}
work=$(mktemp -d)
serve_pid=""
trap '[ -z "$serve_pid" ] || kill "$serve_pid" 2>/dev/null || true; rm -rf "$work"' EXIT
port=$((20000 + $$ % 10000))

image_env=(env -i PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin HOME=/root
  LAB_PRESET=container CCACHE_DIR="$work/ccache" LAB="$lab")
now() { date +%s.%N; }
since() { awk -v a="$1" -v b="$(now)" 'BEGIN {printf "%.1f", b - a}'; }
stats() { CCACHE_DIR="$work/ccache" ccache --print-stats | awk -F'\t' -v k="$1" '$1 == k {print $2}'; }

# The image: the commit's files without .git (.dockerignore leaves it out).
mkdir -p "$work/labs"
git -C "$root" archive HEAD | tar -x -C "$work/labs"
start=$(now)
(cd "$work/labs" && "${image_env[@]}" bash scripts/setup.sh >"$work/image.log" 2>&1) ||
  { tail -n 20 "$work/image.log" >&2; echo "bench_container: the image's build failed" >&2; exit 1; }
image_s=$(since "$start")
hits() { echo $(($(stats direct_cache_hit) + $(stats preprocessed_cache_hit))); }
echo "the image's build: ${image_s} s, $(($(hits) + $(stats cache_miss))) compilations, $(hits) cache hits"

# The mount: a fresh clone of the same commit, with its .git, over the image's tree.
rm -rf "$work/labs"
git clone -q "$root" "$work/labs"
git -C "$work/labs" checkout -q "$(git -C "$root" rev-parse HEAD)"
CCACHE_DIR="$work/ccache" ccache --zero-stats >/dev/null
start=$(now)
# One process from here to `lab serve` (each step execs the next), so that
# its pid is the server's, stopped on the way out.
(cd "$work/labs" && exec "${image_env[@]}" TERM=xterm LANG="$caller_lang" bash -c \
  "bash scripts/setup.sh >'$work/cmd.log' 2>&1 && exec build-container/bin/lab serve \"\$LAB\" --host 127.0.0.1 --port $port" \
  >"$work/serve.log" 2>&1) &
serve_pid=$!
page=""
for ((i = 0; i < 9000; i++)); do  # up to 15 minutes, every 0.1 s
  if python3 -c "import urllib.request; urllib.request.urlopen('http://127.0.0.1:$port/', timeout=1)" 2>/dev/null; then
    page=$(since "$start")
    break
  fi
  kill -0 "$serve_pid" 2>/dev/null || break  # the build failed, or the server ended
  sleep 0.1
done
hits=$(hits)
misses=$(stats cache_miss)
[ -n "$page" ] || { tail -n 20 "$work/cmd.log" "$work/serve.log" >&2; echo "bench_container: no page (the command ended, or 15 minutes passed)" >&2; exit 1; }
awk -v v="$page" -v l="$caller_lang" 'BEGIN {
  printf "%-44s %8s   goal <= 60     %s\n", "first page after the command starts (s)", v, (v <= 60) ? "met" : "NOT met"
  printf "  (a fresh git clone mounted, the caller'"'"'s LANG=%s)\n", l }'
echo "the command's compilations: $hits hits in the image's cache, $misses compiled afresh"
