// `course release --github-classroom`: the student repository's GitHub
// Actions workflow for GitHub Classroom's autograding (release.hpp).
#include <cctype>
#include <map>
#include <nlohmann/json.hpp>

#include "framework/error.hpp"
#include "framework/text.hpp"
#include "grading/release/release.hpp"

namespace grading {

namespace {

// A YAML scalar in double quotes: a JSON string is one.
std::string yaml_string(const std::string& text) { return nlohmann::json(text).dump(); }

// The job up to the labs' steps. A Debian 12 container, as scripts/setup.sh
// expects and the course's other autograders run, so that Mesa is theirs;
// as root, setup.sh installs without sudo. The Debian packages and ccache's
// files are kept between runs; the image's apt deletes the packages it
// installed unless its docker-clean is removed.
constexpr const char* kJob =
    R"(# GitHub Classroom's autograding, written by `course release --github-classroom`
# (README.md, "GitHub Classroom"): on each push, builds lab and course as
# scripts/setup.sh does, grades each lab's visible checkpoints with
# `course grade --format github-classroom` and reports its points to GitHub
# Classroom. There are no hidden checkpoints here: the course's grade comes
# from its own grading after the deadline.
name: Autograding
on:
  push:
  workflow_dispatch:
permissions:
  actions: read
  contents: read
jobs:
  autograding:
    name: Autograding
    runs-on: ubuntu-latest
    container: debian:bookworm
    timeout-minutes: 60
    env:
      DEBIAN_FRONTEND: noninteractive
      CCACHE_MAXSIZE: 500M
    defaults:
      run:
        shell: bash
    steps:
      - name: Check out the repository
        uses: actions/checkout@v4
      - name: Restore the Debian packages
        uses: actions/cache@v4
        with:
          path: /var/cache/apt/archives/*.deb
          key: apt-bookworm-${{ hashFiles('scripts/setup.sh') }}
          restore-keys: apt-bookworm-
      - name: Restore the compiler cache
        uses: actions/cache@v4
        with:
          path: ~/.cache/ccache
          key: ccache-${{ github.sha }}
          restore-keys: ccache-
      - name: Build lab and course
        run: |
          rm -f /etc/apt/apt.conf.d/docker-clean
          apt-get update -qq
          apt-get install -y -qq --no-install-recommends ccache
          LAB_PRESET=student bash scripts/setup.sh
)";

}  // namespace

std::string classroom_runner(const LabData& lab) {
    std::string digits, letters;
    for (char c : lab.dir) {
        if (!std::isdigit(static_cast<unsigned char>(c))) break;
        digits += c;
    }
    for (char c : lab.id)
        if (std::isalnum(static_cast<unsigned char>(c)))
            letters += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return "lab" + (digits.empty() ? letters : digits);
}

std::string github_classroom_workflow(const std::vector<LabData>& labs) {
    if (labs.empty()) throw fw::Error("no labs to grade: GitHub Classroom's workflow needs one");
    std::string text = kJob, env, runners;
    std::map<std::string, std::string> seen;  // runner id -> lab
    for (const LabData& lab : labs) {
        const std::string id = classroom_runner(lab);
        if (!seen.emplace(id, lab.dir).second)
            throw fw::Error("labs/" + seen[id] + " and labs/" + lab.dir + " both report as " + id +
                            " to GitHub Classroom; number their folders apart");
        const std::string out = fw::shell_quote("build/classroom/" + lab.dir);
        // course grade exits 1 when a check failed (its points still count)
        // and 2 on an error of its own, which fails the workflow.
        text += "      - name: " + yaml_string("Grade " + lab.id) + "\n        id: " + id +
                "\n        run: |\n          status=0\n          build/bin/course grade " +
                fw::shell_quote(lab.id) + " --format github-classroom --out " + out +
                " || status=$?\n          if [ \"$status\" -gt 1 ]; then exit \"$status\"; fi\n"
                "          echo \"result=$(base64 -w0 " +
                out + "/results.json)\" >> \"$GITHUB_OUTPUT\"\n";
        std::string upper = id;
        for (char& c : upper) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
        env += "          " + upper + "_RESULTS: ${{ steps." + id + ".outputs.result }}\n";
        runners += (runners.empty() ? "" : ",") + id;
    }
    return text +
           "      - name: Report to GitHub Classroom\n"
           "        uses: classroom-resources/autograding-grading-reporter@v1\n"
           "        env:\n" +
           env + "        with:\n          runners: " + runners + "\n";
}

}  // namespace grading
