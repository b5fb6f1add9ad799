#!/usr/bin/env bash
# Gradescope runs this once, as root, in /autograder/source, when it builds
# the autograder's image (`course gradescope` put it at the top of the folder).
# It installs the packages, builds `lab` and `course`, and creates the
# unprivileged user that submitted code runs as (`course grade --run-as`).
#
#   AUTOGRADER_USER=student   that user (created when missing)
#   SKIP_APT=1                the packages are present: configure and build only
set -euo pipefail

source_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
user=${AUTOGRADER_USER:-student}
cd "$source_dir"

# The project's own set-up installs the missing Debian packages and builds.
# The gradescope preset (CMakePresets.json) builds lab and course only, for
# the submissions' rebuilds: without -Werror (a student's warning is not a
# failure), without a compiler cache (the submission is compiled as the
# user, who has no home for ccache to write in; a launcher named in the
# environment's CMAKE_CXX_COMPILER_LAUNCHER is still used), with the labs'
# precompiled header and without debug information, which together about
# halve the compiling of a submitted lab's files.
if [ "${SKIP_APT:-0}" != 1 ]; then
  env -u CI LAB_PRESET=gradescope bash scripts/setup.sh
fi
cmake --preset gradescope >/dev/null
cmake --build --preset gradescope -j "$(nproc)"

# Mesa's shader cache, warmed once here by rendering every graded frame:
# each lab's child starts from a private copy of it (course grade
# --shader-cache), where it would otherwise compile every shader afresh.
# `course autograde` uses the shader-cache/ beside the course it runs.
warm_cache() {
  "$1/course" warm-cache --lab "$source_dir/build/bin/lab" "$1/shader-cache" >/dev/null ||
    echo "setup.sh: warming the shader cache failed; every submission will compile its shaders cold"
}

if [ "$(id -u)" -ne 0 ]; then
  warm_cache "$source_dir/build/bin"
  echo "setup.sh: not root: no user '$user' and no permissions set; submitted code will run as $(id -un)"
  exit 0
fi
if ! id -u "$user" >/dev/null 2>&1; then
  useradd --system --no-create-home --shell /usr/sbin/nologin "$user"
fi
# The user may read the sources and build and run `lab`, and nothing more: it
# writes nothing of the autograder's, and reads neither references nor
# checkpoint files (hidden checkpoints are the course's), nor the course's
# text of the student shaders in solution_shaders/. `course autograde` and
# `course grade` check this before they grade. Submissions are compiled as the user too, so that an
# #include of a reference or a checkpoint file cannot quote it back in the
# compiler's message; the user owns build/, so the trusted `course` is copied
# out of it, into course-bin/, which stays root's.
chown -R root:root "$source_dir"
chmod -R go-w "$source_dir"
for lab in "$source_dir"/labs/*/; do
  if [ -d "$lab/reference" ]; then chmod 0700 "$lab/reference"; fi
  if [ -f "$lab/checkpoints.json" ]; then chmod 0600 "$lab/checkpoints.json"; fi
done
if [ -d "$source_dir/solution_shaders" ]; then chmod 0700 "$source_dir/solution_shaders"; fi
install -d -m 0755 "$source_dir/course-bin"
install -m 0755 "$source_dir/build/bin/course" "$source_dir/course-bin/course"
rm -rf "$source_dir/course-bin/shader-cache"
warm_cache "$source_dir/course-bin"
chmod -R go-rwx "$source_dir/course-bin/shader-cache" 2>/dev/null || true
chown -R "$user" "$source_dir/build"
echo "setup.sh: built $source_dir/build; submitted code will be built and run as '$user'"
