#!/usr/bin/env bash
# PrairieLearn runs this for each submission, as root, in the grader's image
# (`course prairielearn` put it in serverFilesCourse/gl-labs/, next to the
# checkpoints and references it grades with). `course autograde` does the
# work: it puts the files in /grade/student in place of the student versions
# in /course, rebuilds `lab`, grades it and writes
# /grade/results/results.json, complete whatever the submission does (see
# grading/platforms/autograde.cpp). This shim only maps the environment to its
# options, and writes a results.json of its own if course cannot run at all.
#
#   grade.sh [LAB...]            the labs this question grades (default: all)
#   PL_GRADE_ROOT=/grade         holds student/ and results/
#   PL_COURSE_DIR=/course        the built student version of the course (the image's)
#   AUTOGRADER_USER=student      submitted code is built and run as this user (when root)
#   COURSE_TIMEOUT=60            seconds each lab may run
set -u

root=${PL_GRADE_ROOT:-/grade}
source_dir=${PL_COURSE_DIR:-/course}
data=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
# setup.sh copies the trusted course out of build/ (which the user owns) when
# it runs as root; without that user, the build's own copy is the only one.
course=$source_dir/course-bin/course
[ -x "$course" ] || course=$source_dir/build/bin/course

mkdir -p "$root/results"
rm -f "$root/results/results.json"
"$course" autograde --layout prairielearn --root "$root" --source "$source_dir" --data "$data" \
  --user "${AUTOGRADER_USER:-student}" --timeout "${COURSE_TIMEOUT:-60}" "$@"
status=$?
if [ ! -s "$root/results/results.json" ]; then
  echo "grade.sh: $course autograde left no results.json (exit status $status)"
  cat >"$root/results/results.json" <<'JSON'
{"gradable": false, "score": 0,
 "message": "The grader could not run, so this submission was not graded; please tell the course staff.",
 "output": "", "format_errors": ["The grader could not run; please tell the course staff."],
 "tests": []}
JSON
fi
exit 0
