#!/usr/bin/env bash
# Proves the README on a fresh Debian: builds a minimal SUITE system with
# debootstrap (minbase, plus git, sudo and ca-certificates, nothing else),
# clones this repository into it, runs the README's two commands exactly as
# written, as root in /root/gl-labs, and prints each one's exit status, its time
# and the versions of Mesa, GCC, CMake, Dear ImGui and GLFW that the set-up
# installed.
#
#   scripts/fresh-debian.sh trixie          # bookworm, trixie, forky (testing), sid
#   scripts/fresh-debian.sh --keep forky    # keep the system afterwards (path printed)
#   scripts/fresh-debian.sh --student trixie
#       the student's side instead: builds `course` (LAB_PRESET=student
#       scripts/setup.sh), writes the student repository with `course release`,
#       and runs the student README's two commands there (scripts/setup.sh,
#       then scripts/grade.sh transforms on the starting code): the set-up must
#       build only lab and course, and the starting code must score low with
#       the sentence that says so (exit 1)
#
# Environment:
#   FRESH_DEBIAN_MIRROR  Debian mirror (default http://deb.debian.org/debian)
#   FRESH_DEBIAN_DIR     where the system is made (default /var/tmp)
#   FRESH_DEBIAN_CACHE   a folder kept between runs for downloaded .deb files
#                        (default: none, everything is downloaded)
#   FRESH_DEBIAN_UNSHARE 0: mount in this namespace even where unshare works
#   FRESH_DEBIAN_TEST_ARGS
#                        arguments added to the second command, as ctest
#                        takes them (CI passes -LE "release|...": the tests
#                        that build copies of the tree ran in its first step);
#                        printed with the command
#   CI, LAB_REQUIRE_BACKENDS, LAB_REQUIRE_CLANG_FORMAT, LAB_REQUIRE_BROWSER
#                        passed into the system when set (CI=true makes
#                        warnings errors there too; LAB_REQUIRE_BACKENDS=built
#                        fails a test that skips a backend the build has;
#                        LAB_REQUIRE_CLANG_FORMAT=1 one that skips the format
#                        check; LAB_REQUIRE_BROWSER=1 one that skips for want
#                        of Chromium)
#
# Needs root (or sudo) for debootstrap, chroot and mounts. Everything mounted
# lives in a private mount namespace (unshare) where the machine allows one, so
# the mounts vanish with the run even when it is killed; either way a trap
# unmounts them, and the system is removed only after a check that nothing
# under it is still mounted. Exit status: 0 both commands passed, 1 one failed,
# 2 a usage or set-up error.
set -euo pipefail

me=fresh-debian
say() { printf '%s: %s\n' "$me" "$*"; }
die() { printf '%s: %s\n' "$me" "$*" >&2; exit 2; }
usage() {
  sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//' >&2
  exit 2
}

