// What the report says of a failed checkpoint, by the kind of mistake behind
// it, without a child: a part still at its starting code (the release's
// student version of one block applied to a copy of the student's file)
// is said as such (in a student's own copy, by the release's hashes), and
// no other checkpoint or mistake is named for it; a
// sorting mistake draws no words about mipmaps; a shader mistake no words
// naming a C++ file. Lab 7's and lab 10's real checkpoints and references,
// with frames and unit results written by hand as a child would.
#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "framework/image.hpp"
#include "grading/diagnosis/solution_blocks.hpp"
#include "grading/diagnosis/starting_code.hpp"
#include "grading/judge/checks.hpp"
#include "grading/run/child.hpp"
#include "grading/units/reference.hpp"
#include "tests/support/test_support.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

const std::string kBlending = "labs/07_framebuffer_ops/blending.cpp";
const std::string kPart4 =
    "Part 4 (`back_to_front()` in labs/07_framebuffer_ops/blending.cpp) still has its starting "
    "code; this checkpoint needs it.";

grading::LabData lab_named(const std::string& id) {
    for (grading::LabData& lab : grading::discover_labs(fw::test::source_dir()))
        if (lab.id == id) {
            grading::parse_checks(lab);
            return lab;
        }
    FAIL("no lab " << id);
    return {};
}

// A folder of student files: `file` as `text`.
std::string sources_with(const std::string& name, const std::string& file,
                         const std::string& text) {
    const fs::path dir = fs::path(fw::test::out_dir()) / name;
    fs::remove_all(dir);
    fw::test::write_text((dir / file).string(), text);
    return dir.string();
}

// blending.cpp with only back_to_front()'s block in its student version.
std::string back_to_front_unwritten() {
    const std::string staff = fw::test::read_text(fw::test::source_dir() + "/" + kBlending);
    const std::vector<grading::SolutionBlock> blocks = grading::solution_blocks(staff, kBlending);
    const size_t at = staff.find("std::vector<int> back_to_front(");
    const int line = 1 + static_cast<int>(std::count(staff.begin(), staff.begin() + at, '\n'));
    for (size_t i = 0; i < blocks.size(); ++i)
        if (blocks[i].begin_line > line) return grading::student_text_of_block(staff, kBlending, i);
    FAIL("back_to_front() has no solution block");
    return "";
}

// A child's outputs: files in a work directory, read back as after a normal exit.
struct Outputs {
    grading::ChildRun run;
    std::unique_ptr<grading::ChildOutputs> outputs;
    Outputs(const std::string& name,
            const std::vector<std::pair<std::string, std::string>>& files) {
        const std::string dir = fw::test::out_dir() + "/" + name;
        fs::remove_all(dir);
        fs::create_directories(dir);
        for (const auto& [file, bytes] : files) fw::test::write_text(dir + "/" + file, bytes);
        outputs = std::make_unique<grading::ChildOutputs>(dir, run, grading::ChildLimits{});
    }
};

std::string frame_of(const grading::LabData& lab, const std::string& checkpoint) {
    return fw::encode_pam(fw::read_png(lab.root + "/" + lab.reference(checkpoint)));
}

// Every check of `checkpoint`, judged from `files`.
std::vector<grading::CheckResult> judged(
    const grading::LabData& lab, const std::string& checkpoint,
    const std::vector<std::pair<std::string, std::string>>& files) {
    const grading::LabPlan plan = grading::plan_lab(lab, 7, grading::PlanFor::Grading);
    const Outputs child("outputs-" + checkpoint, files);
    const std::string out = fw::test::out_dir() + "/report-" + checkpoint;
    fs::remove_all(out);
    fs::create_directories(out + "/" + lab.id);
    std::vector<grading::CheckResult> mine;
    for (grading::CheckResult& r : grading::judge_lab(lab, plan, *child.outputs, out))
        if (r.checkpoint == checkpoint) mine.push_back(std::move(r));
    return mine;
}

std::string all_words(const std::vector<grading::CheckResult>& results) {
    std::string text;
    for (const grading::CheckResult& r : results) text += r.output + "\n" + r.diagnosis + "\n";
    return text;
}

