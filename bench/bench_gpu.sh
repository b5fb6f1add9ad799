#!/usr/bin/env bash
# The benchmarks on a machine that has a GPU but no build of the course: the
# programs built here, and the shared libraries they need that such a machine
# may lack, are staged into one folder; there, run from a copy of this
# repository, they print every figure of bench/bench_grade.sh, bench_draw,
# bench_context and bench_floor in one run. Prints figures; it is not a test.
#
#   bench/bench_gpu.sh stage [BUILD=build-egl-only] [DIR=build-gpu]
#       copies lab, course, bench_floor, bench_draw and bench_context from
#       BUILD/bin into DIR/bin without their debug information, and into
#       DIR/lib every library `ldd` lists for them except the C library's
#       own, the GL and EGL dispatch libraries and the C++ runtime (the GPU
#       machine's own, which its driver uses);
#       DIR/source names the folder the programs were built from (they read
#       labs/ and shaders/ there)
#   bench/bench_gpu.sh run [DIR=build-gpu] [RUNS=3]
#       on the GPU machine, from the repository's root: the driver and the GPU
#       in a line, bench_context, bench_draw, bench_floor RUNS, then
#       bench/bench_grade.sh RUNS with DIR's programs. When the folder the
#       programs were built from is missing there, it is made a link to this
#       repository's root (root may need to run it for that).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
me=bench_gpu
die() { printf '%s: %s\n' "$me" "$*" >&2; exit 2; }
programs=(lab course bench_floor bench_draw bench_context)

stage() {
  local build=${1:-build-egl-only} dir=${2:-build-gpu}
  case $build in /*) ;; *) build=$root/$build ;; esac
  case $dir in /*) ;; *) dir=$root/$dir ;; esac
  [ -f "$build/CMakeCache.txt" ] || die "$build is not a build folder (no CMakeCache.txt); make one with cmake --preset egl-only && cmake --build --preset egl-only"
  rm -rf "$dir"
  mkdir -p "$dir/bin" "$dir/lib"
  local exe
  for exe in "${programs[@]}"; do
    [ -x "$build/bin/$exe" ] || die "$build/bin/$exe not built"
    strip --strip-debug -o "$dir/bin/$exe" "$build/bin/$exe"
  done
  # What the GPU machine's own libraries provide is left out: glibc's, GL's
  # and EGL's dispatch (libglvnd), which its driver plugs into, and the C++
  # runtime, which the driver may need at its own (newer) version.
  local skip='^(linux-vdso|ld-linux|libc|libm|libdl|libpthread|librt|libGL|libEGL|libOpenGL|libGLX|libGLdispatch|libstdc\+\+|libgcc_s)[.-]'
  for exe in "${programs[@]}"; do ldd "$dir/bin/$exe"; done |
    awk '$2 == "=>" && $3 ~ /^\// {print $1, $3}' | sort -u |
    while read -r name path; do
      [[ $name =~ $skip ]] || cp -L "$path" "$dir/lib/$name"
    done
  sed -n 's/^CMAKE_HOME_DIRECTORY:INTERNAL=//p' "$build/CMakeCache.txt" >"$dir/source"
  printf '%s: %s (%s)\n' "$me" "$dir" "$(du -sh "$dir" | cut -f1)"
}

run() {
  local dir=${1:-build-gpu} runs=${2:-3}
  case $dir in /*) ;; *) dir=$root/$dir ;; esac
  [ -x "$dir/bin/course" ] || die "$dir/bin/course missing; stage it with: bench/bench_gpu.sh stage"
  local source
  source=$(cat "$dir/source")
  if [ ! -e "$source" ]; then
    { mkdir -p "$(dirname "$source")" && ln -s "$root" "$source"; } ||
      die "the programs read $source, which is missing and cannot be made a link to $root"
  fi
  [ "$(cd "$source" && pwd -P)" = "$(cd "$root" && pwd -P)" ] ||
    printf '%s: note: the programs read labs and shaders from %s, not from %s\n' "$me" "$source" "$root"
  export LD_LIBRARY_PATH="$dir/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
  if command -v nvidia-smi >/dev/null; then
    nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv,noheader || true
  fi
  echo "$(nproc) cores"
  "$dir/bin/bench_context"
  "$dir/bin/bench_draw"
  "$dir/bin/bench_floor" "$runs"
  LAB_BIN="$dir/bin" "$root/bench/bench_grade.sh" "$runs"
}

case ${1:-} in
  stage) shift; stage "$@" ;;
  run) shift; run "$@" ;;
  *) sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//' >&2; exit 2 ;;
esac
