// `course grade` against hostile children (docs/contract.md, `course grade`): a crash,
// a hang, a flood of output, an oversized file, a full disk, garbage, links to the
// references, and a child that claims a perfect score. Each fails exactly the
// checks of its own lab with the reason, the reports are complete, and the
// other lab, graded in the same run, keeps full marks.
#include <cstdio>
#include <map>

#include "tests/grading/grade_support.hpp"

using namespace grade_test;

namespace {

struct Misbehaviour {
    std::string mode;
    std::string status;  // in course's output (the lab's status line)
    // Substrings of every hostile check's output, or, keyed by part of the
    // check's name, of that check's.
    std::vector<std::string> every;
    std::vector<std::pair<std::string, std::string>> specific;
};

}  // namespace

TEST_CASE(
    "course grade: a hostile child fails its own lab's checks, with the reason, and nothing else") {
    const std::string tree = make_tree(fw::test::out_dir() + "/tree", /*hostile=*/true);
    const size_t pipeline_checks = lab0_checks().size();
    const std::vector<Misbehaviour> cases = {
        {"segv",
         "crashed (signal 11, SIGSEGV)",
         {"the child crashed (signal 11, SIGSEGV) before writing frame"},
         {}},
        {"hang", "timed out after 2 s", {"the child timed out after 2 s before writing"}, {}},
        {"spew",
         "wrote more than 8 MiB to stdout/stderr",
         {"wrote more than 8 MiB to stdout/stderr"},
         {}},
        {"bigfile", "SIGXFSZ", {"SIGXFSZ", "64 MiB"}, {}},
        {"fill",
         "wrote more than 256 MiB into its work directory",
         {"256 MiB into its work directory"},
         {}},
        {"garbage",
         "ok",
         {},
         {{"frame / image", "frame.pam is 100000x100000, but course asked for 64x64"},
          {"frame2 / image", "frame2.pam is not a PAM file: it starts with \"garbage instead"},
          {"frame2 / probe", "frame2.pam is not a PAM file"},
          {"frame / stat", "frame.stats.json is not a JSON object"}}},
        {"symlink",
         "ok",
         {},
         {{"frame / image", "frame.pam is not a regular file"},
          {"frame2 / probe", "frame2.pam is not a regular file"},
          {"frame / stat", "exited normally without writing frame.stats.json"}}},
        // What it sends on its output descriptor instead of files.
        {"stream_garbage",
         "sent something that is not an output record (a line \"OUTPUT SIZE PATH\") on its "
         "output descriptor",
         {"not an output record"},
         {}},
        {"stream_outside",
         "sent an output outside its work directory ('/etc/planted.txt')",
         {"outside its work directory"},
         {}},
        {"stream_flood",
         "sent more than 256 MiB of outputs on its output descriptor, the limit of its work "
         "directory",
         {"256 MiB of outputs"},
         {}},
        {"stream_cut",
         "ok",
         {},
         {{"frame / image", "exited normally without writing frame.pam"},
          {"frame2 / image", "exited normally without writing frame2.pam"}}},
    };
    for (const Misbehaviour& m : cases) {
        CAPTURE(m.mode);
        const std::string out = fw::test::out_dir() + "/" + m.mode;
        // Short for the hang; long enough elsewhere for the cap to act first
        // on a busy machine.
        const std::string timeout = m.mode == "hang" ? " --timeout 2" : " --timeout 60";
        const std::string env = "LAB_ROOT=" + tree +
                                " FAKE_LAB_TARGET=hostile FAKE_LAB_MODE=" + m.mode +
                                " FAKE_LAB_REFERENCES=" + tree + "/labs/01_hostile/reference";
        Graded g = grade(env, "--lab " + fake_lab() + " --jobs 2" + timeout, out);
        CHECK(g.exit_code == 1);
        CHECK(g.output.find(m.status) != std::string::npos);
        if (m.mode == "spew")
            CHECK_MESSAGE(g.seconds < 15, "killed at the cap, not after a long flood");
        check_reports(out, pipeline_checks + 6);

        const json pipeline = lab_tests(g.results, "pipeline");
        CHECK(pipeline.size() == pipeline_checks);
        for (const json& t : pipeline) {
            CAPTURE(t.dump());
            CHECK(t["status"] == "passed");
        }
        const json hostile = lab_tests(g.results, "hostile");
        CHECK(hostile.size() == 6);
        for (const json& t : hostile) {
            CAPTURE(t.dump());
            CHECK(t["status"] == "failed");
            CHECK(t["score"] == 0);
            const std::string output = t["output"];
            // The lab's status heads each of its checkpoints.
            for (const std::string& s : m.every)
                CHECK(t["checkpoint_output"].get<std::string>().find(s) != std::string::npos);
            for (const auto& [name, s] : m.specific)
                if (t["name"].get<std::string>().find(name) != std::string::npos)
                    CHECK_MESSAGE(output.find(s) != std::string::npos,
                                  "expected the output to mention: " << s);
        }
    }
}