# --- Internal: the part that runs inside the namespaces (or directly). -------
# fresh-debian.sh --inside SUITE TARGET REPO RESULTS MODE (staff or student)
inside() {
  local suite=$1 target=$2 repo=$3 results=$4 mode=${5:-staff}
  local mirror=${FRESH_DEBIAN_MIRROR:-http://deb.debian.org/debian}
  local cache=${FRESH_DEBIAN_CACHE:-}

  inside_target=$target  # global: the EXIT trap runs after this function has returned
  trap 'unmount_under "$inside_target"' EXIT
  trap 'exit 130' INT
  trap 'exit 143' TERM

  # debootstrap knows the suites of its own release; a newer one (forky on a
  # Debian 12 host) is made with the script of sid, which every release has.
  local script=/usr/share/debootstrap/scripts/$suite
  [ -e "$script" ] || script=/usr/share/debootstrap/scripts/sid
  local -a cache_args=()
  if [ -n "$cache" ]; then
    mkdir -p "$cache/$suite/debootstrap" "$cache/$suite/apt/partial"
    cache_args=(--cache-dir="$cache/$suite/debootstrap")
  fi
  say "debootstrap $suite from $mirror (minbase, git, sudo, ca-certificates)"
  local t0=$SECONDS
  if ! debootstrap --variant=minbase --include=git,sudo,ca-certificates "${cache_args[@]}" \
    "$suite" "$target" "$mirror" "$script" >"$results/debootstrap.log" 2>&1; then
    tail -n 30 "$results/debootstrap.log" >&2
    die "debootstrap $suite failed (log above)"
  fi
  say "debootstrap took $((SECONDS - t0)) s"

  # The archive as a fresh install has it: the suite, and for a stable release
  # its updates and security updates.
  {
    echo "deb $mirror $suite main"
    case $suite in
      bookworm | trixie)
        echo "deb $mirror $suite-updates main"
        echo "deb ${mirror%/debian}/debian-security $suite-security main"
        ;;
    esac
  } >"$target/etc/apt/sources.list"
  cp /etc/resolv.conf "$target/etc/resolv.conf"
  # No init runs in a chroot: packages must not try to start services.
  printf '#!/bin/sh\nexit 101\n' >"$target/usr/sbin/policy-rc.d"
  chmod 755 "$target/usr/sbin/policy-rc.d"

  mount -t proc proc "$target/proc"
  mount --rbind /sys "$target/sys"
  mount --rbind /dev "$target/dev"
  mount --make-rslave "$target/sys"
  mount --make-rslave "$target/dev"
  if [ -n "$cache" ]; then
    mount --bind "$cache/$suite/apt" "$target/var/cache/apt/archives"
  else
    # Installed packages' .deb files are deleted, as Debian's container
    # images do: a gigabyte less on the disk, the same system.
    echo 'APT::Keep-Downloaded-Packages "false";' >"$target/etc/apt/apt.conf.d/99fresh-debian-no-archives"
  fi
  mkdir -p "$target/mnt/origin"
  mount --bind -o ro "$repo" "$target/mnt/origin"
  mount -o remount,bind,ro "$target/mnt/origin"

  local -a env=(HOME=/root LANG=C.UTF-8 "PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin")
  [ -n "${CI:-}" ] && env+=("CI=$CI")
  [ -n "${LAB_REQUIRE_BACKENDS:-}" ] && env+=("LAB_REQUIRE_BACKENDS=$LAB_REQUIRE_BACKENDS")
  [ -n "${LAB_REQUIRE_CLANG_FORMAT:-}" ] && env+=("LAB_REQUIRE_CLANG_FORMAT=$LAB_REQUIRE_CLANG_FORMAT")
  [ -n "${LAB_REQUIRE_BROWSER:-}" ] && env+=("LAB_REQUIRE_BROWSER=$LAB_REQUIRE_BROWSER")
  in_root() { chroot "$target" /usr/bin/env -i "${env[@]}" "$@"; }

  # A testing suite's Release file can expire on a mirror that lags; only
  # there is the date check turned off, and the run says so.
  if ! in_root apt-get update -qq >"$results/apt-update.log" 2>&1; then
    if grep -qiE 'no longer valid|expired' "$results/apt-update.log" &&
      [[ $suite != bookworm && $suite != trixie ]]; then
      say "the $suite Release file on the mirror has expired: setting Acquire::Check-Valid-Until=false for $suite only"
      echo 'Acquire::Check-Valid-Until "false";' >"$target/etc/apt/apt.conf.d/99fresh-debian-valid-until"
      in_root apt-get update -qq >"$results/apt-update.log" 2>&1 ||
        { cat "$results/apt-update.log" >&2; die "apt-get update failed in $suite"; }
    else
      cat "$results/apt-update.log" >&2
      die "apt-get update failed in $suite"
    fi
  fi

  in_root git clone -q --no-hardlinks /mnt/origin /root/gl-labs
  say "cloned $(in_root git -C /root/gl-labs log -1 --format='%h %s')"

  # One step: its command in the system, its log and "STATUS SECONDS".
  run_step() {
    local step=$1 command=$2
    say "running $step in $suite: $command"
    t0=$SECONDS
    set +e
    in_root bash -c "$command" 2>&1 | tee "$results/$step.log" | sed -u "s/^/[$suite] /"
    status=${PIPESTATUS[0]}
    set -e
    seconds=$((SECONDS - t0))
    echo "$status $seconds" >"$results/$step.status"
  }
  local step status=0 seconds
  if [ "$mode" = student ]; then
    run_step course "cd /root/gl-labs && LAB_PRESET=student scripts/setup.sh"
    run_step release "cd /root/gl-labs && build/bin/course release --out /root/student"
    run_step student-setup "cd /root/student && scripts/setup.sh"
    run_step student-grade "cd /root/student && scripts/grade.sh transforms"
    in_root bash -c 'cd /root/student/build/bin && ls' >"$results/student-built" 2>&1 || true
  else
    run_step grade "cd /root/gl-labs && scripts/grade.sh"
    run_step test "cd /root/gl-labs && scripts/test.sh${FRESH_DEBIAN_TEST_ARGS:+ $FRESH_DEBIAN_TEST_ARGS}"
  fi

  # The disk the system took, the build and its tests' files with it.
  du -sx --block-size=1M "$target" 2>/dev/null | cut -f1 >"$results/disk_mb" || true

  # What the set-up installed.
  in_root dpkg-query -W -f='${Package} ${Version}\n' libegl-mesa0 libosmesa6-dev g++ cmake \
    libimgui-dev libglfw3-dev 2>/dev/null >"$results/versions" || true
  in_root cat /etc/debian_version >"$results/debian_version" 2>/dev/null || true
  in_root g++ -dumpfullversion >"$results/gcc_version" 2>/dev/null || true
}

