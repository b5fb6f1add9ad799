// `buffer` checks (docs/contract.md, Checks): the buffers file the child
// writes and course reads back as hostile input, the check's fields
// validated before any child runs, the verdict's words (counts, the first
// differing element, NaN, a known mistake), and every report carrying them.
// The reference is registered here for a lab folder of the test's own
// ("90_buffers"): particles falling from rest in closed form.
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "framework/error.hpp"
#include "framework/lab_buffers.hpp"
#include "grading/judge/cases.hpp"
#include "grading/judge/checks.hpp"
#include "grading/judge/judge_buffer.hpp"
#include "grading/report/prairielearn_results.hpp"
#include "grading/report/reports.hpp"
#include "grading/units/buffer_reference.hpp"
#include "tests/grading/judge_support.hpp"
#include "tests/support/test_support.hpp"

namespace {

using nlohmann::json;

// Particle i starts at (0.1 i, 1.2, 0) and falls for steps * 0.1 s.
grading::BufferExpectation fall(const json& params, double g) {
    const int steps = params.at("steps").get<int>(), count = params.at("count").get<int>();
    if (count < 0 || count > 100000) throw fw::Error("count must be 0 to 100000");
    const double t = steps * 0.1;
    grading::BufferExpectation e{3, {}};
    for (int i = 0; i < count; ++i)
        for (double v : {0.1 * i, 1.2 - 0.5 * g * t * t, 0.0}) e.values.push_back(float(v));
    return e;
}
grading::BufferExpectation ref_fall(const json& params) { return fall(params, 9.8); }
grading::BufferExpectation ref_fall_twice(const json& params) { return fall(params, 19.6); }

const bool registered =
    grading::register_buffer_reference(
        "90_buffers", {"", "fall", &ref_fall, "particle", "is at", {"steps", "count"}}) &&
    grading::register_buffer_mistake(
        "90_buffers", {"", "fall", "gravity-twice", "gravity applied twice", &ref_fall_twice});

const json kParams = {{"steps", 1}, {"count", 4}};

// The message parse_checks throws for `lab`.
std::string parse_error_of(grading::LabData& lab) {
    try {
        grading::parse_checks(lab);
    } catch (const fw::UsageError& e) {
        return e.what();
    }
    return "(no error)";
}

// A lab of one checkpoint with `check` (and the params given), its checks parsed.
grading::LabData lab_with(const json& check, const json& params = kParams) {
    REQUIRE(registered);
    return judge_test::lab_of("buffers", "90_buffers",
                              {judge_test::checkpoint("falling", json::array({check}), params)});
}

const json kCheck = {
    {"kind", "buffer"}, {"buffer", "particles"}, {"reference", "fall"}, {"points", 2}};

// The message parse_checks throws for `check`.
std::string parse_error(const json& check, const json& params = kParams) {
    try {
        lab_with(check, params);
    } catch (const fw::UsageError& e) {
        return e.what();
    }
    return "(no error)";
}

fw::LabBuffer particles(const json& params, double g = 9.8) {
    const grading::BufferExpectation e = fall(params, g);
    return {"particles", e.components, e.values};
}

// The check of lab_with(kCheck) judged against `buffers`.
grading::CheckResult judged(const std::vector<fw::LabBuffer>& buffers) {
    const grading::LabData lab = lab_with(kCheck);
    grading::CheckResult r;
    r.max_score = 2;
    grading::judge_buffer(lab.checks[0][0].as<grading::BufferCheck>(), &buffers, "", r);
    return r;
}

bool has(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

// A child's outputs of `files`, and read_buffers' verdict on them.
struct Outputs : judge_test::Outputs {
    using judge_test::Outputs::Outputs;
    // read_buffers' verdict: "" when read, else why.
    std::string why() const {
        std::vector<fw::LabBuffer> buffers;
        std::string why;
        return grading::read_buffers(*outputs, "falling", buffers, why) ? "" : why;
    }
};

}  // namespace

TEST_CASE("the buffers file: every float back exactly, NaN and infinity as names") {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    const std::vector<fw::LabBuffer> written = {
        {"particles", 3, {0.1f, 1.0f / 3, -0.0f, 1e-38f, 3.4e38f, 7.0f}},
        {"speeds", 1, {nan, inf, -inf}}};
    const std::string text = fw::buffers_json(written);
    INFO(text);
    CHECK(has(text, "\"components\": 3"));
    CHECK(has(text, "[0.1,0.33333334,"));
    CHECK(has(text, "[\"NaN\",\"Infinity\",\"-Infinity\"]"));
    const std::vector<fw::LabBuffer> read = fw::parse_buffers(text, "f.buffers.json");
    REQUIRE(read.size() == 2);
    CHECK(read[0].name == "particles");
    CHECK(read[0].components == 3);
    CHECK(read[0].values == written[0].values);
    CHECK(std::isnan(read[1].values[0]));
    CHECK(read[1].values[1] == inf);
    CHECK(read[1].values[2] == -inf);
    // What a lab's buffers() returns is checked where it is made.
    CHECK_THROWS_WITH_AS(fw::check_lab_buffers({{"a", 0, {}}}, "particles"),
                         doctest::Contains("LabBuffer 'a': components is 0"), fw::Error);
    CHECK_THROWS_WITH_AS(fw::check_lab_buffers({{"a", 1, {}}, {"a", 2, {}}}, "particles"),
                         doctest::Contains("'a' is returned twice"), fw::Error);
    CHECK_THROWS_WITH_AS(fw::check_lab_buffers({{"", 1, {}}}, "particles"),
                         doctest::Contains("has no name"), fw::Error);
}

TEST_CASE("a buffers file from the child is hostile: each malformation fails, named") {
    CHECK(Outputs(Outputs::Files{{"falling.buffers.json", fw::buffers_json({particles(kParams)})}})
              .why() == "");
    const std::vector<std::pair<std::string, std::string>> bad = {
        {"{\"particles\": {\"components\": 3, \"values\": [0.1, 0.2", "is not valid JSON"},
        {"[1, 2, 3]", "must be a JSON object of buffers by name"},
        {"{\"particles\": [1, 2]}", "buffer 'particles' must be an object"},
        {"{\"particles\": {\"components\": \"3\", \"values\": []}}",
         "\"components\" must be an integer from 1 to 64, got \"3\""},
        {"{\"particles\": {\"components\": 0, \"values\": []}}", "must be an integer from 1 to 64"},
        {"{\"particles\": {\"components\": 1e9, \"values\": []}}",
         "must be an integer from 1 to 64"},
        {"{\"particles\": {\"values\": []}}", "and is missing"},
        {"{\"particles\": {\"components\": 1, \"values\": {\"a\": 1}}}",
         "\"values\" must be an array"},
        {"{\"particles\": {\"components\": 1, \"values\": [1, {\"x\": 2}]}}",
         "\"values\"[1] is {\"x\":2}, not a number"},
        {"{\"particles\": {\"components\": 1, \"values\": [1, \"nan\"]}}",
         "\"values\"[1] is \"nan\", not a number"},
        {"{\"particles\": {\"components\": 1, \"values\": [], \"extra\": 1}}",
         "unknown field 'extra'"},
        {"{\"\": {\"components\": 1, \"values\": []}}", "a buffer has an empty name"},
    };
    for (const auto& [text, why] : bad) {
        CAPTURE(text);
        const std::string seen = Outputs(Outputs::Files{{"falling.buffers.json", text}}).why();
        CHECK_MESSAGE(has(seen, "no buffers: falling.buffers.json"), seen);
        CHECK_MESSAGE(has(seen, why), seen);
    }
    // Past the limit: refused unread, however well formed.
    std::string huge = "{\"particles\": {\"components\": 1, \"values\": [0";
    while (huge.size() <= grading::kBuffersFileLimit) huge += ",0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0";
    huge += "]}}";
    CHECK(has(Outputs(Outputs::Files{{"falling.buffers.json", huge}}).why(), "output too large"));
    CHECK(has(Outputs(Outputs::Files{}).why(),
              "exited normally without writing falling.buffers.json"));
    CHECK(has(
        Outputs(Outputs::Files{{"falling.error.txt", "buffers(): GL_INVALID_OPERATION\n"}}).why(),
        "could not produce falling.buffers.json: buffers(): GL_INVALID_OPERATION"));
}

TEST_CASE("a buffer check's fields are validated when the file is read, each named") {
    const grading::LabData lab = lab_with(kCheck);
    const auto& c = lab.checks[0][0].as<grading::BufferCheck>();
    CHECK(lab.checks[0][0].kind == grading::CheckKind::Buffer);
    CHECK(c.buffer == "particles");
    CHECK(c.tolerance == grading::kBufferTolerance);
    CHECK(c.expected.components == 3);
    CHECK(c.expected.values.size() == 12);
    REQUIRE(c.mistakes.size() == 1);
    CHECK(c.mistakes[0].id == "gravity-twice");
    json tolerant = kCheck;
    tolerant["tolerance"] = 0.01;
    tolerant["size"] = {64, 64};
    CHECK(lab_with(tolerant).checks[0][0].as<grading::BufferCheck>().tolerance == 0.01);

    const std::string where =
        "labs/90_buffers/checkpoints.json: checkpoint 'falling', check 1 "
        "(buffer): ";
    const auto without = [](const char* field) {
        json check = kCheck;
        check.erase(field);
        return check;
    };
    const auto with = [](const char* field, const json& value) {
        json check = kCheck;
        check[field] = value;
        return check;
    };
    CHECK(parse_error(without("buffer")) == where +
                                                "\"buffer\" must be a name, e.g. "
                                                "\"particles\" (a fw::LabBuffer the lab's "
                                                "buffers() returns)");
    CHECK(has(parse_error(with("buffer", 3)), where + "\"buffer\" must be a name"));
    CHECK(has(parse_error(without("reference")), where + "\"reference\" must be a name"));
    CHECK(has(parse_error(with("reference", "rise")),
              where + "\"reference\" course has no buffer reference 'rise' for lab 'buffers'; it "
                      "has: fall"));
    CHECK(has(parse_error(with("tolerance", -1)), where + "\"tolerance\" must be a number in [0"));
    CHECK(has(parse_error(with("tolerance", "0.1")), where + "\"tolerance\" must be a number"));
    CHECK(has(parse_error(with("stat", "x")),
              where + "\"stat\" is not a field of a buffer check; its fields are: kind, points, "
                      "size, buffer, reference, tolerance"));
    CHECK(has(parse_error(without("points")), where + "\"points\" is missing"));
    CHECK(has(parse_error(kCheck, {{"count", 4}}),
              where + "\"reference\" 'fall' computes its values from the params steps, count as "
                      "the checkpoint writes them, but its \"params\" lack steps"));
    CHECK(has(parse_error(kCheck, {{"steps", 1}, {"count", -1}}),
              where + "\"reference\" cannot be computed: reference 'fall' fails on the "
                      "checkpoint's params {\"count\":-1,\"steps\":1}: count must be 0 to 100000"));
    CHECK(has(parse_error(kCheck, {{"steps", "one"}, {"count", 4}}),
              where + "\"reference\" cannot be computed"));
    CHECK(has(parse_error({{"kind", "buffers"}, {"points", 1}}),
              "it must be one of image, probe, stat, unit, forbidden, buffer"));
}

TEST_CASE("a buffer check asks the child for the checkpoint's buffers, and only then") {
    const grading::LabData lab = lab_with(kCheck);
    const grading::LabPlan plan = grading::plan_lab(lab, 1, grading::PlanFor::Grading);
    REQUIRE(plan.job["renders"].size() == 1);
    CHECK(plan.job["renders"][0]["buffers"] == true);
    CHECK(plan.job["renders"][0]["depth"] == false);
    const grading::LabData probe =
        lab_with({{"kind", "probe"}, {"at", {1, 1}}, {"color", {0, 0, 0}}, {"points", 1}});
    CHECK(grading::plan_lab(probe, 1, grading::PlanFor::Grading).job["renders"][0]["buffers"] ==
          false);
    // Blessing renders only the checkpoints of image checks.
    CHECK(grading::plan_lab(lab, 1, grading::PlanFor::Blessing).job["renders"].empty());
}

TEST_CASE("a buffer check passes within the tolerance and says what differs where") {
    grading::CheckResult pass = judged({particles(kParams)});
    CHECK(pass.passed);
    CHECK(pass.score == 2);
    CHECK(pass.title == "buffer particles");
    CHECK(pass.output ==
          "Expected: buffer 'particles' holds 4 particles of 3 floats, each float within 0.0001 "
          "of course's reference 'fall'\nObserved: all 4 particles within 0.0001");

    fw::LabBuffer off = particles(kParams);
    off.values[3 * 2 + 1] += 0.5f;  // particle 2's y
    off.values[3 * 3 + 0] += 1e-3f;
    const grading::CheckResult wrong = judged({off});
    CHECK_FALSE(wrong.passed);
    CHECK(wrong.score == 0);
    CHECK(has(wrong.output,
              "\nObserved: particle 2 is at (0.2, 1.651, 0) but should be at (0.2, "
              "1.151, 0); 2 of 4 particles differ"));
    CHECK(wrong.diagnosis.empty());

    const grading::CheckResult twice = judged({particles(kParams, 19.6)});
    CHECK(has(twice.output,
              "Observed: particle 0 is at (0, 1.102, 0) but should be at (0, 1.151, "
              "0); 4 of 4 particles differ: gravity applied twice?"));
    CHECK(twice.diagnosis == "Likely mistake (gravity-twice): gravity applied twice.");
    CHECK(has(twice.output, "\nLikely mistake (gravity-twice): gravity applied twice."));

    fw::LabBuffer nan = particles(kParams);
    nan.values[4] = std::numeric_limits<float>::quiet_NaN();
    const grading::CheckResult not_finite = judged({nan});
    CHECK(has(not_finite.output,
              "particle 1 is at (0.1, NaN, 0) but should be at (0.1, 1.151, "
              "0); 1 of 4 particles differs"));
    CHECK(not_finite.diagnosis == "Your shaders wrote NaN: a division by a zero length?");
}

TEST_CASE("a buffer of another size, layout or name fails, saying what it holds") {
    fw::LabBuffer short_one = particles(kParams);
    short_one.values.resize(11);
    CHECK(has(judged({short_one}).output,
              "Observed: the buffer 'particles' holds 11 floats, 3 vec3 and 2 left over, but "
              "should hold 4 particles of 3 floats"));
    fw::LabBuffer vec4 = {"particles", 4, std::vector<float>(16, 0.0f)};
    CHECK(has(judged({vec4}).output,
              "holds 16 floats, 4 vec4, but should hold 4 particles of 3 floats"));
    fw::LabBuffer scalars = {"particles", 1, std::vector<float>(12, 0.0f)};
    CHECK(has(judged({scalars}).output, "holds 12 floats, but should hold 4 particles"));
    CHECK(has(judged({{"velocities", 3, {}}}).output,
              "Observed: the lab wrote no buffer 'particles' (it wrote 'velocities')"));
    CHECK(has(judged({}).output, "the lab wrote no buffer 'particles' (it wrote none)"));
    grading::CheckResult unread;
    grading::judge_buffer(lab_with(kCheck).checks[0][0].as<grading::BufferCheck>(), nullptr,
                          "no buffers: falling.buffers.json is not valid JSON", unread);
    CHECK_FALSE(unread.passed);
    CHECK(has(unread.output, "Observed: no buffers: falling.buffers.json is not valid JSON"));
}

TEST_CASE("judge_lab reads the buffers file and every report carries the verdict") {
    const grading::LabData lab = lab_with(kCheck);
    const grading::LabPlan plan = grading::plan_lab(lab, 1, grading::PlanFor::Grading);
    const Outputs child(
        Outputs::Files{{"falling.buffers.json", fw::buffers_json({particles(kParams, 19.6)})}});
    const std::string out = fw::test::out_dir() + "/report";
    std::filesystem::remove_all(out);
    std::filesystem::create_directories(out + "/buffers");
    grading::GradeRun run;
    grading::LabResult result;
    result.lab = lab.id;
    result.checks = grading::judge_lab(lab, plan, *child.outputs, out);
    REQUIRE(result.checks.size() == 1);
    CHECK(result.checks[0].kind == grading::CheckKind::Buffer);
    CHECK(std::string(grading::name_of(result.checks[0].kind)) == "buffer");
    run.labs.push_back(result);
    run.backend = "egl";
    grading::write_reports(run, out);
    const std::string words = "4 of 4 particles differ: gravity applied twice?";
    const std::string summary = fw::test::read_text(out + "/summary.txt");
    CHECK_MESSAGE(has(summary,
                      "buffers/falling: buffer particles (0/2 points) - Observed: particle 0 is at "
                      "(0, 1.102, 0) but should be at (0, 1.151, 0); " +
                          words),
                  summary);
    CHECK_MESSAGE(has(summary, "Likely mistake (gravity-twice)"), summary);
    const json gradescope = json::parse(fw::test::read_text(out + "/results.json"));
    const json& test = gradescope.at("tests").at(0);
    CHECK(test.at("extra_data").at("checks").at(0).at("kind") == "buffer");
    CHECK(has(test.at("output").get<std::string>(), words));
    const std::string junit = fw::test::read_text(out + "/junit.xml");
    CHECK_MESSAGE(has(junit, "type=\"buffer\""), junit);
    CHECK(has(junit, words));
    CHECK(has(fw::test::read_text(out + "/index.html"), words));
    const json prairielearn = json::parse(grading::prairielearn_results_json(run, out));
    const json& pl = prairielearn.at("tests").at(0);
    CHECK(has(pl.at("message").get<std::string>(), words));
    CHECK(has(pl.at("output").get<std::string>(), words));
}

TEST_CASE("a copy without the references judges buffer checks from the values recorded") {
    const grading::LabData lab = lab_with(kCheck);
    const json cases = grading::record_unit_cases(lab, 1, 50);
    REQUIRE(cases.at("checks").size() == 1);
    CHECK(cases["checks"][0].at("buffer").at("mistakes").size() == 1);
    // The same checkpoint in a lab course has no compiled reference for.
    grading::LabData copy = lab;
    copy.id = "copied";
    copy.dir = "92_copied";
    copy.checks.clear();
    json tolerant = kCheck;
    tolerant["tolerance"] = 0.001;  // the check's own, as its file writes it
    copy.file.checkpoints[0].checks = json::array({tolerant});
    std::filesystem::remove_all(copy.root);
    CHECK_THROWS_WITH_AS(grading::parse_checks(copy),
                         doctest::Contains("\"reference\" course has no buffer reference 'fall' "
                                           "for lab 'copied'; it has none for that lab"),
                         fw::UsageError);
    grading::write_unit_cases(grading::unit_cases_path(copy), cases);
    grading::parse_checks(copy);
    const auto& recorded = copy.checks[0][0].as<grading::BufferCheck>();
    const auto& compiled = lab.checks[0][0].as<grading::BufferCheck>();
    CHECK(recorded.expected.values == compiled.expected.values);
    CHECK(recorded.tolerance == 0.001);
    CHECK(recorded.element == "particle");
    const std::vector<fw::LabBuffer> twice = {particles(kParams, 19.6)};
    grading::CheckResult r;
    grading::judge_buffer(recorded, &twice, "", r);
    CHECK(has(r.output, "4 of 4 particles differ: gravity applied twice?"));
    // Another reference's values are not this check's.
    json other = kCheck;
    other["reference"] = "rise";
    copy.file.checkpoints[0].checks = json::array({other});
    const std::string why = parse_error_of(copy);
    CHECK_MESSAGE(
        has(why, "nor does " + grading::unit_cases_path(copy) + " hold its values for this check"),
        why);
}

TEST_CASE("buffer references: their words, and registrations that cannot work") {
    CHECK(grading::plural_noun("particle") == "particles");
    CHECK(grading::plural_noun("vertex") == "vertices");
    CHECK(grading::plural_noun("box") == "boxes");
    CHECK(grading::plural_noun("body") == "bodies");
    CHECK(grading::expected_verb("is at") == "should be at");
    CHECK(grading::expected_verb("has velocity") == "should have velocity");
    CHECK_THROWS_WITH_AS(grading::register_buffer_reference(
                             "90_buffers", {"", "up", &ref_fall, "particle", "moves to", {}}),
                         doctest::Contains("must start with \"is\" or \"has\""), fw::Error);
    CHECK_THROWS_WITH_AS(grading::register_buffer_reference(
                             "90_buffers", {"", "fall", &ref_fall, "particle", "is at", {}}),
                         doctest::Contains("'buffers.fall' is registered twice"), fw::Error);
    CHECK_THROWS_WITH_AS(grading::register_buffer_mistake(
                             "90_buffers", {"", "fall", "Gravity Twice", "x", &ref_fall_twice}),
                         doctest::Contains("lower-case letters, digits and '-'"), fw::Error);
    // A mistake of a reference the lab lacks is named when the lab's checks are read.
    REQUIRE(grading::register_buffer_mistake(
        "91_strays", {"", "rise", "upside-down", "gravity upwards", &ref_fall_twice}));
    CHECK_THROWS_WITH_AS(grading::find_buffer_reference("strays", "rise"),
                         doctest::Contains("buffer mistake 'upside-down' names the reference "
                                           "'rise', which lab 'strays' does not register"),
                         fw::Error);
}
