// `course release --github-classroom` (docs/contract.md): the workflow it
// writes into the student repository, parsed as YAML and checked step by
// step against the labs released; a lab's grading step run as GitHub Actions
// runs it (bash -eo pipefail), with the real course and with stand-ins that
// exit 1 and 2; and actionlint over it where actionlint is on PATH.
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <regex>
#include <string>
#include <vector>

#include "framework/text.hpp"
#include "grading/judge/checks.hpp"
#include "grading/release/release.hpp"
#include "tests/support/browser.hpp"
#include "tests/support/test_support.hpp"

namespace {

namespace fs = std::filesystem;
using fw::shell_quote;

// The student repository with the workflow, released once for every case.
struct Released {
    fs::path dir = fs::path(fw::test::out_dir()) / "released";
    std::vector<grading::LabData> labs;  // what the release holds, in order
    YAML::Node workflow;

    Released() {
        fs::remove_all(dir);
        grading::release_tree(fw::test::source_dir(), dir.string(), {true});
        labs = grading::discover_labs(dir.string());
        workflow = YAML::LoadFile((dir / grading::kGitHubClassroomWorkflow).string());
        fw::test::remove_when_passed(dir.string());
    }
    YAML::Node steps() const { return workflow["jobs"]["autograding"]["steps"]; }
    // The step with this id or `uses` prefix; a failed check when none.
    YAML::Node step(const std::string& key, const std::string& value) const {
        for (const YAML::Node& s : steps())
            if (s[key] && s[key].as<std::string>().rfind(value, 0) == 0) return s;
        FAIL_CHECK("no step whose " << key << " starts with " << value);
        return YAML::Node();
    }
};

const Released& released() {
    static const Released r;
    return r;
}

// `text` without the line breaks and blanks at its end.
std::string chomp(std::string text) {
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.pop_back();
    return text;
}

std::string upper(std::string text) {
    for (char& c : text) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return text;
}

// actionlint on PATH, or $LAB_ACTIONLINT; "" when there is none.
std::string actionlint_path() {
    if (const char* chosen = std::getenv("LAB_ACTIONLINT"); chosen && *chosen) return chosen;
    const fw::test::CommandResult found = fw::test::run_command("command -v actionlint");
    return found.exit_code == 0 ? chomp(found.output) : "";
}

}  // namespace

TEST_CASE("course release --github-classroom: the workflow's job, parsed") {
    const Released& r = released();
    const YAML::Node& w = r.workflow;
    REQUIRE(w.IsMap());
    CHECK(w["on"]["push"]);
    const YAML::Node job = w["jobs"]["autograding"];
    REQUIRE(job.IsMap());
    CHECK(job["runs-on"].as<std::string>() == "ubuntu-latest");
    CHECK(job["container"].as<std::string>() == "debian:bookworm");  // setup.sh's Debian 12
    CHECK(job["defaults"]["run"]["shell"].as<std::string>() == "bash");
    // Every action pinned by its major version.
    const std::regex major(R"([\w.-]+/[\w.-]+@v\d+)");
    for (const YAML::Node& s : r.steps())
        if (s["uses"])
            CHECK_MESSAGE(std::regex_match(s["uses"].as<std::string>(), major),
                          s["uses"].as<std::string>());
    CHECK(r.step("uses", "actions/checkout@")["uses"].as<std::string>() == "actions/checkout@v4");

    // The caches: Debian's packages keyed by setup.sh, ccache's by commit.
    std::vector<std::string> cached;
    for (const YAML::Node& s : r.steps())
        if (s["uses"] && s["uses"].as<std::string>() == "actions/cache@v4") {
            cached.push_back(s["with"]["path"].as<std::string>());
            CHECK(s["with"]["key"]);
            CHECK(s["with"]["restore-keys"]);
        }
    CHECK(cached == std::vector<std::string>{"/var/cache/apt/archives/*.deb", "~/.cache/ccache"});

    // The build: ccache installed before setup.sh builds the student preset.
    std::string build;
    for (const YAML::Node& s : r.steps())
        if (s["run"] && s["run"].as<std::string>().find("setup.sh") != std::string::npos)
            build = s["run"].as<std::string>();
    CHECK(build.find("apt-get install -y -qq --no-install-recommends ccache") <
          build.find("LAB_PRESET=student bash scripts/setup.sh"));
    CHECK(build.find("rm -f /etc/apt/apt.conf.d/docker-clean") != std::string::npos);
}

