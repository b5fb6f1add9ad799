#!/usr/bin/env bash
# Checks that every C++ file of a tree is formatted as its .clang-format says.
#
#   scripts/check-format.sh              # this repository
#   scripts/check-format.sh DIR          # another tree, e.g. one `course release --out DIR` wrote
#   scripts/check-format.sh --fix [DIR]  # rewrite the files that differ, in place
#
# Files: *.cpp and *.hpp under framework/ grading/ labs/ tests/ bench/ (never
# third_party/). In a git checkout, those git knows: tracked ones and new ones
# it does not ignore; elsewhere (a released tree), every such file on disk.
# Also: a `// STUDENT:` line longer than the column limit (see below). GLSL is
# not checked: clang-format would read it as C++, and the tests quote shader
# line numbers (shaders/tests/broken.frag:9).
#
# Exit status: 0 every file is formatted (or --fix rewrote them), 1 some file
# is not (each is listed with the start of its diff), 2 a usage error or a tree
# without .clang-format, 77 no clang-format on this machine (the test reports
# SKIP; LAB_REQUIRE_CLANG_FORMAT=1 makes that a failure, exit 1, as CI wants).
# CLANG_FORMAT=/path/to/clang-format picks the binary.
#
# clang-format 14 (Debian 12) and 19 (Debian 13) format this tree alike, and
# the check runs each version installed; the constructs where they still
# differ, and how to write them, are in docs/conventions.md, Formatting.
set -euo pipefail

usage() {
  sed -n '2,6p' "$0" | sed 's/^# \{0,1\}//' >&2
  exit "${1:-2}"
}

fix=0
dir=
for arg in "$@"; do
  case $arg in
    --fix) fix=1 ;;
    -h | --help) usage 0 ;;
    -*) echo "check-format: unknown option '$arg'" >&2; usage ;;
    *)
      [ -z "$dir" ] || { echo "check-format: give at most one DIR (got '$dir' and '$arg')" >&2; exit 2; }
      dir=$arg
      ;;
  esac
done
dir=${dir:-$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)}
[ -d "$dir" ] || { echo "check-format: '$dir' is not a directory" >&2; exit 2; }
dir=$(cd "$dir" && pwd)
if [ ! -f "$dir/.clang-format" ]; then
  echo "check-format: $dir has no .clang-format; give the root of the repository or of a released tree" >&2
  exit 2
fi

# The binaries: $CLANG_FORMAT alone, else every clang-format on the PATH
# (clang-format and each clang-format-NN), one per version, so that a machine
# with both 14 and 19 checks what Debian 12 and Debian 13 would each say.
version_of() { "$1" --version | sed -n 's/.*clang-format version \([0-9][0-9.]*\).*/\1/p'; }
cfs=()
if [ -n "${CLANG_FORMAT:-}" ]; then
  command -v "$CLANG_FORMAT" >/dev/null && cfs=("$CLANG_FORMAT")
else
  seen=" "
  for c in clang-format $({ compgen -c clang-format- | grep -E '^clang-format-[0-9]+$' | sort -u -t- -k3 -n; } 2>/dev/null || true); do
    command -v "$c" >/dev/null || continue
    v=$(version_of "$c")
    case $seen in *" $v "*) continue ;; esac
    seen="$seen$v "
    cfs+=("$c")
  done
