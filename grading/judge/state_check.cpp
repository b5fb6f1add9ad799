// The `state` check (checks.hpp, StateCheck): the render's record of the
// draws against the solution's, by the state diff's sentence
// (grading/diagnosis/state_diff.hpp).
#include <nlohmann/json.hpp>

#include "grading/diagnosis/diagnosis.hpp"
#include "grading/judge/checks.hpp"

namespace grading {

using nlohmann::json;

void judge_state(const LabData& lab, const fw::Checkpoint& cp, const ChildOutputs& outputs,
                 CheckResult& r) {
    r.title = "state of the draws the sheet fixes";
    const std::string rel = reference_record(lab, cp.name);
    const std::string expected =
        "Expected: each draw, dispatch, clear and read-back told the "
        "state the solution's are (" +
        rel + ")\n";
    r.passed = false;
    r.score = 0.0;
    // (A copy with no records at all, a student's, does not judge it:
    // judge_lab leaves it out.)
    if (!has_reference_record(lab, cp.name)) {
        r.output =
            expected + "Observed: no reference record " + rel + "; run course bless " + lab.id;
        return;
    }
    std::string bytes, why;
    if (!outputs.read(cp.name + ".record.json", 16 * kMiB, bytes, why)) {
        r.output = expected + "Observed: no record of the draws: " + why;
        return;
    }
    const json student = json::parse(bytes, nullptr, /*allow_exceptions=*/false);
    const json reference = read_record(lab.root + "/" + rel);
    if (!valid_record(student)) {
        r.output = expected + "Observed: the lab's record of the draws is not one";
        return;
    }
    std::string sentence;
    try {
        sentence = state_difference(student, reference, cp, lab.state_words,
                                    r.visibility == Visibility::Visible);
    } catch (const json::exception& e) {
        r.output = expected + "Observed: the lab's record of the draws cannot be read: " + e.what();
        return;
    }
    r.passed = sentence.empty();
    r.score = r.passed ? r.max_score : 0.0;
    r.output = expected + "Observed: " + (r.passed ? "the same state in every one" : sentence);
    if (!r.passed) r.diagnosis = sentence;
}

bool has_reference_records(const LabData& lab) {
    for (const fw::Checkpoint& cp : lab.file.checkpoints)
        if (has_reference_record(lab, cp.name)) return true;
    return false;
}

StateLeftOut state_checks_left_out(const LabData& lab) {
    StateLeftOut out;
    if (has_reference_records(lab)) return out;
    for (const std::vector<Check>& checks : lab.checks)
        for (const Check& c : checks)
            if (c.kind == CheckKind::State) {
                ++out.checks;
                out.points += c.points;
            }
    return out;
}

}  // namespace grading
