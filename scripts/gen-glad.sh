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
# GL's enum names, by the registry's groups, for the enums the loader defines:
# the one table the error messages, the record and the usage checks name
# enums from (fw::gl_enum_name).
xml=$(python3 -c 'import glad, os; print(os.path.join(os.path.dirname(glad.__file__), "files", "gl.xml"))')
python3 "$here/scripts/gen-gl-names.py" "$xml" "$out"
echo "gen-glad: wrote $out"