bool has(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

// back_to_front()'s results for every unit case of sorting_order, sorting by
// z (the most negative first) instead of by distance from the eye.
size_t checkpoint_index(const grading::LabData& lab, const std::string& name) {
    for (size_t k = 0; k < lab.file.checkpoints.size(); ++k)
        if (lab.file.checkpoints[k].name == name) return k;
    FAIL("no checkpoint " << name);
    return 0;
}

// The units.json of a child whose every unit function is the course's own:
// each case's result from its reference.
std::string solution_units(const grading::LabData& lab) {
    const grading::LabPlan plan = grading::plan_lab(lab, 7, grading::PlanFor::Grading);
    json units = json::object();
    for (const grading::UnitPlan& u : plan.units) {
        const grading::UnitCheck& check =
            lab.checks[checkpoint_index(lab, u.checkpoint)][u.check].as<grading::UnitCheck>();
        const grading::ReferenceUnit& ref = grading::find_reference(lab.id, check.function);
        for (const grading::UnitCase& c : u.cases)
            units[c.id] = {{"result", ref.function.call(c.args)}};
    }
    return units.dump();
}

std::string by_z_units(const grading::LabData& lab) {
    const grading::LabPlan plan = grading::plan_lab(lab, 7, grading::PlanFor::Grading);
    json units = json::object();
    for (const grading::UnitPlan& u : plan.units)
        for (const grading::UnitCase& c : u.cases) {
            std::vector<int> order = {0, 1, 2, 3};
            if (u.checkpoint == "sorting_order")
                std::stable_sort(order.begin(), order.end(), [&](int i, int j) {
                    return c.args[1 + i][2].get<double>() < c.args[1 + j][2].get<double>();
                });
            units[c.id] = {{"result", order}};
        }
    return units.dump();
}

}  // namespace

TEST_CASE(
    "a function still at its starting code is known by its body, whitespace and comments aside") {
    const grading::LabData lab = lab_named("framebuffer-ops");
    const std::string root = lab.root, unwritten = back_to_front_unwritten();
    // The staff tree itself: every part written.
    CHECK(grading::starting_code_sentence(root, root, lab.parts, {4}).empty());
    const std::string sources = sources_with("starting", kBlending, unwritten);
    CHECK(grading::starting_code_sentence(root, sources, lab.parts, {4}) == kPart4);
    CHECK(grading::starting_code_sentence(root, sources, lab.parts, {1, 4}) == kPart4);
    // Parts not listed, or written: nothing.
    CHECK(grading::starting_code_sentence(root, sources, lab.parts, {2}).empty());
    CHECK(grading::starting_code_sentence(root, sources, lab.parts, {}).empty());
    // Formatted otherwise and without its TODO comment: still the starting code.
    std::string reformatted = unwritten;
    const size_t todo = reformatted.find("(void)eye;");
    REQUIRE(todo != std::string::npos);
    reformatted.replace(todo, reformatted.find('\n', todo) - todo, "(void)  eye ;");
    CHECK(grading::starting_code_sentence(root, sources_with("reformatted", kBlending, reformatted),
                                          lab.parts, {4}) == kPart4);
    // One line of the student's own: written.
    std::string begun = unwritten;
    begun.insert(todo, "std::reverse(order.begin(), order.end());\n    ");
    CHECK(grading::starting_code_sentence(root, sources_with("begun", kBlending, begun), lab.parts,
                                          {4})
              .empty());
    // Without markers in the staff tree, an autograder's student_versions/
    // gives the starting code; a student's own copy has neither.
    const std::string student =
        grading::student_text(fw::test::read_text(root + "/" + kBlending), kBlending);
    const std::string folder = sources_with("autograder", "student_versions/" + kBlending, student);
    CHECK(grading::starting_code_sentence(folder, sources, lab.parts, {4}) == kPart4);
    const std::string own = sources_with("own-copy", kBlending, student);
    CHECK(grading::starting_code_sentence(own, own, lab.parts, {4}).empty());
}