TEST_CASE("course grade: a child's claims count for nothing; only its raw outputs do") {
    // The liar writes black frames, stats saying "passed" with a score of
    // 1000, and units.json claiming every case passed. It earns exactly the
    // points a black frame truly earns: probes that expect black, and image
    // checks whose reference is within the thresholds of black (thin points
    // and lines are), computed here with the framework's comparison.
    std::ifstream in(fw::test::source_dir() + "/labs/00_pipeline/checkpoints.json");
    const json doc = json::parse(in, nullptr, true, /*ignore_comments=*/true);
    const fw::Image blank(512, 512, {0, 0, 0, 255});
    double black = 0.0;
    for (const json& cp : doc["checkpoints"])
        for (const json& c : cp.value("checks", json::array())) {
            if (c["kind"] == "probe" && c.contains("color") && c["color"] == json::array({0, 0, 0}))
                black += c["points"].get<double>();
            fw::CompareOptions options;  // the check's own thresholds, as course reads them
            options.tolerance = c.value("tolerance", options.tolerance);
            options.radius = c.value("radius", options.radius);
            options.max_failed_fraction = c.value("max_fail_fraction", options.max_failed_fraction);
            if (c["kind"] == "image" &&
                fw::compare_images(
                    blank,
                    fw::read_png(fw::test::source_dir() + "/labs/00_pipeline/reference/" +
                                 cp["name"].get<std::string>() + ".png"),
                    options)
                    .passed) {
                MESSAGE("a black frame passes the image check of " << cp["name"]);
                black += c["points"].get<double>();
            }
        }
    REQUIRE(black > 0);
    Graded g = grade("FAKE_LAB_TARGET=pipeline FAKE_LAB_MODE=liar", "pipeline --lab " + fake_lab(),
                     fw::test::out_dir() + "/report");
    CHECK(g.exit_code == 1);
    REQUIRE(g.results.is_object());
    MESSAGE("Expected score " << black << ", observed " << g.results["score"]);
    CHECK(g.results["score"].get<double>() == black);
    check_reports(fw::test::out_dir() + "/report", lab0_checks().size());
    // The report's frames are the black ones it rendered, never a copy of
    // the reference it was compared with.
    int frames = 0;
    for (const json& cp : doc["checkpoints"]) {
        const std::string png =
            fw::test::out_dir() + "/report/pipeline/" + cp["name"].get<std::string>() + ".png";
        if (!std::ifstream(png)) continue;
        ++frames;
        const fw::Image shown = fw::read_png(png);
        CHECK_MESSAGE(shown.pixels == blank.pixels, png << " is not the black frame rendered");
    }
    CHECK(frames > 0);
}

TEST_CASE(
    "course grade --jobs 1: one child grades the labs in turn; a lab that breaks it is "
    "graded again alone, and its neighbour keeps its result") {
    struct Case {
        std::string mode, status;
        std::vector<std::string> runs;  // the fake's FAKE_LAB_MARK lines
    };
    // A crash in robot-arm: pipeline ended before it and is not run again;
    // robot-arm alone crashes again. A crash after both ended: which lab's
    // code broke the child is unknown, so each is graded again alone. A hang
    // is the crash's case, with robot-arm's timeout counted from
    // pipeline's end.
    const Case cases[] = {
        {"segv", "crashed (signal 11, SIGSEGV)", {"ran: pipeline robot-arm", "ran: robot-arm"}},
        {"exit_segv",
         "crashed (signal 11, SIGSEGV)",
         {"ran: pipeline robot-arm", "ran: pipeline", "ran: robot-arm"}},
        {"hang", "timed out after 3 s", {"ran: pipeline robot-arm", "ran: robot-arm"}},
    };
    const size_t pipeline_checks = lab0_checks().size();
    for (const Case& c : cases) {
        CAPTURE(c.mode);
        const std::string out = fw::test::out_dir() + "/one-child-" + c.mode,
                          mark = fw::test::out_dir() + "/one-child-" + c.mode + ".runs";
        fs::remove(mark);
        Graded g =
            grade("FAKE_LAB_TARGET=robot-arm FAKE_LAB_MODE=" + c.mode + " FAKE_LAB_MARK=" + mark,
                  "pipeline robot-arm --jobs 1 --timeout 3 --lab " + fake_lab(), out);
        CHECK(g.exit_code == 1);
        std::ifstream in(mark);
        std::vector<std::string> runs;
        for (std::string line; std::getline(in, line);) runs.push_back(line);
        CHECK(runs == c.runs);
        // Each lab's status in summary.txt: only robot-arm's is not "ok".
        std::ifstream summary(out + "/summary.txt");
        const std::string text((std::istreambuf_iterator<char>(summary)), {});
        std::map<std::string, std::string> status;
        for (const std::vector<std::string>& row : summary_rows(text))
            if (row.size() > 3) status[row[0]] = row[3];
        CHECK(status["pipeline"] == "ok");
        CHECK_MESSAGE(status["robot-arm"] == c.status.substr(0, c.status.find(' ')), text);
        CHECK(g.output.find(c.status) != std::string::npos);
        const json pipeline = lab_tests(g.results, "pipeline");
        CHECK(pipeline.size() == pipeline_checks);
        for (const json& t : pipeline) {
            CAPTURE(t.dump());
            CHECK(t["status"] == "passed");
        }
        CHECK(!lab_tests(g.results, "robot-arm").empty());
    }
}
