#!/usr/bin/env bash
# Installs the Debian packages the project needs (Debian 12 or later; only
# those missing), then configures and builds. Idempotent: a second run installs
# nothing and rebuilds only what changed. Sourced by grade.sh and test.sh; also runs alone.
#
#   LAB_PRESET=asan scripts/setup.sh   # another CMake preset (default: default,
#                                      # or ci when $CI is set: warnings are errors)
#   LAB_SETUP_TESTS=1 scripts/setup.sh # also what only the tests need
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)

# Build tools, GL (OSMesa, EGL + Mesa's drivers), window (GLFW, ImGui, Xvfb
# for window tests), and header libraries. docs/contract.md, Set-up.
packages=(
  cmake g++ make pkg-config
  libegl-dev libegl-mesa0 libgl1-mesa-dri libosmesa6-dev
  libglfw3-dev libimgui-dev xvfb xauth
  libglm-dev libstb-dev doctest-dev nlohmann-json3-dev libcli11-dev
  # PNG: libdeflate compresses every PNG written (framework/image.cpp);
  # libspng and libpng only for the encoder benchmark (bench/bench_png).
  libdeflate-dev libspng-dev libpng-dev
  # `lab serve`: HTTP and WebSocket (CivetWeb) and JPEG frames (libjpeg-turbo).
  libcivetweb-dev libturbojpeg0-dev
  # The grading child's seccomp filter.
  libseccomp-dev
  # `course grade-class`: archives, Gradescope's export metadata, git repositories,
  # Canvas's roster (libcsv).
  libarchive-dev libyaml-cpp-dev libgit2-dev libcsv-dev
  # The format test (scripts/check-format.sh); any version from Debian 12's 14 on.
  clang-format
  # The linker CMake picks first: links in a fraction of GNU ld's time.
  mold
)
# What only the tests need (scripts/test.sh sets LAB_SETUP_TESTS=1), so that
# grading, and the autograders' images, go without it: a browser, for the
# tests that look at the reports as a student sees them.
if [ "${LAB_SETUP_TESTS:-0}" = 1 ]; then
  packages+=(chromium python3-html5lib)
  # A one-node Slurm cluster for the sharded class grading's test.
  packages+=(slurmctld slurmd slurm-client munge)
  # Debian 13's clang-format beside Debian 12's, so that the format test on
  # either checks what both would say (scripts/check-format.sh runs each).
  packages+=(clang-format-19)
fi

preset=${LAB_PRESET:-}
if [ -z "$preset" ]; then
  # A student's repository (made by `course release`) has no test suite:
  # build only what a student runs, `lab` and `course`.
  if [ ! -d "$root/tests" ]; then preset=student
  elif [ -n "${CI:-}" ]; then preset=ci; else preset=default; fi
fi
# A compiler cache for a tree with a test suite, from its first build on: the
# tests that build copies of the repository take most of their files from it,
# and only if the suite's own build went through it (were it installed by
# scripts/test.sh alone, after `scripts/grade.sh` built without it, every copy
# would compile every file afresh). An autograder's image goes without. The
# container's image (Dockerfile) keeps the cache of its own build, so that
# the first build of a tree mounted over /labs takes the image's objects.
if [ -d "$root/tests" ]; then
  case $preset in default | ci | egl-only | asan) packages+=(ccache) ;; esac
fi
if [ "$preset" = container ]; then
  packages+=(ccache)
  # ccache keys an object by the variables that change the compiler's
  # messages too (LANG, LC_ALL, LC_CTYPE, LC_MESSAGES, GCC_COLORS), so a
  # mounted tree built with the caller's (a shell's LANG passed in, a
  # -e LANG) would miss every object of the image's build, made with none.
  # Neither build has them, whatever the caller passes in.
  unset LANG LC_ALL LC_CTYPE LC_MESSAGES GCC_COLORS
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}"
  if [ "$(id -u)" -eq 0 ]; then
    sudo=()
  elif command -v sudo >/dev/null; then
    sudo=(sudo)
  else
    echo "setup: these packages are missing and this user is not root and has no sudo:" >&2
    echo "setup:   ${missing[*]}" >&2
    echo "setup: ask an administrator to run: apt-get install ${missing[*]}" >&2
    exit 2
  fi
  "${sudo[@]}" apt-get update -qq
  # Mesa 25.1 dropped OSMesa: where the package no longer exists, build without it.
  if ! apt-cache show libosmesa6-dev >/dev/null 2>&1; then
    echo "setup: libosmesa6-dev is not available on this system; building without the osmesa backend"
    missing=("${missing[@]/libosmesa6-dev/}")
  fi
  if ! apt-cache show clang-format-19 >/dev/null 2>&1; then
    echo "setup: clang-format-19 is not available on this system; the format test checks with clang-format alone"
    missing=("${missing[@]/clang-format-19/}")
  fi
  DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends ${missing[*]}
fi

cd "$root"
cmake --preset "$preset" >/dev/null
cmake --build --preset "$preset" -j "$(nproc)"
echo "setup: built preset '$preset'"
