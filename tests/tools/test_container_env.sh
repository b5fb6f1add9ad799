#!/usr/bin/env bash
# The container's builds (LAB_PRESET=container: the Dockerfile's RUN, then
# its CMD on a mounted tree) compile with the same variables whatever the
# caller passes in, because ccache keys an object by the locale and by
# GCC_COLORS, and the mounted tree's first build must take the image's
# objects (docs/performance.md, The container's first build). setup.sh runs
# with stand-ins for dpkg-query (every package installed) and cmake (which
# writes down what the compiler would see), once with none of the variables
# set, as the image is built, and once with a caller's; the two must agree.
#
#   tests/tools/test_container_env.sh SOURCE_DIR OUT_DIR
set -euo pipefail
src=$1
out=$2
rm -rf "$out"
mkdir -p "$out/bin"
hashed='^(LANG|LC_ALL|LC_CTYPE|LC_MESSAGES|GCC_COLORS)='
cat >"$out/bin/dpkg-query" <<'SH'
#!/bin/sh
printf 'install ok installed'
SH
cat >"$out/bin/cmake" <<SH
#!/bin/sh
{ echo "cmake \$*"; env | grep -E '$hashed' | sort; } >>"\$LAB_TEST_ENV_OUT"
SH
chmod +x "$out/bin/dpkg-query" "$out/bin/cmake"

run_setup() { # NAME VAR=VALUE...
  local name=$1
  shift
  env -i PATH="$out/bin:/usr/bin:/bin" HOME="$out" LAB_PRESET=container \
    LAB_TEST_ENV_OUT="$out/$name.env" "$@" bash "$src/scripts/setup.sh" >"$out/$name.log" 2>&1 ||
    { echo "FAIL: setup.sh ($name) failed:" >&2; cat "$out/$name.log" >&2; exit 1; }
}
run_setup image
run_setup caller LANG=de_DE.UTF-8 LC_ALL=fr_FR.UTF-8 LC_CTYPE=C.UTF-8 LC_MESSAGES=C GCC_COLORS='error=01;31'

grep -q -- '--build --preset container' "$out/image.env" ||
  { echo "FAIL: setup.sh did not build the container preset:" >&2; cat "$out/image.env" >&2; exit 1; }
if ! diff -u "$out/image.env" "$out/caller.env"; then
  echo "FAIL: with the caller's locale, the container's build compiles with other variables" >&2
  echo "      than the image's build: ccache would miss every object the image keeps" >&2
  exit 1
fi
echo "PASS: the container's build compiles with the same variables whatever the caller's locale"