TEST_CASE("course release --github-classroom: a grading step per lab, all reported") {
    const Released& r = released();
    REQUIRE(r.labs.size() >= 2);
    const YAML::Node reporter = r.step("uses", "classroom-resources/autograding-grading-reporter@");
    REQUIRE(reporter.IsMap());
    CHECK(reporter["uses"].as<std::string>() ==
          "classroom-resources/autograding-grading-reporter@v1");
    std::vector<std::string> ids;
    for (const grading::LabData& lab : r.labs) {
        const std::string id = grading::classroom_runner(lab);
        INFO(lab.dir << " as " << id);
        // The reporter's ids: letters and digits (its own check of `runners`).
        CHECK(std::regex_match(id, std::regex("[a-z0-9]+")));
        const YAML::Node step = r.step("id", id);
        CHECK(step["name"].as<std::string>() == "Grade " + lab.id);
        fw::test::check_mentions(
            step["run"].as<std::string>(),
            {"build/bin/course grade " + shell_quote(lab.id) + " --format github-classroom --out " +
                 shell_quote("build/classroom/" + lab.dir),
             "$GITHUB_OUTPUT", "result=$(base64 -w0 "});
        CHECK(reporter["env"][upper(id) + "_RESULTS"].as<std::string>() ==
              "${{ steps." + id + ".outputs.result }}");
        ids.push_back(id);
    }
    CHECK(std::is_sorted(ids.begin(), ids.end()));
    CHECK(std::adjacent_find(ids.begin(), ids.end()) == ids.end());
    CHECK(reporter["env"].size() == ids.size());
    CHECK(reporter["with"]["runners"].as<std::string>() == fw::join(ids, ","));
    // The reporter comes last, after every lab's step.
    CHECK(r.steps()[r.steps().size() - 1]["uses"].as<std::string>() ==
          reporter["uses"].as<std::string>());

    // The student README says what the workflow does not grade.
    fw::test::check_mentions(fw::test::read_text((r.dir / "README.md").string()),
                             {"## GitHub Classroom", "hidden", "course grade-class"});
}

TEST_CASE("course release --github-classroom: runner ids, and labs that would share one") {
    grading::LabData numbered, named, twin;
    numbered.id = "robot-arm", numbered.dir = "02_robot_arm";
    named.id = "Extra-Lab_2", named.dir = "extra";
    CHECK(grading::classroom_runner(numbered) == "lab02");
    CHECK(grading::classroom_runner(named) == "labextralab2");
    twin.id = "robot-arm-2", twin.dir = "02_robot_arm_2";
    const std::vector<grading::LabData> sharing = {numbered, named, twin};
    fw::test::check_mentions(fw::test::thrown([&] { grading::github_classroom_workflow(sharing); }),
                             {"labs/02_robot_arm and labs/02_robot_arm_2 both report as lab02"});
    fw::test::check_mentions(fw::test::thrown([] { grading::github_classroom_workflow({}); }),
                             {"no labs to grade"});
}

TEST_CASE("course release --github-classroom: a tree that has the workflow already") {
    // The release itself, released again: its workflow would be replaced.
    const Released& r = released();
    const fs::path again = fs::path(fw::test::out_dir()) / "again";
    fs::remove_all(again);
    fw::test::check_mentions(
        fw::test::thrown([&] { grading::release_tree(r.dir.string(), again.string(), {true}); }),
        {grading::kGitHubClassroomWorkflow, "would be replaced", "not written"});
    CHECK((!fs::exists(again) || fs::is_empty(again)));
}