# Unmounts everything at or below $1 (deepest first) after stopping what still
# runs there; says what it could not unmount.
unmount_under() {
  local target=$1 pid m
  for pid in /proc/[0-9]*; do
    [ "$(readlink "$pid/root" 2>/dev/null)" = "$target" ] && kill -KILL "${pid#/proc/}" 2>/dev/null
  done
  # Deepest first; a point listed twice (stacked mounts) or unmounted by
  # another unmount_under meanwhile is no failure.
  for m in $(mounts_under "$target" | sort -r); do
    umount "$m" 2>/dev/null || umount -l "$m" 2>/dev/null ||
      ! mounts_under "$target" | grep -qxF "$m" || say "could not unmount $m"
  done
  return 0
}

# Mount points at or below $1 in this mount namespace.
mounts_under() {
  awk -v t="$1" '$5 == t || index($5, t "/") == 1 { print $5 }' /proc/self/mountinfo
}

# The tests ctest skipped and the parts of tests that skipped themselves, each
# with the reason the test printed (SKIP lines in ctest's log).
skipped() {
  local summary=$1 log=$2 name
  local -a names=()
  mapfile -t names < <(sed -n '/tests did not run/,/^$/p' "$summary" 2>/dev/null |
    sed -nE 's/^[[:space:]]*[0-9]+ - ([^ ]+) \(Skipped\).*/\1/p')
  if ((${#names[@]})); then
    say "  skipped tests:"
    local reason
    for name in "${names[@]}"; do
      reason=$(awk -v t="$name" '
        $0 ~ "^[0-9]+/[0-9]+ Test: " t "$" { on = 1; next }
        on && /^SKIP/ { print; exit }
        on && /^Test time/ { on = 0 }' "$log" 2>/dev/null)
      say "    $name: ${reason:-(no SKIP line in the ctest log)}"
    done
  fi
  local parts
  parts=$(grep -E '^SKIP .*\(backend [a-z]+\)' "$log" 2>/dev/null | sort -u)
  if [ -n "$parts" ]; then
    say "  parts of tests skipped:"
    while IFS= read -r line; do say "    $line"; done <<<"$parts"
  fi
  if ((${#names[@]} == 0)) && [ -z "$parts" ]; then say "  nothing skipped"; fi
}

version_of() { awk -v p="$1" '$1 == p { print $2 }' "$2"; }

# The student's side (--student): course built, the release written, the
# student's set-up building only lab and course, and the starting code of
# lab 1 scoring low with the sentence that says so.
report_student() {
  local results=$1 step status seconds failed=0 expected
  for step in course release student-setup student-grade; do
    if [ ! -f "$results/$step.status" ]; then
      say "  $step: did not run"
      failed=1
      continue
    fi
    read -r status seconds <"$results/$step.status"
    expected=0
    [ "$step" = student-grade ] && expected=1
    say "  $step: exit $status in ${seconds} s$( [ "$step" = student-grade ] && grep -E '^Total:' "$results/$step.log" | tail -n 1 | sed 's/^/: /')"
    [ "$status" -eq "$expected" ] || { say "    expected exit $expected"; failed=1; }
  done
  if ! grep -q "starting copy scores low" "$results/student-grade.log" 2>/dev/null; then
    say "  the starting code's grade does not say that a starting copy scores low"
    failed=1
  fi
  local built
  built=$(tr '\n' ' ' <"$results/student-built" 2>/dev/null)
  say "  the student's build/bin: ${built:-nothing}"
  [ "$built" = "course lab " ] || { say "    expected only course and lab"; failed=1; }
  return "$failed"
}

report() {
  local suite=$1 results=$2 step status seconds summary
  local v=$results/versions
  echo
  say "$suite (Debian $(cat "$results/debian_version" 2>/dev/null || echo '?'))"
  say "  Mesa $(version_of libegl-mesa0 "$v"), GCC $(cat "$results/gcc_version" 2>/dev/null) (g++ $(version_of g++ "$v")), CMake $(version_of cmake "$v"), imgui $(version_of libimgui-dev "$v"), GLFW $(version_of libglfw3-dev "$v")"
  local osmesa
  osmesa=$(version_of libosmesa6-dev "$v")
  say "  OSMesa: ${osmesa:-not installed (not in $suite)}"
  [ -s "$results/disk_mb" ] && say "  disk: the system took $(cat "$results/disk_mb") MB at the end"
  local failed=0
  if [ -f "$results/student-grade.status" ]; then
    report_student "$results" || failed=1
    return "$failed"
  fi
  for step in grade test; do
    if [ ! -f "$results/$step.status" ]; then
      say "  scripts/$step.sh: did not run"
      failed=1
      continue
    fi
    read -r status seconds <"$results/$step.status"
    case $step in
      grade) summary=$(grep -E '^Total:' "$results/$step.log" | tail -n 1) ;;
      test) summary=$(grep -E 'tests passed|tests failed' "$results/$step.log" | tail -n 1) ;;
    esac
    say "  scripts/$step.sh: exit $status in ${seconds} s: ${summary:-no summary line}"
    [ "$status" -eq 0 ] || failed=1
  done
  skipped "$results/test.log" "$target/root/gl-labs/build/Testing/Temporary/LastTest.log"
  return "$failed"
}

# --- Main. ---------------------------------------------------------------
if [ "${1:-}" = --inside ]; then
  shift
  inside "$@"
  exit 0
fi

keep=0
mode=staff
suite=
for arg in "$@"; do
  case $arg in
    --keep) keep=1 ;;
    --student) mode=student ;;
    -h | --help) usage ;;
    -*) say "unknown option '$arg'" >&2; usage ;;
    *) [ -z "$suite" ] || usage; suite=$arg ;;
  esac
