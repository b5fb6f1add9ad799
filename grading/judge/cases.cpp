// Recorded unit cases (cases.hpp): recording a lab's unit checks into
// cases.json, and loading the file where the references are not compiled.
#include "grading/judge/cases.hpp"

#include <filesystem>
#include <fstream>
#include <memory>
#include <random>

#include "framework/error.hpp"
#include "grading/units/recorded.hpp"

namespace grading {

namespace {

using nlohmann::json;
namespace fs = std::filesystem;

constexpr int kFormat = 1;
constexpr const char* kForStudentCopy = "student copy";
constexpr const char* kForAutograder = "autograder";

// The lab's compiled reference for `function`; recording a recorded one
// would lose the calls it does not hold.
const ReferenceUnit& compiled_reference(const LabData& lab, const std::string& function) {
    const ReferenceUnit& ref = find_reference(lab.id, function);
    if (ref.recorded)
        throw fw::Error("course has no compiled reference for '" + function + "' of lab '" +
                        lab.id + "' (only " + unit_cases_path(lab) +
                        "), so it cannot record its cases");
    return ref;
}

json expectation_json(const BufferExpectation& e) {
    return {{"components", e.components}, {"values", e.values}};
}

BufferExpectation expectation_of(const json& j) {
    return {j.at("components").get<int>(), j.at("values").get<std::vector<float>>()};
}

// A buffer check's expectation and mistakes, as course computed them.
json buffer_json(const BufferCheck& c) {
    json entry = expectation_json(c.expected);
    entry.update({{"reference", c.reference}, {"element", c.element}, {"verb", c.verb}});
    entry["mistakes"] = json::array();
    for (const KnownBufferMistake& m : c.mistakes) {
        json mistake = expectation_json(m.values);
        mistake.update({{"id", m.id}, {"sentence", m.sentence}});
        entry["mistakes"].push_back(std::move(mistake));
    }
    return entry;
}

BufferCheck buffer_of(const json& j) {
    BufferCheck c;
    c.reference = j.at("reference").get<std::string>();
    c.element = j.at("element").get<std::string>();
    c.verb = j.at("verb").get<std::string>();
    c.expected = expectation_of(j);
    for (const json& m : j.at("mistakes"))
        c.mistakes.push_back({m.at("id").get<std::string>(), m.at("sentence").get<std::string>(),
                              expectation_of(m)});
    return c;
}

}  // namespace

json record_unit_cases(const LabData& lab, unsigned seed, int max_random, RecordFor recorded_for) {
    LabData parsed = lab;
    if (parsed.checks.size() != parsed.file.checkpoints.size() ||
        parsed.visibility.size() != parsed.file.checkpoints.size())
        parse_checks(parsed);
    std::seed_seq seq{seed};
    std::mt19937 rng(seq);
    std::map<std::string, std::unique_ptr<ReferenceRecorder>> recorders;
    json checks = json::array();
    for (size_t k = 0; k < parsed.file.checkpoints.size(); ++k) {
        const fw::Checkpoint& cp = parsed.file.checkpoints[k];
        if (parsed.visibility[k] == Visibility::Hidden && recorded_for == RecordFor::StudentCopy)
            continue;  // not in the student's copy
        for (size_t i = 0; i < parsed.checks[k].size(); ++i) {
            if (parsed.checks[k][i].kind == CheckKind::Buffer)
                checks.push_back({{"checkpoint", cp.name},
                                  {"check", i},
                                  {"buffer", buffer_json(parsed.checks[k][i].as<BufferCheck>())}});
            if (parsed.checks[k][i].kind != CheckKind::Unit) continue;
            const UnitCheck& check = parsed.checks[k][i].as<UnitCheck>();
            const ReferenceUnit& ref = compiled_reference(parsed, check.function);
            std::unique_ptr<ReferenceRecorder>& recorder = recorders[check.function];
            if (!recorder) recorder = std::make_unique<ReferenceRecorder>(ref);
            const double tolerance = check.tolerance.value_or(ref.tolerance);
            json random = json::array();
            for (int n = 0; n < std::min(check.random, max_random); ++n) {
                json args = float_digits(random_arguments(ref, rng));
                recorder->record(args, tolerance);
                random.push_back(std::move(args));
            }
            for (const json& args : check.edge) recorder->record(args, tolerance);
            checks.push_back({{"checkpoint", cp.name},
                              {"check", i},
                              {"function", check.function},
                              {"random", std::move(random)}});
        }
    }
    json functions = json::object();
    for (const auto& [name, recorder] : recorders) functions[name] = recorder->entry();
    return {{"format", kFormat},
            {"lab", lab.id},
            {"seed", seed},
            {"max_random", max_random},
            {"for", recorded_for == RecordFor::Autograder ? kForAutograder : kForStudentCopy},
            {"functions", functions},
            {"checks", checks}};
}

void write_unit_cases(const std::string& path, const json& cases) {
    const fs::path p(path);
    if (p.has_parent_path()) fs::create_directories(p.parent_path());
    std::ofstream out(p, std::ios::binary);
    out << cases.dump() << '\n';
    if (!out) throw fw::Error("cannot write " + path);
}

std::string unit_cases_path(const LabData& lab) {
    return (fs::path(lab.root) / "labs" / lab.dir / "grading" / "cases.json").string();
}

namespace {

RecordedChecks read_checks(const json& checks) {
    RecordedChecks out;
    for (const json& c : checks) {
        RecordedCheck r;
        if (c.contains("buffer")) {
            r.buffer = buffer_of(c.at("buffer"));
        } else {
            r.function = c.at("function").get<std::string>();
            r.random = c.at("random").get<std::vector<json>>();
        }
        out[{c.at("checkpoint").get<std::string>(), c.at("check").get<size_t>()}] = std::move(r);
    }
    return out;
}

}  // namespace

RecordedChecks load_unit_cases(const LabData& lab) {
    const std::string path = unit_cases_path(lab);
    if (!fs::exists(path)) return {};
    try {
        std::ifstream in(path, std::ios::binary);
        const json cases = json::parse(in);
        if (cases.at("format") != kFormat)
            throw fw::Error("it is of format " + cases.at("format").dump() + ", course reads " +
                            std::to_string(kFormat));
        const std::string recorded_for = cases.value("for", kForStudentCopy);
        if (recorded_for != kForStudentCopy && recorded_for != kForAutograder)
            throw fw::Error("\"for\" is \"" + recorded_for + "\", not \"" + kForStudentCopy +
                            "\" or \"" + kForAutograder + "\"");
        const std::string what =
            recorded_for == kForAutograder
                ? "the cases the course recorded for its autograder (seed " +
                      cases.at("seed").dump() + ")"
                : std::string("the cases recorded in this copy (the autograder draws fresh ones)");
        for (const auto& [name, entry] : cases.at("functions").items()) {
            ReferenceUnit unit = recorded_reference(name, entry);
            unit.recorded_cases = what;
            register_reference(lab.dir, std::move(unit));
        }
        return read_checks(cases.at("checks"));
    } catch (const std::exception& e) {
        throw fw::UsageError(path + ": " + e.what() +
                             "; write it again with course release (or course cases)");
    }
}

}  // namespace grading