fi
if ((${#cfs[@]} == 0)); then
  why="clang-format is not installed (apt-get install clang-format, or set CLANG_FORMAT=/path/to/clang-format)"
  [ -n "${CLANG_FORMAT:-}" ] && why="CLANG_FORMAT='$CLANG_FORMAT' is not an executable"
  if [ "${LAB_REQUIRE_CLANG_FORMAT:-0}" = 1 ]; then
    echo "check-format: FAIL: $why; LAB_REQUIRE_CLANG_FORMAT=1 requires it" >&2
    exit 1
  fi
  echo "check-format: SKIP: $why"
  exit 77
fi

# The files, relative to $dir, NUL-separated.
areas=(framework grading labs tests bench)
list_files() {
  if git -C "$dir" rev-parse --is-inside-work-tree >/dev/null 2>&1 &&
    [ "$(git -C "$dir" rev-parse --show-toplevel)" = "$dir" ]; then
    git -C "$dir" ls-files -z --cached --others --exclude-standard -- \
      "${areas[@]/%//*.cpp}" "${areas[@]/%//*.hpp}"
  else
    local existing=()
    for a in "${areas[@]}"; do [ -d "$dir/$a" ] && existing+=("$a"); done
    ((${#existing[@]})) || return 0
    (cd "$dir" && find "${existing[@]}" \( -name third_party -o -name .git \) -prune \
      -o -type f \( -name '*.cpp' -o -name '*.hpp' \) -print0)
  fi
}
files=()
while IFS= read -r -d '' f; do
  case $f in third_party/* | */third_party/*) continue ;; esac
  [ -f "$dir/$f" ] && files+=("$f")  # a tracked file deleted in the working tree: nothing to check
done < <(list_files | sort -z)

if ((${#files[@]} == 0)); then
  echo "check-format: no C++ files under $dir (${areas[*]})" >&2
  exit 2
fi

cd "$dir"
tmp=$(mktemp)
trap 'rm -f "$tmp"' EXIT
total=${#files[@]}
status=0

# check_with CF: the files CF would format otherwise, listed (or rewritten
# with --fix), and its verdict; sets status=1 where some file differs.
check_with() {
  local cf=$1 version err f lines
  version=$(version_of "$cf")
  # A .clang-format this clang-format cannot read (an option it does not
  # know) would otherwise look like a formatting failure of every file.
  if ! err=$("$cf" --style=file --dump-config "${files[0]}" 2>&1 >/dev/null); then
    echo "check-format: clang-format $version cannot use $dir/.clang-format:" >&2
    echo "$err" >&2
    exit 2
  fi
  # clang-format --dry-run --Werror over all files at once names each
  # offending file in "FILE:LINE:COL: error: code should be clang-formatted".
  local flagged=() bad=()
  while IFS= read -r f; do flagged+=("$f"); done < <(
    printf '%s\0' "${files[@]}" |
      { xargs -0 "$cf" --style=file --dry-run --Werror 2>&1 >/dev/null || true; } |
      sed -n 's/^\(.*\):[0-9][0-9]*:[0-9][0-9]*: error: code should be clang-formatted.*/\1/p' |
      sort -u
  )
  for f in "${flagged[@]}"; do
    "$cf" --style=file "$f" >"$tmp"
    cmp -s "$f" "$tmp" && continue
    bad+=("$f")
    if ((fix)); then
      cat "$tmp" >"$f"  # keeps the file's mode
      echo "  fixed $f"
    else
      lines=$({ diff "$f" "$tmp" || true; } | grep -c '^[<>]' || true)
      echo "  $f: $lines lines differ; the start of the diff (- now, + formatted):"
      { diff -U0 "$f" "$tmp" || true; } | sed -n '3,12p' | sed 's/^/      /'
    fi
  done
  if ((${#bad[@]} == 0)); then
    echo "check-format: all $total C++ files under $dir are formatted (clang-format $version)"
  elif ((fix)); then
    echo "check-format: reformatted ${#bad[@]} of $total C++ files under $dir (clang-format $version)"
  else
    echo "check-format: ${#bad[@]} of $total C++ files under $dir are not formatted (clang-format $version);"
    echo "check-format: fix them with: scripts/check-format.sh --fix $dir"
    status=1
  fi
}

# With --fix the first version rewrites and the others then only check: two
# versions that disagree on a construct need it written the way both accept
# (docs/conventions.md, Formatting).
for cf in "${cfs[@]}"; do
  check_with "$cf"
  if ((fix)); then fix=0; fi
done

# clang-format leaves `// STUDENT:` lines alone (CommentPragmas), so it never
# shortens one; the release turns each into a code line, which must fit too.
limit=$(sed -n 's/^ColumnLimit: *\([0-9][0-9]*\).*/\1/p' .clang-format)
# shellcheck disable=SC2016  # $0 is awk's
long=$(printf '%s\0' "${files[@]}" | xargs -0 awk -v limit="${limit:-100}" '
  /^[ \t]*\/\/ STUDENT:/ && length($0) > limit {
    print "  " FILENAME ":" FNR ": a STUDENT line of " length($0) " columns (limit " limit \
      "); split it into two STUDENT lines"
  }')
[ -z "$long" ] || echo "$long"

if [ -n "$long" ]; then
  echo "check-format: $(echo "$long" | wc -l) STUDENT lines are too long (--fix cannot split them)"
  status=1
fi
exit $status