done
case $suite in
  bookworm | trixie | forky | testing | sid | unstable) ;;
  '') usage ;;
  *) die "unknown suite '$suite'; choose bookworm, trixie, forky, testing or sid" ;;
esac

if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || die "needs root for debootstrap, chroot and mounts; run it as root"
  exec sudo --preserve-env=FRESH_DEBIAN_MIRROR,FRESH_DEBIAN_DIR,FRESH_DEBIAN_CACHE,FRESH_DEBIAN_UNSHARE,FRESH_DEBIAN_TEST_ARGS,CI,LAB_REQUIRE_BACKENDS,LAB_REQUIRE_CLANG_FORMAT,LAB_REQUIRE_BROWSER \
    bash "$0" "$@"
fi

repo=$(cd "$(dirname "$0")/.." && pwd)
git -C "$repo" rev-parse --git-dir >/dev/null 2>&1 || die "$repo is not a git repository"
if ! command -v debootstrap >/dev/null; then
  say "installing debootstrap"
  if ! { apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq debootstrap >/dev/null; }; then
    die "could not install debootstrap (apt-get install debootstrap)"
  fi
fi

parent=${FRESH_DEBIAN_DIR:-/var/tmp}
mkdir -p "$parent"
dir=$(mktemp -d "$parent/fresh-debian-$suite.XXXXXX")
[[ $dir != *[[:space:]]* ]] || die "FRESH_DEBIAN_DIR must not contain spaces: '$parent'"
target=$dir/root
results=$dir/results
mkdir -p "$target" "$results"

child=
cleanup() {
  local rc=$?
  trap - EXIT INT TERM
  if [ -n "$child" ] && kill -0 "$child" 2>/dev/null; then
    # Under unshare the run is the namespace's first process (unshare itself
    # ignores SIGINT and SIGTERM while it waits): killing it ends every process
    # in the namespace and with them its mounts. Without unshare the run gets
    # SIGTERM, and what still runs in the system is killed below.
    local init
    for init in $(cat /proc/"$child"/task/*/children 2>/dev/null); do
      kill -KILL "$init" 2>/dev/null || true
    done
    kill -TERM "$child" 2>/dev/null || true
    unmount_under "$target"
    wait "$child" 2>/dev/null || true
  fi
  unmount_under "$target"
  local left
  left=$(mounts_under "$target")
  if [ -n "$left" ]; then
    say "still mounted under $target, so it is not removed:" >&2
    printf '  %s\n' "$left" >&2
    exit 2
  fi
  say "nothing is mounted under $target"
  if ((keep)); then
    say "kept the system in $target (logs in $results)"
  else
    rm -rf --one-file-system "$dir"
  fi
  exit "$rc"
}
trap cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM

# A private mount and PID namespace: the mounts and every process in the
# system end with the run, however it ends.
if [ "${FRESH_DEBIAN_UNSHARE:-1}" = 0 ]; then
  say "FRESH_DEBIAN_UNSHARE=0: mounting in this namespace, unmounted by the trap"
  runner=(bash "$0" --inside)
elif unshare --mount --propagation private --pid --fork true 2>/dev/null; then
  runner=(unshare --mount --propagation private --pid --fork bash "$0" --inside)
else
  say "no mount namespace here (unshare failed): mounting in this namespace, unmounted by the trap"
  runner=(bash "$0" --inside)
fi
say "disk: $(df --output=avail -BG "$parent" | tail -n 1 | tr -d ' ') free in $parent"
t_all=$SECONDS
"${runner[@]}" "$suite" "$target" "$repo" "$results" "$mode" &
child=$!
set +e
wait "$child"
inside_status=$?
set -e
child=
((inside_status == 0)) || die "setting up $suite failed (exit $inside_status)"

status=0
report "$suite" "$results" || status=1
say "total $((SECONDS - t_all)) s"
exit "$status"
