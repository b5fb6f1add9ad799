#!/usr/bin/env bash
# A class to measure `course grade-class` with: N submissions made from the
# student release (about a tenth starting copies, a tenth that do not build,
# one hostile pair: a crash and an archive that climbs out of its folder;
# the rest the solution with one of the mistake suite's mistakes, or none),
# graded twice (the second run finds nothing changed), for two assignments:
# one lab, and all eleven. Prints, with the goals beside them:
#   one lab:  CPU per submission, build included        <= 1.5 s
#             a class of 200 on 2 cores                  <= 3 min
#   all labs: CPU per submission, build included        <= 8 s
#             a class of 200 on 2 cores                  <= 15 min (16 cores: <= 2 min)
#   the second run, nothing changed, 200 submissions     <= 5 s
# and the baseline, the same labs graded by `course grade --jobs 1` of the
# built solution (no unpacking, no building): the ratio says what taking,
# building and keeping each submission adds. A class of N is scaled to 200 in
# the "for 200" column (the work is linear in N). Peak memory is the largest
# process's (RUSAGE_CHILDREN). Prints figures; it is not a test.
#
#   bench/bench_class.sh [N=200] [ONE_LAB=framebuffer-ops] [--jobs J]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=${LAB_BIN:-$root/build/bin}
[ -x "$bin/course" ] && [ -x "$bin/lab" ] ||
  { echo "bench_class: $bin/course and lab not built; run scripts/setup.sh" >&2; exit 2; }
n=${1:-200}
one_lab=${2:-framebuffer-ops}
jobs=$(nproc)
[ "${3:-}" = --jobs ] && jobs=$4
work=$(mktemp -d)
[ -n "${BENCH_CLASS_KEEP:-}" ] && echo "bench_class: keeping $work"
trap '[ -n "${BENCH_CLASS_KEEP:-}" ] || rm -rf "$work"' EXIT

"$bin/course" release --out "$work/release" >/dev/null

# make_class DIR LABS: N submissions of the student files of LABS ("" all).
make_class() {
  python3 - "$root" "$work/release" "$1" "$n" "$2" <<'PY'
import json, os, re, shutil, sys, zipfile
root, release, out, n, labs = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4]), sys.argv[5]
def lab_dirs():
    dirs = sorted(d for d in os.listdir(os.path.join(root, "labs")) if re.match(r"\d\d_", d))
    if not labs:
        return dirs
    wanted = set(labs.split(","))
    # A lab's name is its folder's without the number, "_" as "-".
    return [d for d in dirs if d in wanted or d[3:].replace("_", "-") in wanted]
dirs = lab_dirs()
files = []
for top in ("labs", "shaders"):
    for d in dirs:
        base = os.path.join(root, top, d)
        for name in sorted(os.listdir(base)) if os.path.isdir(base) else []:
            path = os.path.join(base, name)
            if os.path.isfile(path) and "BEGIN SOLUTION" in open(path, errors="replace").read():
                files.append(os.path.join(top, d, name))
text = open(os.path.join(root, "tests/mistakes/mistakes.hpp")).read()
body = text[text.index('R"json(') + 7:text.index(')json"')]
body = "\n".join(l for l in body.splitlines() if not l.strip().startswith("//"))
mistakes = [m for m in json.loads(body)["mistakes"] if m["lab"] in dirs]
os.makedirs(out)
for i in range(n):
    name = "s%03d" % i
    src = release if i % 10 == 3 else root
    chosen = {f: open(os.path.join(src, f), errors="surrogateescape").read() for f in files}
    if i % 10 == 7:  # does not build
        cpp = [f for f in files if f.endswith(".cpp")]
        chosen[cpp[i % len(cpp)]] += "\nthis is not C++;\n"
    elif i == 1:  # hostile: crashes as it starts
        cpp = [f for f in files if f.endswith(".cpp")][0]
        chosen[cpp] = '#include <cstdlib>\nstatic int crash = (std::abort(), 0);\n' + chosen[cpp]
    elif i % 10 not in (3, 0) and mistakes:
        m = mistakes[i % len(mistakes)]
        chosen[m["file"]] = chosen[m["file"]].replace(m["find"], m["replace"], 1)
    if i == 2:  # hostile: an archive with a path outside its folder
        with zipfile.ZipFile(os.path.join(out, name + ".zip"), "w") as z:
            z.writestr("../../escaped.cpp", "int escaped;")
        continue
    for f, t in chosen.items():
        os.makedirs(os.path.dirname(os.path.join(out, name, f)), exist_ok=True)
        with open(os.path.join(out, name, f), "w", errors="surrogateescape") as o:
            o.write(t)
