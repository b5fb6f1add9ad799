// The labs of one grading shared between --jobs workers
// (grading/commands/lab_shares.hpp): the costliest first, each to the least
// loaded worker, so that no worker draws the two slowest labs while another
// idles; labs built by hand, no child runs.
#include "grading/commands/lab_shares.hpp"
#include "tests/support/test_support.hpp"

using grading::Check;
using grading::CheckKind;
using grading::LabData;

namespace {

// A lab of `frames` checkpoints with an image check each, and one checkpoint
// with a unit check of `cases` random cases.
LabData lab(int frames, int cases = 0) {
    LabData l;
    for (int i = 0; i < frames; ++i) l.checks.push_back({Check{}});
    if (cases > 0) {
        Check unit;
        unit.kind = CheckKind::Unit;
        grading::UnitCheck u;
        u.random = cases;
        unit.spec = u;
        l.checks.push_back({unit});
    }
    return l;
}

}  // namespace

TEST_CASE("grading_cost: a frame per checkpoint that renders, 200 unit cases a frame") {
    CHECK(grading::grading_cost(lab(3)) == doctest::Approx(3.0));
    CHECK(grading::grading_cost(lab(2, 1000)) == doctest::Approx(7.0));
    CHECK(grading::grading_cost(lab(0, 200)) == doctest::Approx(1.0));
}

TEST_CASE("shares: the costliest first, each to the least loaded worker") {
    // Costs 10, 1, 1, 8 and 9: every second lab in turn would give one worker
    // 10 + 1 + 9 = 20 and the other 9; longest first gives 10 + 1 + 1 = 12
    // against 8 + 9 = 17.
    const std::vector<LabData> labs = {lab(10), lab(1), lab(1), lab(8), lab(4, 1000)};
    const std::vector<size_t> all = {0, 1, 2, 3, 4};
    const std::vector<std::vector<size_t>> two = grading::shares(labs, all, 2);
    REQUIRE(two.size() == 2);
    CHECK(two[0] == std::vector<size_t>{0, 1, 2});
    CHECK(two[1] == std::vector<size_t>{3, 4});
    // One worker takes every lab, in order; the same labs, the same shares.
    CHECK(grading::shares(labs, all, 1) == std::vector<std::vector<size_t>>{all});
    CHECK(grading::shares(labs, all, 2) == two);
    // Positions in `which`, not lab indices.
    const std::vector<std::vector<size_t>> some = grading::shares(labs, {3, 0}, 2);
    CHECK(some == std::vector<std::vector<size_t>>{{1}, {0}});
}
