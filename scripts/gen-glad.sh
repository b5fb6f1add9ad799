#!/usr/bin/env bash
# Regenerates the OpenGL 4.3 core loader in third_party/glad/ from the
# Khronos XML that Debian's python3-glad ships. The output is committed, so
# building never needs this script; run it only to change the API or
# extension list, and commit the result.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
command -v glad >/dev/null || { echo "gen-glad: 'glad' not found; apt-get install python3-glad" >&2; exit 1; }
out="$here/third_party/glad"
rm -rf "$out/include" "$out/src"
glad --reproducible --quiet --api gl:core=4.3 --extensions GL_KHR_debug --out-path "$out" c --debug
echo "gen-glad: wrote $out"
