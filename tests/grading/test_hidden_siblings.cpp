// No mistake is seen only by a hidden checkpoint: every hidden checkpoint of
// every lab keeps a visible sibling that a student sees fail before the
// deadline, a visible checkpoint of the same scene that needs the same parts
// and has a check of every kind the hidden one has. (The mistake suite checks
// the same from the other side: each realistic mistake loses points on a
// visible check.)
#include <algorithm>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "grading/judge/checks.hpp"
#include "tests/support/test_support.hpp"

namespace {

std::string scene_of(const fw::Checkpoint& cp) {
    return cp.params.is_object() && cp.params.contains("scene") ? cp.params["scene"].dump() : "";
}

std::set<grading::CheckKind> kinds_of(const std::vector<grading::Check>& checks) {
    std::set<grading::CheckKind> kinds;
    for (const grading::Check& c : checks) kinds.insert(c.kind);
    return kinds;
}

// The first visible checkpoint of `lab` that is a sibling of checkpoint `h`,
// or "" when none is.
std::string visible_sibling(const grading::LabData& lab, size_t h) {
    const fw::Checkpoint& hidden = lab.file.checkpoints[h];
    const std::set<grading::CheckKind> needed = kinds_of(lab.checks[h]);
    const std::set<int> parts(hidden.parts.begin(), hidden.parts.end());
    for (size_t k = 0; k < lab.file.checkpoints.size(); ++k) {
        const fw::Checkpoint& v = lab.file.checkpoints[k];
        if (v.visibility != "visible" || scene_of(v) != scene_of(hidden)) continue;
        const std::set<grading::CheckKind> has = kinds_of(lab.checks[k]);
        const std::set<int> covers(v.parts.begin(), v.parts.end());
        if (std::includes(has.begin(), has.end(), needed.begin(), needed.end()) &&
            std::includes(covers.begin(), covers.end(), parts.begin(), parts.end()))
            return v.name;
    }
    return "";
}

}  // namespace

TEST_CASE("every hidden checkpoint keeps a visible sibling that fails with it") {
    std::vector<grading::LabData> labs = grading::discover_labs(fw::test::source_dir());
    REQUIRE(!labs.empty());
    size_t hidden = 0;
    for (grading::LabData& lab : labs) {
        grading::parse_checks(lab);
        for (size_t h = 0; h < lab.file.checkpoints.size(); ++h) {
            if (lab.file.checkpoints[h].visibility != "hidden") continue;
            ++hidden;
            CHECK_MESSAGE(!visible_sibling(lab, h).empty(),
                          lab.id << "/" << lab.file.checkpoints[h].name
                                 << " is hidden and no visible checkpoint of its scene needs its "
                                    "parts with a check of each of its kinds: a mistake only it "
                                    "catches is seen only after the deadline");
        }
    }
    CHECK(hidden > 0);
}

TEST_CASE("a copy without the solution's records leaves its state checks to the autograder") {
    namespace fs = std::filesystem;
    // Lab 7's data as a student's copy holds it: no reference/*.record.json.
    const fs::path root = fs::path(fw::test::out_dir()) / "no-records";
    const fs::path lab_dir = root / "labs" / "07_framebuffer_ops";
    fs::remove_all(root);
    fs::create_directories(lab_dir / "reference");
    const fs::path source = fs::path(fw::test::source_dir()) / "labs" / "07_framebuffer_ops";
    fs::copy_file(source / "checkpoints.json", lab_dir / "checkpoints.json");
    for (const fs::directory_entry& e : fs::directory_iterator(source / "reference"))
        if (e.path().extension() == ".png")
            fs::copy_file(e.path(), lab_dir / "reference" / e.path().filename());
    auto load = [&] {
        std::vector<grading::LabData> labs = grading::discover_labs(root.string());
        REQUIRE(labs.size() == 1);
        grading::parse_checks(labs[0]);
        return labs[0];
    };
    size_t state_checks = 0;
    double points = 0;
    grading::LabData lab = load();
    for (const std::vector<grading::Check>& checks : lab.checks)
        for (const grading::Check& c : checks)
            if (c.kind == grading::CheckKind::State) ++state_checks, points += c.points;
    REQUIRE(state_checks > 0);
    CHECK_FALSE(grading::has_reference_records(lab));
    const grading::StateLeftOut left = grading::state_checks_left_out(lab);
    CHECK(left.checks == static_cast<int>(state_checks));
    CHECK(left.points == doctest::Approx(points));
    // With one record back, the copy is the course's: nothing is left out.
    fs::copy_file(source / "reference" / "blend_over.record.json",
                  lab_dir / "reference" / "blend_over.record.json");
    lab = load();
    CHECK(grading::has_reference_records(lab));
    CHECK(grading::state_checks_left_out(lab).checks == 0);
}