TEST_CASE("a student's own copy knows its starting code by the release's hashes") {
    const grading::LabData lab = lab_named("framebuffer-ops");
    const std::string starting = grading::starting_file(lab.dir);
    CHECK(starting == "labs/07_framebuffer_ops/grading/starting.json");
    // The release's tree: the student version of blending.cpp and the starting file.
    const std::string own = sources_with(
        "released", kBlending,
        grading::student_text(fw::test::read_text(lab.root + "/" + kBlending), kBlending));
    const std::string text = grading::starting_file_text(lab.root, lab.parts);
    fw::test::write_text(own + "/" + starting, text);
    const json entries = json::parse(text)["parts"];
    CHECK(entries.size() == lab.parts.size());
    std::vector<grading::PartPlace> places = lab.parts;
    // Without the file, nothing is known.
    CHECK(grading::starting_code_sentence(own, own, places, {4}).empty());
    grading::read_starting_file(own, lab.dir, places);
    for (const grading::PartPlace& p : places) CHECK_MESSAGE(p.start.size() == 16, p.function);
    CHECK(grading::starting_code_sentence(own, own, places, {4}) == kPart4);
    CHECK(has(grading::starting_code_sentence(own, own, places, {2}), "Part 2 (`factor()` in"));
    // Formatted otherwise: still the starting code; begun, or the solution's: written.
    const std::string unwritten = back_to_front_unwritten();
    std::string reformatted = unwritten;
    const size_t todo = reformatted.find("(void)eye;");
    REQUIRE(todo != std::string::npos);
    reformatted.replace(todo, reformatted.find('\n', todo) - todo, "(void)  eye ;");
    CHECK(grading::starting_code_sentence(
              own, sources_with("released-reformatted", kBlending, reformatted), places, {4}) ==
          kPart4);
    std::string begun = unwritten;
    begun.insert(todo, "std::reverse(order.begin(), order.end());\n    ");
    CHECK(grading::starting_code_sentence(own, sources_with("released-begun", kBlending, begun),
                                          places, {4})
              .empty());
    CHECK(grading::starting_code_sentence(own, lab.root, places, {4}).empty());
    // A hash of another body: nothing said.
    for (grading::PartPlace& p : places)
        if (p.function == "back_to_front") p.start = grading::starting_hash("{return{};}");
    CHECK(grading::starting_code_sentence(own, own, places, {4}).empty());
    // A staff tree's solution blocks win over a starting file.
    CHECK(grading::starting_code_sentence(lab.root,
                                          sources_with("starting-staff", kBlending, unwritten),
                                          places, {4}) == kPart4);
    // A file not as the release writes it is an error naming it.
    for (const std::string& bad :
         {std::string("{\"parts\": [{\"part\": 4}]}"), std::string("[]"), std::string("{"),
          std::string("{\"parts\": [{\"part\": 4, \"file\": \"a\", \"function\": \"f\", "
                      "\"fnv1a64\": \"XYZ\"}]}")}) {
        fw::test::write_text(own + "/" + starting, bad);
        CAPTURE(bad);
        fw::test::check_mentions(
            fw::test::thrown([&] { grading::read_starting_file(own, lab.dir, places); }),
            {starting, "fnv1a64", "course release"});
    }
}

TEST_CASE("the parts' places are checked against the staff tree, each error naming the file") {
    const grading::LabData lab = lab_named("framebuffer-ops");
    const std::string where = lab.file.path;
    CHECK_NOTHROW(grading::check_part_places(lab.root, where, lab.parts));
    // What checking part 4 placed in `function` of blending.cpp throws.
    const auto placed = [&](const char* function) {
        const std::vector<grading::PartPlace> places = {{4, kBlending, function, ""}};
        return fw::test::thrown([&] { grading::check_part_places(lab.root, where, places); });
    };
    fw::test::check_mentions(placed("back_to_fronts"),
                             {"checkpoints.json", "part 4", "defines no function back_to_fronts"});
    fw::test::check_mentions(placed("back_to_front4"),
                             {"back_to_front4()", "has no solution block"});
    fw::CheckpointFile file = lab.file;
    file.checkpoints.front().parts = {12};
    fw::test::check_mentions(fw::test::thrown([&] { grading::read_parts(file); }),
                             {"checkpoints.json", "needs part 12"});
    file.parts = json::array({{{"part", 0}, {"file", kBlending}, {"function", "blend"}}});
    fw::test::check_mentions(fw::test::thrown([&] { grading::read_parts(file); }),
                             {"parts[0]", "\"part\": N"});
}