PY
}

# measure LABEL COMMAND...: wall s, CPU s (children), peak RSS MB.
measure() {
  python3 - "$@" <<'PY'
import resource, subprocess, sys, time
start = time.monotonic()
subprocess.run(sys.argv[2:], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
wall = time.monotonic() - start
r = resource.getrusage(resource.RUSAGE_CHILDREN)
print("%s %.2f %.2f %.0f" % (sys.argv[1], wall, r.ru_utime + r.ru_stime, r.ru_maxrss / 1024))
PY
}

# build_cpu OUT: the sum of the rows' build CPU.
build_cpu() {
  python3 -c 'import glob, json, sys
print("%.2f" % sum(json.load(open(f))["build_cpu"] for f in glob.glob(sys.argv[1] + "/students/*/row.json")))' "$1"
}

echo "bench_class: $n submissions, $jobs at once, $(nproc) cores"
printf '%-10s %-24s %10s %10s %9s %s\n' labs figure measured "for 200" goal ""
for shape in one all; do
  if [ $shape = one ]; then labs=$one_lab; cpu_goal=1.5; wall_goal=180; else labs=""; cpu_goal=8; wall_goal=900; fi
  class="$work/class-$shape"
  make_class "$class" "$labs"
  args=(--out "$work/out-$shape" --jobs "$jobs")
  [ -n "$labs" ] && args+=(--labs "$labs")
  read -r _ wall cpu peak < <(measure first "$bin/course" grade-class "$class" "${args[@]}")
  build=$(build_cpu "$work/out-$shape")  # before the second run rewrites the rows
  read -r _ again _ _ < <(measure again "$bin/course" grade-class "$class" "${args[@]}")
  read -r _ base_wall base_cpu _ < <(measure base "$bin/course" grade ${labs:+$labs} \
    --out "$work/base-$shape" --jobs 1)
  python3 - "$shape" "$n" "$wall" "$cpu" "$peak" "$again" "$build" "$base_cpu" "$cpu_goal" "$wall_goal" <<'PY'
import sys
shape, n, wall, cpu, peak, again, build, base, cpu_goal, wall_goal = sys.argv[1:]
n = int(n); wall, cpu, again, build, base = map(float, (wall, cpu, again, build, base))
per = cpu / n
scale = 200 / n
name = "one lab" if shape == "one" else "all labs"
def row(figure, value, at200, goal, ok):
    print("%-10s %-24s %10s %10s %9s %s" % (name, figure, value, at200, goal, ("ok" if ok else "OVER") if goal else ""))
row("CPU per submission", "%.2f s" % per, "", "<= %s s" % cpu_goal, per <= float(cpu_goal))
row("  build", "%.2f s" % (build / n), "", "", True)
row("  grading", "%.2f s" % ((cpu - build) / n), "", "", True)
row("class wall time", "%.0f s" % wall, "%.0f s" % (wall * scale), "<= %s s" % wall_goal, wall * scale <= float(wall_goal))
row("submissions per minute", "%.1f" % (n / wall * 60), "", "", True)
row("second run (unchanged)", "%.2f s" % again, "%.2f s" % (again * scale), "<= 5 s", again * scale <= 5)
row("peak memory", "%s MB" % peak, "", "", True)
row("/ course grade (solution)", "%.2f" % (per / base if base else 0), "", "", True)
PY
done
