// A `lab` older than a file it is built from (grading/commands/lab_sources.hpp): the list
// CMake writes beside the build's `lab`, course's comparison of the times, and `course grade`,
// `course bless` and `course warm-cache` refusing such a `lab` before any child runs.
#include <chrono>
#include <fstream>
#include <set>

#include "grading/commands/lab_sources.hpp"
#include "tests/grading/grade_support.hpp"

using namespace grade_test;

namespace {

using Clock = fs::file_time_type::clock;

// A tree with one lab file, and a `lab` beside its list naming that file:
// a script that runs the build's own `lab`, so that it grades for real.
// `cd` runs a command away from the tree, where course names paths in full.
struct Built {
    fs::path dir, source, lab, file;
    std::string cd;

    explicit Built(const std::string& name) : dir(fw::test::out_dir() + "/" + name) {
        fs::remove_all(dir);
        fs::create_directories(dir / "elsewhere");
        cd = "cd " + fw::shell_quote((dir / "elsewhere").string()) + " &&";
        source = dir / "tree";
        file = source / "labs/00_pipeline/pipeline.cpp";
        lab = dir / "build/bin/lab";
        fw::test::write_text(file.string(), "// a lab file\n");
        fw::test::write_text(lab.string(),
                             "#!/bin/sh\nexec " + fw::test::bin_dir() + "/lab \"$@\"\n");
        fs::permissions(lab, fs::perms::owner_all);
        write_list({"labs/00_pipeline/pipeline.cpp"});
    }

    void write_list(const std::vector<std::string>& files, const std::string& extra = "") const {
        std::string text = "# written by the test\nsource " + source.string() + "\nbuild " +
                           (dir / "build").string() + "\n" + extra;
        for (const std::string& f : files) text += "file " + f + "\n";
        fw::test::write_text(lab.string() + ".sources", text);
    }

    // The file `seconds` after the executable (before it when negative).
    void file_after_lab(int seconds) const {
        const auto now = Clock::now();
        fs::last_write_time(lab, now - std::chrono::hours(1));
        fs::last_write_time(file, now - std::chrono::hours(1) + std::chrono::seconds(seconds));
    }
};

}  // namespace

TEST_CASE("lab_sources: the files newer than lab, or gone, and nothing without a list") {
    const Built b("lab_sources");
    b.file_after_lab(-10);
    grading::LabSources s = grading::lab_sources(b.lab.string());
    CHECK(s.manifest == b.lab.string() + ".sources");
    CHECK(s.source == b.source.string());
    CHECK(s.build == (b.dir / "build").string());
    CHECK(s.newer.empty());

    b.file_after_lab(10);
    s = grading::lab_sources(b.lab.string());
    REQUIRE(s.newer.size() == 1);
    CHECK(s.newer[0] == b.file.string());  // in full: the test does not run at the tree's top

    b.file_after_lab(-10);
    b.write_list({"labs/00_pipeline/pipeline.cpp", "labs/00_pipeline/removed.cpp"});
    s = grading::lab_sources(b.lab.string());
    REQUIRE(s.newer.size() == 1);
    const std::string gone = " (gone)";
    REQUIRE(s.newer[0].size() > gone.size());
    CHECK(s.newer[0].substr(s.newer[0].size() - gone.size()) == gone);
    CHECK(s.newer[0].substr(0, s.newer[0].size() - gone.size()) ==
          (b.source / "labs/00_pipeline/removed.cpp").string());

    b.write_list({}, "files labs/00_pipeline/pipeline.cpp\n");
    fw::test::check_mentions(
        fw::test::thrown([&] { grading::lab_sources(b.lab.string()); }),
        {b.lab.string() + ".sources:4", "files labs/00_pipeline/pipeline.cpp", "build again"});

    fs::remove(b.lab.string() + ".sources");
    s = grading::lab_sources(b.lab.string());
    CHECK(s.manifest.empty());
    CHECK(s.newer.empty());
    CHECK_NOTHROW(grading::require_lab_up_to_date(b.lab.string(), true, {"pipeline"}));
}

