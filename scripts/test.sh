#!/usr/bin/env bash
# README command 2: installs what is missing, builds, and runs the whole test
# suite, ending in ctest's summary. LAB_PRESET=asan runs it under sanitizers.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
LAB_SETUP_TESTS=1 bash "$root/scripts/setup.sh"
preset=${LAB_PRESET:-}
[ -n "$preset" ] || { [ -n "${CI:-}" ] && preset=ci || preset=default; }
cd "$root"
exec ctest --preset "$preset" -j "$(nproc)" "$@"