TEST_CASE("a failed checkpoint whose part is starting code says so, and names nothing else") {
    grading::LabData lab = lab_named("framebuffer-ops");
    // back_to_front() unwritten keeps the listed order: sorting_sorted draws
    // sorting_no_depth_write's frame.
    // (Its unit checks pass: a failing one would be the likelier cause.)
    const std::vector<std::pair<std::string, std::string>> files = {
        {"sorting_sorted.pam", frame_of(lab, "sorting_no_depth_write")},
        {"units.json", solution_units(lab)}};
    const std::string staff = all_words(judged(lab, "sorting_sorted", files));
    CHECK_MESSAGE(has(staff, "your code most likely treats sorted true as false"), staff);
    lab.sources = sources_with("starting-judged", kBlending, back_to_front_unwritten());
    const std::vector<grading::CheckResult> results = judged(lab, "sorting_sorted", files);
    REQUIRE(!results.empty());
    const std::string words = all_words(results);
    CHECK_MESSAGE(has(words, kPart4), words);
    CHECK_MESSAGE(!has(words, "treats"), words);
    CHECK_MESSAGE(!has(words, "Your frame is the one"), words);
    // Said once, under the first failed check.
    size_t said = 0;
    for (const grading::CheckResult& r : results) said += has(r.diagnosis, kPart4) ? 1 : 0;
    CHECK(said == 1);
    // A passing checkpoint of the same part says nothing.
    for (const grading::CheckResult& r :
         judged(lab, "sorting_no_depth_write",
                {{"sorting_no_depth_write.pam", frame_of(lab, "sorting_no_depth_write")}}))
        if (r.kind == grading::CheckKind::Image) CHECK(r.diagnosis.empty());
}

TEST_CASE("each kind of mistake draws only its own kind of words") {
    SUBCASE("sorting by z: no words about mipmaps or levels, on any check of lab 7") {
        const grading::LabData lab = lab_named("framebuffer-ops");
        const std::vector<std::pair<std::string, std::string>> files = {
            {"sorting_sorted.pam", frame_of(lab, "sorting_no_depth_write")},
            {"units.json", by_z_units(lab)}};
        for (const std::string checkpoint : {"sorting_sorted", "sorting_order"}) {
            const std::vector<grading::CheckResult> results = judged(lab, checkpoint, files);
            REQUIRE(!results.empty());
            CHECK(std::any_of(results.begin(), results.end(),
                              [](const grading::CheckResult& r) { return !r.passed; }));
            const std::string words = all_words(results);
            CAPTURE(words);
            for (const char* word : {"mipmap", "level", "off-by-one"}) CHECK(!has(words, word));
            // A unit check's sentence only under its own checkpoint.
            if (std::string(checkpoint) == "sorting_sorted") CHECK(!has(words, "Likely mistake"));
        }
    }
    SUBCASE("a silhouette shader's mistake: no sentence names a C++ file") {
        const grading::LabData lab = lab_named("advanced-geometry");
        REQUIRE(lab.mistake_frames.count("silhouette_cube") == 1);
        for (const grading::MistakeFrame& m : lab.mistake_frames.at("silhouette_cube")) {
            CAPTURE(m.image);
            const std::string frame = fw::encode_pam(
                fw::read_png(lab.root + "/labs/" + lab.dir + "/reference/mistakes/" + m.image));
            const std::string words =
                all_words(judged(lab, "silhouette_cube", {{"silhouette_cube.pam", frame}}));
            CAPTURE(words);
            CHECK(!has(words, ".cpp"));
            CHECK(!has(words, "silhouette.geom"));
        }
    }
}