TEST_CASE("course grade, bless and warm-cache refuse a lab older than a file it is built from") {
    const Built b("lab_sources_course");
    const std::string tree = make_tree((b.dir / "data").string(), false);
    const std::string env = b.cd + " LAB_ROOT=" + tree;
    const std::string out = (b.dir / "report").string();
    b.file_after_lab(10);

    Graded g = grade(env, "pipeline --lab " + b.lab.string(), out);
    CHECK(g.exit_code == 2);
    fw::test::check_mentions(g.output,
                             {"older than a file it is built from", b.file.string(),
                              "cmake --build " + (b.dir / "build").string() + " --target lab",
                              b.lab.string() + ".sources"});
    CHECK_MESSAGE(!fs::exists(out + "/results.json"), "a report was written:\n" << g.output);

    const fs::path reference = fs::path(tree) / "labs/00_pipeline/reference";
    const fs::path png = *fs::directory_iterator(reference);
    const auto written = fs::last_write_time(png);
    fw::test::CommandResult r =
        fw::test::run_command(env + " " + course() + " bless pipeline --lab " + b.lab.string());
    CHECK(r.exit_code == 2);
    fw::test::check_mentions(r.output, {b.file.string(), "--target lab"});
    CHECK(fs::last_write_time(png) == written);

    const std::string cache = (b.dir / "cache").string();
    r = fw::test::run_command(env + " " + course() + " warm-cache " + cache + " pipeline --lab " +
                              b.lab.string());
    CHECK(r.exit_code == 2);
    fw::test::check_mentions(r.output, {b.file.string(), "--target lab"});
    CHECK(!fs::exists(cache));

    // Built again: the executable is the newer.
    b.file_after_lab(-10);
    g = grade(env, "pipeline --lab " + b.lab.string(), out);
    CHECK(g.exit_code == 0);
    CHECK(g.results.is_object());
}

TEST_CASE("the refusal names scripts/grade.sh for the tree's build/, relative at the tree's top") {
    const Built b("lab_sources_script");
    // The lab's tree is its own build's source: build/ beside scripts/grade.sh.
    const fs::path source = b.dir;
    fw::test::write_text((source / "scripts/grade.sh").string(), "#!/bin/sh\n");
    fw::test::write_text((source / "labs/00_pipeline/pipeline.cpp").string(), "// a lab file\n");
    fw::test::write_text(b.lab.string() + ".sources", "source " + source.string() + "\nbuild " +
                                                          (source / "build").string() +
                                                          "\nfile labs/00_pipeline/pipeline.cpp\n");
    fs::last_write_time(b.lab, Clock::now() - std::chrono::hours(1));
    const auto refusal = [&](bool grading) {
        return fw::test::thrown([&] {
            grading::require_lab_up_to_date(b.lab.string(), grading, {"pipeline", "transforms"});
        });
    };
    const fs::path was = fs::current_path();
    // Elsewhere (ctest runs a self-check in the build folder): every path in full.
    fs::current_path(b.dir / "elsewhere");
    fw::test::check_mentions(refusal(true),
                             {"'" + b.lab.string() + "' is older than a file it is built from, " +
                                  (source / "labs/00_pipeline/pipeline.cpp").string() + ":",
                              (source / "scripts/grade.sh").string() +
                                  " pipeline transforms (builds, then grades) or cmake --build " +
                                  (source / "build").string() + " --target lab"});
    // At the tree's top, where a student types the commands: relative.
    fs::current_path(source);
    fw::test::check_mentions(refusal(true),
                             {"'build/bin/lab' is older than a file it is built from, "
                              "labs/00_pipeline/pipeline.cpp:",
                              "scripts/grade.sh pipeline transforms (builds, then grades) or "
                              "cmake --build build --target lab (build/bin/lab.sources lists"});
    // bless and warm-cache grade nothing: the build alone.
    CHECK(refusal(false).find("grade.sh") == std::string::npos);
    fs::current_path(was);
}

// The build's own list: every file of `lab`'s C++ and the headers it includes
// (shared.glsl among them), no shader read at run time, nothing of course's.
TEST_CASE("the build's lab.sources lists what lab is compiled from, and lab is not older") {
    const std::string lab = fw::test::bin_dir() + "/lab";
    const grading::LabSources s = grading::lab_sources(lab);
    REQUIRE_MESSAGE(!s.manifest.empty(), "no " << lab << ".sources: cmake/lab_sources.cmake");
    CHECK(fs::equivalent(s.source, fw::test::source_dir()));
    CHECK_MESSAGE(s.newer.empty(), "the suite's lab is older than " << fw::join(s.newer, ", "));
    std::set<std::string> files;
    std::ifstream in(s.manifest);
    for (std::string line; std::getline(in, line);)
        if (line.rfind("file ", 0) == 0) files.insert(line.substr(5));
    for (const char* f : {"labs/00_pipeline/pipeline.cpp", "labs/00_pipeline/pipeline.hpp",
                          "labs/07_framebuffer_ops/fragment_state.cpp",
                          "shaders/00_pipeline/shared.glsl", "framework/runner/lab_main.cpp",
                          "framework/gl/shader.hpp", "framework/serve/page/index.html"})
        CHECK_MESSAGE(files.count(f), std::string(f) << " is not listed");
    for (const std::string& f : files) {
        CAPTURE(f);
        CHECK(fs::is_regular_file(fs::path(s.source) / f));
        CHECK(f.find("grading/") == std::string::npos);
        CHECK(f.find("tests/") == std::string::npos);
        const std::string ext = fs::path(f).extension().string();
        for (const char* shader : {".vert", ".frag", ".geom", ".tesc", ".tese", ".comp"})
            CHECK(ext != shader);
    }
}