TEST_CASE("course release: without --github-classroom, no workflow") {
    const fs::path dir = fs::path(fw::test::out_dir()) / "plain";
    fs::remove_all(dir);
    grading::release_tree(fw::test::source_dir(), dir.string());
    CHECK(fs::exists(dir / "README.md"));
    CHECK_FALSE(fs::exists(dir / ".github"));
    fw::test::remove_when_passed(dir.string());
}

TEST_CASE("course release --github-classroom: a lab's step outputs its results.json in base64") {
    const Released& r = released();
    const std::string script = r.step("id", "lab00")["run"].as<std::string>();
    const fs::path work = fs::path(fw::test::out_dir()) / "step";
    // As GitHub Actions runs a step of `shell: bash`, in a folder whose
    // build/bin is course's own, or a stand-in exiting with `status`.
    const auto run_step = [&](const std::string& course, int status) {
        fs::remove_all(work);
        fs::create_directories(work / "build/bin");
        if (course.empty()) {
            fs::create_symlink(fs::path(fw::test::bin_dir()) / "course", work / "build/bin/course");
        } else {
            fw::test::write_text((work / "build/bin/course").string(), course);
            fs::permissions(work / "build/bin/course", fs::perms::owner_all);
        }
        fw::test::write_text((work / "step.sh").string(), script);
        fw::test::write_text((work / "output").string(), "");
        const fw::test::CommandResult result = fw::test::run_command(
            "cd " + shell_quote(work.string()) + " && FAKE_STATUS=" + std::to_string(status) +
            " GITHUB_OUTPUT=output bash --noprofile --norc -eo pipefail step.sh");
        INFO(result.output);
        return result.exit_code;
    };
    const std::string out = (work / "build/classroom" / r.labs[0].dir / "results.json").string();
    const auto output_is_results = [&] {
        const std::string output = fw::test::read_text((work / "output").string());
        REQUIRE(output.rfind("result=", 0) == 0);
        CHECK(fw::test::base64_decode(chomp(output.substr(7))) == fw::test::read_text(out));
    };

    // course itself on the solution of lab 0: every check passes (exit 0).
    CHECK(run_step("", 0) == 0);
    fw::test::check_mentions(fw::test::read_text(out), {"\"status\":\"pass\"", "\"version\":1"});
    output_is_results();
    // A check failed (exit 1): its points still go to the reporter.
    const std::string stand_in =
        "#!/bin/bash\nmkdir -p \"$6\"\necho '{\"stand-in\": 1}' > "
        "\"$6/results.json\"\nexit \"$FAKE_STATUS\"\n";
    CHECK(run_step(stand_in, 1) == 0);
    output_is_results();
    // course's own error (exit 2) fails the step, with no output.
    CHECK(run_step(stand_in, 2) == 2);
    CHECK(fw::test::read_text((work / "output").string()).empty());
    fw::test::remove_when_passed(work.string());
}

TEST_CASE("course release --github-classroom: actionlint finds nothing to say") {
    const std::string actionlint = actionlint_path();
    if (actionlint.empty()) {
        MESSAGE(
            "SKIP this case: no actionlint on PATH (nor $LAB_ACTIONLINT); Debian 12 has no "
            "package of it");
        return;
    }
    const Released& r = released();
    const std::string file = (r.dir / grading::kGitHubClassroomWorkflow).string();
    const fw::test::CommandResult lint =
        fw::test::run_command(shell_quote(actionlint) + " " + shell_quote(file));
    INFO(lint.output);
    CHECK(lint.exit_code == 0);
    // And it would say something: the reporter reading a step that is not there.
    std::string broken = fw::test::read_text(file);
    broken.replace(broken.find("steps.lab00."), 12, "steps.lab99.");
    const std::string broken_file = (fs::path(fw::test::out_dir()) / "broken.yml").string();
    fw::test::write_text(broken_file, broken);
    const fw::test::CommandResult caught =
        fw::test::run_command(shell_quote(actionlint) + " " + shell_quote(broken_file));
    INFO(caught.output);
    CHECK(caught.exit_code != 0);
    CHECK(caught.output.find("lab99") != std::string::npos);
}
